// A pbrt-v4 BxDF as Verity's checks see it. pbrt's convention is the one sample_f_adapter.h
// maps: Sample_f(wo, uc, u, mode) samples the incident direction, and f and PDF put the
// given direction first. Values are pbrt's SampledSpectrum, one entry per sampled wavelength.
// Importance transport (TransportMode::Importance) is the model's adjoint, so the check
// holds it to eval with the directions swapped.
#pragma once

#include <pbrt/bxdfs.h>
#include <verity/chi2/sample_f_adapter.h>

#include <array>
#include <optional>

namespace pbrt_bsdfs {

using Spectrum = std::array<double, pbrt::NSpectrumSamples>;

inline Spectrum toArray(const pbrt::SampledSpectrum& s) {
  Spectrum out{};
  for (int i = 0; i < pbrt::NSpectrumSamples; ++i) out[i] = s[i];
  return out;
}

// The model of `bxdf`, which it holds by value: pbrt's BxDFs are small, const after
// construction and safe to call from every thread. exterior and interior are the indices of
// refraction on either side (for the reciprocity check's 1/η² of a refraction).
template <class BxDF>
verity::chi2::BsdfModel bxdfModel(const BxDF& bxdf, double exterior = 1, double interior = 1) {
  using pbrt::TransportMode;
  using pbrt::Vector3f;
  using Sampled = verity::chi2::SampledF<Vector3f, Spectrum>;
  auto sampleF = [bxdf](const Vector3f& wo,
                        const verity::chi2::BsdfUniforms& u) -> std::optional<Sampled> {
    const pstd::optional<pbrt::BSDFSample> s =
        bxdf.Sample_f(wo, static_cast<pbrt::Float>(u.lobe), pbrt::Point2f(u.xy.x, u.xy.y),
                      TransportMode::Radiance, pbrt::BxDFReflTransFlags::All);
    if (!s) return std::nullopt;
    return Sampled{s->wi, toArray(s->f), static_cast<double>(s->pdf), s->IsSpecular()};
  };
  auto f = [bxdf](const Vector3f& wo, const Vector3f& wi) {
    return toArray(bxdf.f(wo, wi, TransportMode::Radiance));
  };
  auto pdf = [bxdf](const Vector3f& wo, const Vector3f& wi) {
    return bxdf.PDF(wo, wi, TransportMode::Radiance, pbrt::BxDFReflTransFlags::All);
  };
  verity::chi2::BsdfModel model =
      verity::chi2::bsdfModelFromSampleF<Vector3f>(sampleF, std::move(f), std::move(pdf));
  model.evalAdjoint = [bxdf](const Eigen::Vector3d& wi, const Eigen::Vector3d& wo) {
    const auto v = [](const Eigen::Vector3d& w) { return Vector3f(w.x(), w.y(), w.z()); };
    const Spectrum value = toArray(bxdf.f(v(wi), v(wo), TransportMode::Importance));
    return Eigen::ArrayXd(Eigen::Map<const Eigen::ArrayXd>(value.data(), value.size()));
  };
  model.exteriorIndex = exterior;
  model.interiorIndex = interior;
  return model;
}

}  // namespace pbrt_bsdfs

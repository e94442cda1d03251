// The other common BSDF convention, pbrt's (Pharr, Jakob & Humphreys, "Physically Based
// Rendering", 4th ed., §9.1): given the outgoing direction wo, sample the incident one wi and
// return f and the pdf, not the weight,
//
//   sampleF(const V& wo, const BsdfUniforms& u) -> std::optional<S>, S having members
//       wi (V), f (value), pdf (a number) and optionally delta (bool), e.g.
//       SampledF<V, Value>; nothing when it cannot scatter (a sample of pdf 0 counts as
//       nothing too, as in pbrt);
//   f(const V& wo, const V& wi)   -> value        without the cosine
//   pdf(const V& wo, const V& wi) -> a number     per unit solid angle of wi
//
// in radiance transport (bind pbrt's TransportMode::Radiance). Both conventions name the
// directions after light's flow: pbrt's wo is Verity's wi (towards where the path came from)
// and pbrt's sampled wi is Verity's wo (bsdf_model.h). Both put the given direction first, so
// f(wo, wi) is Verity's eval(wi, wo) argument for argument; glue that swaps the arguments to
// match the names, or weights a sample without |cos θ| of the sampled direction, is backwards,
// and only a BSDF whose f and pdf are not symmetric in their two directions shows it (a
// Lambertian lobe sampled uniformly passes either way). This adapter maps it exactly:
//
//   sample(wi, u)  = sampleF(wi, u) with wo = s.wi and weight = s.f·|cos θ(s.wi)| / s.pdf
//   eval(wi, wo)   = f(wi, wo)
//   pdf(wi, wo)    = pdf(wi, wo)
//
//   auto model = verity::chi2::bsdfModelFromSampleF<Vec3>(sampleF, f, pdf);
//   CheckResult r = checkBsdf(model, Vec3{0.5, 0, 0.866}, options);
#pragma once

#include <verity/chi2/bsdf_adapter.h>

#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>

namespace verity::chi2 {

// A sample in pbrt's convention, for callables that have no such struct of their own.
template <class V, class Value>
struct SampledF {
  V wi{};
  // No default: a value type need not have a default constructor (clang refuses `f{}` for
  // one even where every SampledF is built from its values).
  Value f;
  double pdf = 0;
  bool delta = false;
};

template <class V, class SampleFFn, class FFn, class PdfFn>
BsdfModel bsdfModelFromSampleF(SampleFFn sampleF, FFn f, PdfFn pdf) {
  using Result = std::decay_t<decltype(sampleF(std::declval<const V&>(), BsdfUniforms{}))>;
  static_assert(detail::IsOptional<Result>::value,
                "sampleF(wo, u) must return a std::optional: nothing when it fails");
  BsdfModel m = detail::evalAndPdf<V>(std::move(f), std::move(pdf));
  m.sample = [sampleF](const Eigen::Vector3d& wi,
                       const BsdfUniforms& u) -> std::optional<DirectionSample> {
    const Result s = sampleF(makeVector3<V>(wi), u);
    if (!s) return std::nullopt;
    using Value = std::decay_t<decltype(s->f)>;
    DirectionSample d;
    d.wo = readVector3(s->wi);
    d.pdf = static_cast<double>(s->pdf);
    d.delta = detail::sampledDelta(*s);
    const Eigen::ArrayXd value = ValueAccess<Value>::read(s->f);
    // A pdf of 0 is no sample (the check drops it): its weight is never read.
    d.weight = d.pdf > 0 ? Eigen::ArrayXd(value * std::fabs(d.wo.z()) / d.pdf)
                         : Eigen::ArrayXd::Zero(value.size());
    return d;
  };
  return m;
}

}  // namespace verity::chi2

// A small, independent GGX BSDF for the broken-sampler tests: written from the papers (not
// from the renderer's materials), correct by default, with one deliberate flaw at a time.
// The suite must accept the correct version and reject each flawed one.
//   D, Λ: Walter et al. 2007 eqs. 33 and 72 (GGX), eq. 27 context (Beckmann Λ, exact form).
//   Visible normals: Dupuy and Benyoub 2023, "Sampling Visible GGX Normals with Spherical
//   Caps" (a different algorithm from the renderer's Heitz 2018 disk method).
//   Refraction: Walter et al. 2007 eqs. 16, 17, 21.
#pragma once

#include <cmath>
#include <numbers>

#include "materials/material.h"

namespace verity::chi2::testing {

enum class Flaw {
  None,
  MissingJacobian,   // reflection pdf lacks 1/(4|wo·m|)
  WrongG1,           // the visible-normal pdf uses Beckmann's G1 with GGX's D
  MissingEta2,       // transmission eval (and so the weight) lacks the ηi² radiance factor
  WeightMissingCos,  // weight = eval / pdf, without |cos θo|
  PdfTooHigh,        // pdf() and the sample pdf 2% too high
};

class ReferenceGgx : public Material {
 public:
  // ior == 0: a white conductor (F = 1); otherwise a rough dielectric of that index.
  ReferenceGgx(float alpha, float ior, Flaw flaw) : a_(alpha), ior_(ior), flaw_(flaw) {}

  Color3 eval(const TextureQuery&, const Vector3f& wi, const Vector3f& wo,
              TransportMode mode) const override {
    return Color3::Constant(float(value(wi, wo, mode)));
  }
  float pdf(const TextureQuery&, const Vector3f& wi, const Vector3f& wo) const override {
    return float(density(wi, wo));
  }
  std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                   const Point2f& u, TransportMode mode) const override {
    if (wi.z() == 0) return std::nullopt;
    const Vector3d wiUp = wi.z() > 0 ? wi.cast<double>() : Vector3d(-wi.cast<double>());
    Vector3d m = sampleVisible(wiUp.normalized(), u.x(), u.y());
    if (wi.z() < 0) m = -m;
    const Vector3d w = wi.cast<double>();
    const double cosI = w.dot(m);
    if (cosI <= 0) return std::nullopt;
    Vector3d wo;
    if (ior_ == 0 || uLobe < fresnel(cosI, wi.z() > 0 ? ior_ : 1 / ior_)) {
      wo = 2 * cosI * m - w;
      if (wo.z() * w.z() <= 0) return std::nullopt;
    } else {
      const double eta = wi.z() > 0 ? ior_ : 1 / ior_;  // far side over near side
      const double sin2T = (1 - cosI * cosI) / (eta * eta);
      if (sin2T >= 1) return std::nullopt;
      wo = -w / eta + (cosI / eta - std::sqrt(1 - sin2T)) * m;
      if (wo.z() * w.z() >= 0) return std::nullopt;
    }
    BsdfSample s;
    s.wo = wo.normalized().cast<float>();
    s.pdf = pdf(q, wi, s.wo);
    if (!(s.pdf > 0)) return std::nullopt;
    const double cosO = flaw_ == Flaw::WeightMissingCos ? 1.0 : std::abs(double(s.wo.z()));
    s.weight = Color3::Constant(float(value(wi, s.wo, mode) * cosO / s.pdf));
    s.lobe = kGlossy | (wo.z() * w.z() > 0 ? kReflection : kTransmission);
    return s;
  }
  uint32_t lobes() const override { return kGlossy | kReflection | (ior_ ? kTransmission : 0); }
  float interiorIndex() const override { return ior_ == 0 ? 1 : ior_; }
  bool isTextured() const override { return false; }

 private:
  using Vector3d = Eigen::Vector3d;

  double D(const Vector3d& m) const {
    if (m.z() <= 0) return 0;
    const double t = (m.x() * m.x() + m.y() * m.y()) / (a_ * a_) + m.z() * m.z();
    return 1 / (std::numbers::pi * a_ * a_ * t * t);
  }
  double lambdaGgx(const Vector3d& v) const {
    const double t2 = (v.x() * v.x() + v.y() * v.y()) / (v.z() * v.z());
    return (std::sqrt(1 + a_ * a_ * t2) - 1) / 2;
  }
  double lambdaBeckmann(const Vector3d& v) const {
    const double t = std::sqrt(v.x() * v.x() + v.y() * v.y()) / std::abs(v.z());
    if (t == 0) return 0;
    const double a = 1 / (a_ * t);
    return (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(std::numbers::pi));
  }
  double G1(const Vector3d& v, const Vector3d& m, bool wrong = false) const {
    if (v.dot(m) * v.z() <= 0) return 0;
    return 1 / (1 + (wrong ? lambdaBeckmann(v) : lambdaGgx(v)));
  }
  // Density of visible normals seen from v (v.z > 0).
  double visiblePdf(const Vector3d& v, const Vector3d& m) const {
    return G1(v, m, flaw_ == Flaw::WrongG1) * std::max(0.0, v.dot(m)) * D(m) / v.z();
  }
  Vector3d sampleVisible(const Vector3d& v, double u1, double u2) const {
    const Vector3d vh = Vector3d(a_ * v.x(), a_ * v.y(), v.z()).normalized();
    const double phi = 2 * std::numbers::pi * u1;
    const double z = (1 - u2) * (1 + vh.z()) - vh.z();
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const Vector3d h = Vector3d(r * std::cos(phi), r * std::sin(phi), z) + vh;
    return Vector3d(a_ * h.x(), a_ * h.y(), std::max(h.z(), 0.0)).normalized();
  }
  static double fresnel(double cosI, double eta) {
    const double sin2T = (1 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1) return 1;
    const double cosT = std::sqrt(1 - sin2T);
    const double rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    const double rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return (rs * rs + rp * rp) / 2;
  }
  // The interface's index on the far side of wi over the index on wi's side.
  double farOverNear(const Vector3d& wi) const { return wi.z() > 0 ? ior_ : 1 / ior_; }
  struct Pair {
    Vector3d h;
    double etaI = 1, etaO = 1;
    bool reflection = true;
  };
  // F of a pair, read symmetrically so that swapping wi and wo cannot change it: a
  // refraction from the outside direction (the outside cosine never nears total internal
  // reflection), a reflection from the mean of the two equal cosines.
  double pairFresnel(const Vector3d& wi, const Vector3d& wo, const Pair& p) const {
    if (ior_ == 0) return 1;
    const double ci = std::abs(wi.dot(p.h)), co = std::abs(wo.dot(p.h));
    if (p.reflection) return fresnel(0.5 * (ci + co), farOverNear(wi));
    return wi.z() > 0 ? fresnel(ci, ior_) : fresnel(co, ior_);
  }
  bool pair(const Vector3f& wif, const Vector3f& wof, Pair& p) const {
    const Vector3d wi = wif.cast<double>(), wo = wof.cast<double>();
    if (wi.z() == 0 || wo.z() == 0) return false;
    p.reflection = wi.z() * wo.z() > 0;
    if (!p.reflection && ior_ == 0) return false;
    p.etaI = wi.z() > 0 ? 1.0 : ior_;
    p.etaO = wo.z() > 0 ? 1.0 : ior_;
    p.h = p.reflection ? Vector3d(wi + wo) : Vector3d(p.etaI * wi + p.etaO * wo);
    if (p.h.norm() == 0) return false;
    p.h.normalize();
    if (p.h.z() < 0) p.h = -p.h;
    return wi.dot(p.h) * wi.z() > 0 && wo.dot(p.h) * wo.z() > 0;
  }
  double value(const Vector3f& wif, const Vector3f& wof, TransportMode mode) const {
    Pair p;
    if (!pair(wif, wof, p)) return 0;
    const Vector3d wi = wif.cast<double>(), wo = wof.cast<double>();
    const double ci = wi.dot(p.h), co = wo.dot(p.h);
    const double F = pairFresnel(wi, wo, p);
    const double g = G1(wi, p.h) * G1(wo, p.h);
    if (p.reflection) return F * D(p.h) * g / (4 * std::abs(wi.z() * wo.z()));
    const double denom = p.etaI * ci + p.etaO * co;
    double eta2 = mode == TransportMode::Radiance ? p.etaI * p.etaI : p.etaO * p.etaO;
    if (flaw_ == Flaw::MissingEta2) eta2 = 1;
    return eta2 * (1 - F) * D(p.h) * g * std::abs(ci * co) /
           (std::abs(wi.z() * wo.z()) * denom * denom);
  }
  double density(const Vector3f& wif, const Vector3f& wof) const {
    Pair p;
    if (!pair(wif, wof, p)) return 0;
    const Vector3d wi = wif.cast<double>(), wo = wof.cast<double>();
    const Vector3d wiUp = wi.z() > 0 ? wi : Vector3d(-wi);
    const double pm = visiblePdf(wiUp.normalized(), p.h);
    const double ci = wi.dot(p.h), co = wo.dot(p.h);
    const double F = pairFresnel(wi, wo, p);
    const double scale = flaw_ == Flaw::PdfTooHigh ? 1.02 : 1.0;
    if (p.reflection) {
      const double jacobian = flaw_ == Flaw::MissingJacobian ? 1.0 : 1 / (4 * std::abs(co));
      return scale * F * pm * jacobian;
    }
    const double denom = p.etaI * ci + p.etaO * co;
    return scale * (1 - F) * pm * p.etaO * p.etaO * std::abs(co) / (denom * denom);
  }

  double a_;
  double ior_;
  Flaw flaw_;
};

}  // namespace verity::chi2::testing

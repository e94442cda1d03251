#include "materials/microfacet.h"

#include <boost/math/special_functions/erf.hpp>

namespace verity {

namespace {
constexpr double kSqrtPi = 1.7724538509055160273;
// Keeps a sample value away from 0 and 1, where the inversions below reach infinities.
constexpr float kUEps = 1e-6f;
Point2f clampSample(const Point2f& u) {
  return {std::clamp(u.x(), kUEps, 1.0f - kUEps), std::clamp(u.y(), kUEps, 1.0f - kUEps)};
}
}  // namespace

MicrofacetDistribution::MicrofacetDistribution(MicrofacetType type, float alpha,
                                               MicrofacetSampling sampling)
    : type_(type),
      alpha_(std::max(std::isfinite(alpha) ? alpha : 1.0f, kMinAlpha)),
      sampling_(sampling) {}

float MicrofacetDistribution::D(const Vector3f& m) const {
  const float cos2 = m.z() * m.z();
  if (m.z() <= 0) return 0;
  const float a2 = alpha_ * alpha_;
  const float sin2 = m.x() * m.x() + m.y() * m.y();
  if (type_ == MicrofacetType::GGX) {
    // D = 1 / (π α² (sin²θ/α² + cos²θ)²), the form of Heitz 2018 eq. 1, which needs neither
    // tan θ nor cos⁴θ (Trowbridge and Reitz 1975; Walter et al. 2007 eq. 33).
    const float t = sin2 / a2 + cos2;
    return 1.0f / (kPi * a2 * t * t);
  }
  // Beckmann: exp(−tan²θ/α²) / (π α² cos⁴θ) (Walter et al. 2007, eq. 25). When cos⁴θ
  // underflows the exponential has long been zero.
  const float cos4 = cos2 * cos2;
  if (cos4 < 1e-30f) return 0;
  const float d = std::exp(-sin2 / (cos2 * a2)) / (kPi * a2 * cos4);
  return std::isfinite(d) ? d : 0.0f;
}

float MicrofacetDistribution::Lambda(const Vector3f& v) const {
  const float cos2 = v.z() * v.z();
  if (cos2 == 0) return kInfinity;
  const float sin2 = v.x() * v.x() + v.y() * v.y();
  // α²·tan²θ
  const float a2t2 = alpha_ * alpha_ * sin2 / cos2;
  if (!std::isfinite(a2t2)) return kInfinity;
  if (type_ == MicrofacetType::GGX) {
    // (−1 + √(1 + α²tan²θ)) / 2, rewritten without the cancellation near zero.
    return a2t2 / (2.0f * (1.0f + std::sqrt(1.0f + a2t2)));
  }
  // Beckmann, exact (Walter et al. 2007, eq. 27 is its rational fit): with a = 1/(α tan θ),
  // Λ = (erf(a) − 1)/2 + exp(−a²)/(2a√π). Double precision limits the cancellation.
  if (a2t2 == 0) return 0;
  const double a = 1.0 / std::sqrt(static_cast<double>(a2t2));
  if (a > 8.0) return 0;  // Λ < 1e-29
  const double l = 0.5 * (std::exp(-a * a) / (a * kSqrtPi) - std::erfc(a));
  return static_cast<float>(std::max(l, 0.0));
}

float MicrofacetDistribution::G1(const Vector3f& v, const Vector3f& m) const {
  if (v.dot(m) * v.z() <= 0) return 0;
  return 1.0f / (1.0f + Lambda(v));
}

float MicrofacetDistribution::G2(const Vector3f& wi, const Vector3f& wo, const Vector3f& m) const {
  if (wi.dot(m) * wi.z() <= 0 || wo.dot(m) * wo.z() <= 0) return 0;
  const float li = Lambda(wi), lo = Lambda(wo);
  if (!std::isfinite(li) || !std::isfinite(lo)) return 0;
  if (wi.z() * wo.z() > 0) return 1.0f / (1.0f + li + lo);
  // Transmission: a point at height-CDF value c is visible from above with probability
  // c^Λ and from below with (1−c)^Λ; ∫ c^Λi (1−c)^Λo dc = B(1+Λi, 1+Λo).
  const float b =
      std::exp(std::lgamma(1.0f + li) + std::lgamma(1.0f + lo) - std::lgamma(2.0f + li + lo));
  return std::isfinite(b) ? std::clamp(b, 0.0f, 1.0f) : 0.0f;
}

Vector3f MicrofacetDistribution::sampleNormal(const Vector3f& wi, Point2f u) const {
  u = clampSample(u);
  if (sampling_ == MicrofacetSampling::Visible && wi.z() > 0) {
    return type_ == MicrofacetType::GGX ? sampleGGXVisible(wi, u) : sampleBeckmannVisible(wi, u);
  }
  // D(m)·cos θm by inverting the CDF of tan²θm (Walter et al. 2007, eqs. 28 and 35).
  const float a2 = alpha_ * alpha_;
  const float tan2 =
      type_ == MicrofacetType::GGX ? a2 * u.x() / (1.0f - u.x()) : -a2 * std::log(1.0f - u.x());
  const float cosTheta = 1.0f / std::sqrt(1.0f + tan2);
  // tan θ · cos θ, not √(1 − cos²θ): below θ ≈ 3e-4 cos θ rounds to 1 and the cancellation
  // would put the normal exactly on the pole, all of them at α = 1e-4.
  const float sinTheta = std::sqrt(tan2) * cosTheta;
  const float phi = 2.0f * kPi * u.y();
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4)): in the
// configuration stretched to α = 1 the visible normals are the projection of a uniformly
// sampled disk onto the hemisphere, the disk's far half squeezed by the projected area of
// the half facing away from the view.
Vector3f MicrofacetDistribution::sampleGGXVisible(const Vector3f& wi, const Point2f& u) const {
  const Vector3f v = Vector3f(alpha_ * wi.x(), alpha_ * wi.y(), wi.z()).normalized();
  const float len2 = v.x() * v.x() + v.y() * v.y();
  const Vector3f t1 = len2 > 0 ? Vector3f(Vector3f(-v.y(), v.x(), 0.0f) / std::sqrt(len2))
                               : Vector3f(Vector3f::UnitX());
  const Vector3f t2 = v.cross(t1);
  const float r = std::sqrt(u.x());
  const float phi = 2.0f * kPi * u.y();
  const float p1 = r * std::cos(phi);
  const float s = 0.5f * (1.0f + v.z());
  const float p2 = lerp(s, safeSqrt(1.0f - p1 * p1), r * std::sin(phi));
  const Vector3f n = p1 * t1 + p2 * t2 + safeSqrt(1.0f - p1 * p1 - p2 * p2) * v;
  // Unstretch back to roughness α.
  const Vector3f m(alpha_ * n.x(), alpha_ * n.y(), std::max(n.z(), 0.0f));
  const float len = m.norm();
  return len > 0 ? Vector3f(m / len) : Vector3f::UnitZ();
}

// Heitz and d'Eon 2014, "Importance Sampling Microfacet-Based BSDFs using the Distribution
// of Visible Normals" (EGSR): stretch wi to the α = 1 configuration, sample the visible
// slopes there, rotate, unstretch. For α = 1 Beckmann and incidence θ (rotated to φ = 0),
// the visible slope density is ∝ max(0, cot θ − x)·exp(−x² − y²): y is an independent
// Gaussian, and x has the CDF ∝ μ√π/2·(1 + erf x) + exp(−x²)/2 for x ≤ μ = cot θ, which we
// invert by safeguarded Newton iterations (our own inversion, not the paper's fit).
Vector3f MicrofacetDistribution::sampleBeckmannVisible(const Vector3f& wi, const Point2f& u) const {
  const Vector3f v = Vector3f(alpha_ * wi.x(), alpha_ * wi.y(), wi.z()).normalized();
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - double(v.z()) * v.z()));
  const double y = boost::math::erf_inv(2.0 * u.y() - 1.0);
  double x;
  if (sinTheta < 1e-7) {
    x = boost::math::erf_inv(2.0 * u.x() - 1.0);  // normal incidence: all slopes visible
  } else {
    const double mu = v.z() / sinTheta;
    auto cdf = [mu](double t) {
      return mu * 0.5 * kSqrtPi * (1.0 + std::erf(t)) + 0.5 * std::exp(-t * t);
    };
    double lo = -10.0, hi = std::min(mu, 10.0);
    const double target = u.x() * cdf(hi);
    x = std::clamp(boost::math::erf_inv(2.0 * u.x() - 1.0), lo, hi);
    for (int i = 0; i < 40; ++i) {
      const double err = cdf(x) - target;
      if (err > 0)
        hi = x;
      else
        lo = x;
      const double deriv = (mu - x) * std::exp(-x * x);
      double next = deriv > 0 ? x - err / deriv : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - x) < 1e-9 * (1.0 + std::abs(x))) {
        x = next;
        break;
      }
      x = next;
    }
  }
  // Rotate the slopes to wi's azimuth, unstretch, and turn the slope into a normal.
  const double len = std::hypot(double(v.x()), double(v.y()));
  const double cosPhi = len > 0 ? v.x() / len : 1.0, sinPhi = len > 0 ? v.y() / len : 0.0;
  const double sx = alpha_ * (cosPhi * x - sinPhi * y);
  const double sy = alpha_ * (sinPhi * x + cosPhi * y);
  const Vector3f m = Vector3f(float(-sx), float(-sy), 1.0f).normalized();
  return m.allFinite() ? m : Vector3f::UnitZ();
}

float MicrofacetDistribution::pdfNormal(const Vector3f& wi, const Vector3f& m) const {
  if (sampling_ == MicrofacetSampling::Normals || wi.z() <= 0) {
    if (sampling_ == MicrofacetSampling::Visible) return 0;
    return D(m) * std::max(m.z(), 0.0f);
  }
  const float pdf = G1(wi, m) * std::max(wi.dot(m), 0.0f) * D(m) / wi.z();
  return std::isfinite(pdf) ? pdf : 0.0f;
}

}  // namespace verity

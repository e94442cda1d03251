#include "materials/microfacet.h"

#include <numbers>

#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/erf.hpp>

namespace verity {

namespace {
constexpr double kSqrtPi = 1.7724538509055160273;
// Keeps a sample value away from 0 and 1, where the inversions below reach infinities.
constexpr float kUEps = 1e-6f;
// Boost's special functions in the argument's own precision: its default policy promotes
// double to long double, and G2's beta alone was then a quarter of a rough dielectric's
// sampling test, for accuracy double already has (a few ulps).
constexpr boost::math::policies::policy<boost::math::policies::promote_double<false>> kInDouble;
Point2f clampSample(const Point2f& u) {
  return {std::clamp(u.x(), kUEps, 1.0f - kUEps), std::clamp(u.y(), kUEps, 1.0f - kUEps)};
}
}  // namespace

MicrofacetDistribution::MicrofacetDistribution(MicrofacetType type, float alpha,
                                               MicrofacetSampling sampling)
    : type_(type),
      alpha_(std::max(std::isfinite(alpha) ? alpha : 1.0f, kMinAlpha)),
      sampling_(sampling) {}

template <class T>
T MicrofacetDistribution::D(const Vec3<T>& m) const {
  const T cos2 = m.z() * m.z();
  if (m.z() <= 0) return 0;
  const T alpha = alpha_, a2 = alpha * alpha;
  const T sin2 = m.x() * m.x() + m.y() * m.y();
  if (type_ == MicrofacetType::GGX) {
    // D = 1 / (π α² (sin²θ/α² + cos²θ)²), the form of Heitz 2018 eq. 1, which needs neither
    // tan θ nor cos⁴θ (Trowbridge and Reitz 1975; Walter et al. 2007 eq. 33), as
    // α² / (π (sin²θ + α² cos²θ)²): one division.
    const T t = sin2 + a2 * cos2;
    return a2 / (std::numbers::pi_v<T> * t * t);
  }
  // Beckmann: exp(−tan²θ/α²) / (π α² cos⁴θ) (Walter et al. 2007, eq. 25). When cos⁴θ
  // underflows the exponential has long been zero.
  const T cos4 = cos2 * cos2;
  if (cos4 < T(1e-30)) return 0;
  const T d = std::exp(-sin2 / (cos2 * a2)) / (std::numbers::pi_v<T> * a2 * cos4);
  return std::isfinite(d) ? d : T(0);
}

template <class T>
T MicrofacetDistribution::Lambda(const Vec3<T>& v) const {
  const T cos2 = v.z() * v.z();
  if (cos2 == 0) return std::numeric_limits<T>::infinity();
  const T sin2 = v.x() * v.x() + v.y() * v.y();
  // α²·tan²θ
  const T alpha = alpha_;
  const T a2t2 = alpha * alpha * sin2 / cos2;
  if (!std::isfinite(a2t2)) return std::numeric_limits<T>::infinity();
  if (type_ == MicrofacetType::GGX) {
    // (−1 + √(1 + α²tan²θ)) / 2, rewritten without the cancellation near zero.
    return a2t2 / (T(2) * (T(1) + std::sqrt(T(1) + a2t2)));
  }
  // Beckmann, exact (Walter et al. 2007, eq. 27 is its rational fit): with a = 1/(α tan θ),
  // Λ = (erf(a) − 1)/2 + exp(−a²)/(2a√π). Double precision limits the cancellation.
  if (a2t2 == 0) return 0;
  const double a = 1.0 / std::sqrt(static_cast<double>(a2t2));
  if (a > 8.0) return 0;  // Λ < 1e-29
  const double l = 0.5 * (std::exp(-a * a) / (a * kSqrtPi) - std::erfc(a));
  return static_cast<T>(std::max(l, 0.0));
}

template <class T>
T MicrofacetDistribution::ggxRoot(const Vec3<T>& v) const {
  const T alpha = alpha_;
  return std::sqrt(v.z() * v.z() + alpha * alpha * (v.x() * v.x() + v.y() * v.y()));
}

template <class T>
T MicrofacetDistribution::G1(const Vec3<T>& v, const Vec3<T>& m) const {
  if (v.dot(m) * v.z() <= 0) return 0;
  if (type_ == MicrofacetType::GGX) {
    // 1/(1 + Λ) with 1 + Λ = (|cos θ| + ggxRoot)/(2 |cos θ|).
    const T c = std::fabs(v.z()), d = c + ggxRoot(v);
    return d > 0 ? T(2) * c / d : T(0);
  }
  return T(1) / (T(1) + Lambda(v));
}

template <class T>
T MicrofacetDistribution::G2(const Vec3<T>& wi, const Vec3<T>& wo, const Vec3<T>& m) const {
  if (wi.dot(m) * wi.z() <= 0 || wo.dot(m) * wo.z() <= 0) return 0;
  if (type_ == MicrofacetType::GGX && wi.z() * wo.z() > 0) {
    // 1/(1 + Λi + Λo) with 1 + Λi + Λo = (ggxRoot(wi)/|cos θi| + ggxRoot(wo)/|cos θo|)/2: one
    // division instead of five.
    const T ci = std::fabs(wi.z()), co = std::fabs(wo.z());
    const T d = co * ggxRoot(wi) + ci * ggxRoot(wo);
    return d > 0 ? T(2) * ci * co / d : T(0);
  }
  const T li = Lambda(wi), lo = Lambda(wo);
  if (!std::isfinite(li) || !std::isfinite(lo)) return 0;
  if (wi.z() * wo.z() > 0) return T(1) / (T(1) + li + lo);
  // Transmission: a point at height-CDF value c is visible from above with probability
  // c^Λ and from below with (1−c)^Λ; ∫ c^Λi (1−c)^Λo dc = B(1+Λi, 1+Λo). Boost's Beta,
  // not exp(lgamma(a) + lgamma(b) − lgamma(a + b)): at a grazing direction (Λ = 3e16 at
  // 90° and α = 4) that difference of two numbers near 1e18 lost every digit, and G2 read 1
  // where it is 1e-33 (eval() of 1e15 one way round and 0 the other).
  const T b = boost::math::beta(T(1) + li, T(1) + lo, kInDouble);
  return std::isfinite(b) ? std::clamp(b, T(0), T(1)) : T(0);
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
  // Each normalisation multiplies by one reciprocal rather than dividing every component.
  const Vector3f stretched(alpha_ * wi.x(), alpha_ * wi.y(), wi.z());
  const Vector3f v = stretched * (1.0f / stretched.norm());
  const float len2 = v.x() * v.x() + v.y() * v.y();
  const Vector3f t1 = len2 > 0 ? Vector3f(Vector3f(-v.y(), v.x(), 0.0f) * (1.0f / std::sqrt(len2)))
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
  return len > 0 ? Vector3f(m * (1.0f / len)) : Vector3f::UnitZ();
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
  const double y = boost::math::erf_inv(2.0 * u.y() - 1.0, kInDouble);
  double x;
  if (sinTheta < 1e-7) {
    x = boost::math::erf_inv(2.0 * u.x() - 1.0, kInDouble);  // normal incidence: all slopes visible
  } else {
    const double mu = v.z() / sinTheta;
    auto cdf = [mu](double t) {
      return mu * 0.5 * kSqrtPi * (1.0 + std::erf(t)) + 0.5 * std::exp(-t * t);
    };
    double lo = -10.0, hi = std::min(mu, 10.0);
    const double target = u.x() * cdf(hi);
    x = std::clamp(boost::math::erf_inv(2.0 * u.x() - 1.0, kInDouble), lo, hi);
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

template <class T>
T MicrofacetDistribution::pdfNormal(const Vec3<T>& wi, const Vec3<T>& m) const {
  if (sampling_ == MicrofacetSampling::Normals || wi.z() <= 0) {
    if (sampling_ == MicrofacetSampling::Visible) return 0;
    return D(m) * std::max(m.z(), T(0));
  }
  const T pdf = G1(wi, m) * std::max(wi.dot(m), T(0)) * D(m) / wi.z();
  return std::isfinite(pdf) ? pdf : T(0);
}

#define VERITY_MICROFACET_INSTANTIATE(T)                                                       \
  template T MicrofacetDistribution::D(const Vec3<T>&) const;                                  \
  template T MicrofacetDistribution::Lambda(const Vec3<T>&) const;                             \
  template T MicrofacetDistribution::ggxRoot(const Vec3<T>&) const;                            \
  template T MicrofacetDistribution::G1(const Vec3<T>&, const Vec3<T>&) const;                 \
  template T MicrofacetDistribution::G2(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&) const; \
  template T MicrofacetDistribution::pdfNormal(const Vec3<T>&, const Vec3<T>&) const;
VERITY_MICROFACET_INSTANTIATE(float)
VERITY_MICROFACET_INSTANTIATE(double)
#undef VERITY_MICROFACET_INSTANTIATE

}  // namespace verity

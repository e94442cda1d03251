// Isotropic microfacet normal distributions (Beckmann and GGX) with Smith masking and
// shadowing and two ways of sampling microfacet normals. Directions are local (normal
// +z); the distribution is a small value type, built per shading query so that roughness
// may be textured.
#pragma once

#include "core/math.h"

namespace verity {

enum class MicrofacetType { Beckmann, GGX };
// Normals: sample D(m)·cos θm (the seed's method; wastes samples at grazing incidence).
// Visible: sample the normals visible from wi, D_wi(m) = G1(wi)·max(0, wi·m)·D(m) / cos θi.
enum class MicrofacetSampling { Normals, Visible };

class MicrofacetDistribution {
 public:
  // Roughness below kMinAlpha is clamped: the formulas stay finite and such a lobe is
  // already far narrower than a pixel.
  static constexpr float kMinAlpha = 1e-4f;

  MicrofacetDistribution(MicrofacetType type, float alpha,
                         MicrofacetSampling sampling = MicrofacetSampling::Visible);

  MicrofacetType type() const { return type_; }
  float alpha() const { return alpha_; }
  MicrofacetSampling sampling() const { return sampling_; }

  // The densities and masking terms are evaluated in the precision of their arguments:
  // single precision, or double where a material evaluates a lobe narrower than single
  // precision resolves (α near kMinAlpha, grazing directions; see RoughConductor::pdf).
  // Instantiated for float and double.
  template <class T>
  using Vec3 = Eigen::Matrix<T, 3, 1>;

  // Density of microfacet normals per solid angle; zero below the horizon.
  template <class T>
  T D(const Vec3<T>& m) const;
  // Smith's auxiliary function Λ(v) (infinite at v.z = 0); depends on |v.z| only.
  template <class T>
  T Lambda(const Vec3<T>& v) const;
  // Masking of direction v for microfacet m, with the χ+((v·m)/(v·n)) visibility test.
  template <class T>
  T G1(const Vec3<T>& v, const Vec3<T>& m) const;
  // Height-correlated masking-shadowing (Heitz 2014, "Understanding the Masking-Shadowing
  // Function in Microfacet-Based BRDFs", §6.2): 1/(1 + Λ(wi) + Λ(wo)) when wi and wo lie
  // on the same side, B(1 + Λ(wi), 1 + Λ(wo)) (the Beta function) when they lie on
  // opposite sides (transmission).
  template <class T>
  T G2(const Vec3<T>& wi, const Vec3<T>& wo, const Vec3<T>& m) const;

  // Samples a microfacet normal (m.z > 0) for a direction wi with wi.z > 0.
  Vector3f sampleNormal(const Vector3f& wi, Point2f u) const;
  // Density of sampleNormal() producing m, per solid angle of normals.
  template <class T>
  T pdfNormal(const Vec3<T>& wi, const Vec3<T>& m) const;

 private:
  // √(cos²θ + α² sin²θ) = |cos θ| √(1 + α² tan²θ): GGX's Λ(v) is (ggxRoot/|cos θ| − 1)/2
  // (Heitz 2014, eq. 72), written without tan θ so that G1 and G2 take one division each.
  template <class T>
  T ggxRoot(const Vec3<T>& v) const;
  Vector3f sampleGGXVisible(const Vector3f& wi, const Point2f& u) const;
  Vector3f sampleBeckmannVisible(const Vector3f& wi, const Point2f& u) const;

  MicrofacetType type_;
  float alpha_;
  MicrofacetSampling sampling_;
};

}  // namespace verity

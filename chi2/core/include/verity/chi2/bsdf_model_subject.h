// A BsdfModel's sample() tested against its pdf() on the sphere of directions, with the
// per-sample checks: weight = eval·|cos θo|/pdf and sample pdf = pdf() to kWeightTolerance
// relative, unit and finite sampled directions, no NaN/Inf/negative values, and
// reciprocity (bsdf_model.h). eval is also checked at every cell centre, so that a NaN
// where sample() never goes is found as well.
//
// The histogram lies on the sphere of the frame's world directions, so that the shading
// normal may be rotated away from the geometric +z (a bump- or normal-mapped surface); the
// model itself always works in its local frame.
#pragma once

#include <verity/chi2/bsdf_model.h>
#include <verity/chi2/subject.h>

#include <atomic>
#include <string>

namespace verity::chi2 {

// An orthonormal frame: s, t, n in world coordinates, n the shading normal.
struct ShadingFrame {
  Vector3d s = Vector3d::UnitX(), t = Vector3d::UnitY(), n = Vector3d::UnitZ();
  Vector3d toLocal(const Vector3d& v) const { return {v.dot(s), v.dot(t), v.dot(n)}; }
  Vector3d toWorld(const Vector3d& v) const { return s * v.x() + t * v.y() + n * v.z(); }
};

struct BsdfTestSetup {
  std::string name;
  Vector3d wi = Vector3d::UnitZ();  // incident direction in the local frame, unit length
  ShadingFrame frame;
  int resolution = 32;  // cells in cos θ; twice as many in φ
  bool checkReciprocity = true;
};

class BsdfModelSubject : public Subject {
 public:
  BsdfModelSubject(BsdfModel model, BsdfTestSetup setup);
  const Domain& domain() const override { return domain_; }
  double pdf(double phi, double z) const override;
  std::optional<Point2d> sample(pcg32& rng, Audit& audit) const override;
  void extraChecks(Audit& audit) const override;
  // The shading horizon and, for a transmitter, where refraction ends.
  std::vector<double> breakpointsY(double phi) const override;
  // The mirror direction of wi about the shading normal and, for a transmitter, its
  // refracted direction (where a lobe narrows to a spike as α → 0 or η → 1).
  std::vector<Point2d> peaks() const override;
  std::string describe() const override;

  long long deltaSamples() const override { return delta_.load(); }

 private:
  // f: eval(wi, wo), already computed by sample().
  void checkReciprocity(const Vector3d& wo, const Eigen::Array3d& f, Audit& audit) const;
  std::string format(const Eigen::Array3d& value) const;
  double indexOn(const Vector3d& w) const {
    return w.z() > 0 ? model_.exteriorIndex : model_.interiorIndex;
  }

  BsdfModel model_;
  BsdfTestSetup setup_;
  Domain domain_;
  mutable std::atomic<long long> delta_{0};
};

}  // namespace verity::chi2

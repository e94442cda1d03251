// A BsdfModel's sample() tested against its pdf() on the sphere of directions, with the
// per-sample checks: weight = eval·|cos θo|/pdf and sample pdf = pdf() to the weight tolerance
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
  // Relative, per component (BsdfCheckOptions).
  double weightTolerance = kWeightTolerance, reciprocityTolerance = kReciprocityTolerance;
  double directionRounding = kDirectionRounding;  // BsdfCheckOptions
};

class BsdfModelSubject : public Subject {
 public:
  BsdfModelSubject(BsdfModel model, BsdfTestSetup setup);
  const Domain& domain() const override { return domain_; }
  double pdf(double phi, double z) const override;
  std::optional<Point2d> sample(pcg32& rng, Audit& audit) const override;
  // Through the model's batched forms where it has them (bsdf_model.h).
  void sampleBatch(pcg32& rng, std::vector<std::optional<Point2d>>& out,
                   Audit& audit) const override;
  bool batchedPdf() const override { return bool(model_.pdfBatch); }
  void pdfBatch(const std::vector<Point2d>& points, std::vector<double>& values) const override;
  void extraChecks(Audit& audit) const override;
  // The shading horizon and, for a transmitter, where refraction ends.
  std::vector<double> breakpointsY(double phi) const override;
  std::vector<double> breakpointCrossingsX(double z) const override;
  // The mirror direction of wi about the shading normal and, for a transmitter, its
  // refracted direction (where a lobe narrows to a spike as α → 0 or η → 1).
  std::vector<Point2d> peaks() const override;
  std::string describe() const override;

  long long deltaSamples() const override { return delta_.load(); }
  // The model and its incident direction in the local frame, for checks of its own
  // (delta_check.h) on the same BSDF.
  const BsdfModel& model() const { return model_; }
  // The least any check of n samples must spend: the seconds to draw them from the model on
  // one thread, as sampleBatch draws them from `seed`'s streams, and histogram them in
  // `cells`, with no audit, density or statistics. Returns the valid samples in `binned`.
  double drawingFloorSeconds(const Domain& cells, long long n, uint64_t seed,
                             long long& binned) const;
  const Vector3d& localWi() const { return setup_.wi; }

 private:
  struct PointByPoint;
  // The cosines, about the shading normal, of the cones along which the density jumps: the
  // horizon and, for a transmitter, where refraction ends (breakpointsY).
  std::vector<double> jumpCones() const;
  // us.size() uniforms from rng and the model's samples for them (drawn, of the same size),
  // through its batched form where it has one: what sampleBatch and the floor draw alike.
  void draw(pcg32& rng, std::vector<BsdfUniforms>& us,
            std::vector<std::optional<DirectionSample>>& drawn) const;
  // The per-sample checks of the sample s drawn with u; eval(wi, wo), pdf(wi, wo) and
  // eval(wo, wi) come from `values` (point by point, or a batch's), asked for only for a
  // sample that needs them (evaluable).
  template <class Values>
  std::optional<Point2d> audited(const BsdfUniforms& u, const std::optional<DirectionSample>& s,
                                 const Values& values, Audit& audit) const;
  // Whether the sample is a direction to evaluate: drawn, not a delta lobe, of a non-zero
  // density, finite and of unit length.
  static bool evaluable(const std::optional<DirectionSample>& s);
  // f: eval(wi, wo), fr: eval(wo, wi), already computed.
  void checkReciprocity(const Vector3d& wo, const Eigen::ArrayXd& f, const Eigen::ArrayXd& fr,
                        Audit& audit) const;
  // Whether v has the model's number of components; records the defect where not, at
  // where() (formatted only then).
  template <class Where>
  bool sized(const Eigen::ArrayXd& v, const char* what, Where where, Audit& audit) const;
  std::string format(const Eigen::ArrayXd& value) const;
  // The largest factorDeviation(q(wi', wo'), q(wi, wo)) over directions near wo whose
  // components are moved by their rounding (directionRounding scaled to each component's
  // magnitude), all three at once and one at a time with the direction kept unit, and over
  // directions near wi moved all three at once. How far, as a factor either way, rounding the
  // directions moves the reference q of a failed comparison (deviationWithinFactor turns it
  // into the bound Audit::record takes). A factor either way: where the reference sits at a
  // peak that rounding missed (a half vector whose cancelled component rests on the last bit of
  // wo), every move lowers it further, and it may as well lie that far below the value an exact
  // evaluation gives.
  template <class Q>
  double roundingSpread(const Vector3d& wo, Q&& q) const;
  // "component c " where the BSDF has several, for an example.
  std::string component(int c) const;
  double indexOn(const Vector3d& w) const {
    return w.z() > 0 ? model_.exteriorIndex : model_.interiorIndex;
  }

  BsdfModel model_;
  BsdfTestSetup setup_;
  Domain domain_;
  mutable std::atomic<long long> delta_{0};
};

}  // namespace verity::chi2

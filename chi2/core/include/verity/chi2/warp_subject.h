// A WarpModel's sample() tested against its pdf() on its domain: sampled points must be
// finite (and unit vectors on the sphere), and the density finite and non-negative.
#pragma once

#include <verity/chi2/subject.h>
#include <verity/chi2/warp_model.h>

#include <string>

namespace verity::chi2 {

class WarpSubject : public Subject {
 public:
  // `resolution`: cells along each side of a planar domain, or in cos θ on the sphere
  // (twice as many in φ).
  WarpSubject(std::string name, WarpModel model, int resolution);
  const Domain& domain() const override { return domain_; }
  double pdf(double x, double y) const override;
  std::optional<Point2d> sample(pcg32& rng, Audit& audit) const override;
  void sampleBatch(pcg32& rng, std::vector<std::optional<Point2d>>& out,
                   Audit& audit) const override;
  bool batchedPdf() const override { return bool(model_.pdfBatch); }
  void pdfBatch(const std::vector<Point2d>& points, std::vector<double>& values) const override;
  std::vector<double> breakpointsY(double x) const override;
  std::vector<double> breakpointCrossingsX(double y) const override;
  std::string describe() const override { return name_; }

 private:
  Vector3d point(double x, double y) const;
  // The checks of a sampled point p drawn with u, and where it lies on the domain.
  std::optional<Point2d> audited(const Uniform2& u, const std::optional<Vector3d>& p,
                                 Audit& audit) const;

  std::string name_;
  WarpModel model_;
  Domain domain_;
};

}  // namespace verity::chi2

// A BSDF as the checks see it: three functions in double precision in the local shading
// frame. bsdf_adapter.h builds one from callables in the caller's own types; Verity's
// materials are adapted in chi2/bsdf_subject.h.
//
// Conventions (those of pbrt, Mitsuba and Verity):
// - The shading normal is +z. wi and wo are unit vectors and both point away from the
//   surface: wi towards where the path came from, wo towards where it goes next. A
//   transmitted wo has wo.z < 0 (for wi.z > 0).
// - eval(wi, wo) is the BSDF f without the cosine factor; pdf(wi, wo) is the density of
//   sample() producing wo per unit solid angle. Both cover the non-delta part only.
// - A sample's weight is f(wi, wo)·|cos θo| / pdf, with cos θo = wo.z.
// - A delta lobe (a mirror, a smooth dielectric) is sampled with `delta` set: such samples are
//   counted and left out of the histogram, so ∫pdf must equal the probability of a valid
//   non-delta sample. A sample() that fails (below the horizon, total internal reflection)
//   returns nothing; it weighs zero and likewise lowers the expected ∫pdf.
// - Values (eval, evalAdjoint, a sample's weight) have `components` entries each: 1 for a grey
//   BSDF, 3 for RGB, as many as wavelengths for a spectral one. Every per-sample check works
//   component by component; a value of another size is a defect ("value of the wrong size").
// - Reciprocity (Veach 1997, §5.3.2): eval(wi, wo)·η(wo)² = eval(wo, wi)·η(wi)², η(w) being
//   the index of refraction on w's side (exteriorIndex above the surface, interiorIndex
//   below), i.e. radiance is scaled by 1/η² across a refraction as in pbrt. Where given,
//   evalAdjoint (the BSDF for importance transport) must equal eval(wo, wi).
#pragma once

#include <verity/chi2/uniforms.h>

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

namespace verity::chi2 {

struct DirectionSample {
  Eigen::Vector3d wo = Eigen::Vector3d::UnitZ();
  Eigen::ArrayXd weight;
  double pdf = 0;
  bool delta = false;
};

struct BsdfModel {
  using SampleFn =
      std::function<std::optional<DirectionSample>(const Eigen::Vector3d& wi, const BsdfUniforms&)>;
  using EvalFn =
      std::function<Eigen::ArrayXd(const Eigen::Vector3d& wi, const Eigen::Vector3d& wo)>;
  using PdfFn = std::function<double(const Eigen::Vector3d& wi, const Eigen::Vector3d& wo)>;

  SampleFn sample;
  EvalFn eval;
  PdfFn pdf;
  EvalFn evalAdjoint;  // optional

  // Optional batched forms, one call for many directions (SIMD or GPU code, NumPy): where
  // sampleBatch and evalBatch are set, the check draws its samples and evaluates them through
  // them; where pdfBatch is set, the quadrature calls it with every node of a refinement level
  // at once (DensityBatchFn, quadrature.h). sample, eval and pdf are still needed where these are
  // not (the delta lobes' own checks, a sample's reversed evaluation through evalAdjoint).
  using SampleBatchFn =
      std::function<void(const Eigen::Vector3d& wi, const std::vector<BsdfUniforms>& u,
                         std::vector<std::optional<DirectionSample>>& out)>;
  // wi holds one direction for every wo, or one direction per wo (the reversed evaluations
  // of the reciprocity check).
  using EvalBatchFn =
      std::function<void(const std::vector<Eigen::Vector3d>& wi,
                         const std::vector<Eigen::Vector3d>& wo, std::vector<Eigen::ArrayXd>& out)>;
  using PdfBatchFn = std::function<void(
      const Eigen::Vector3d& wi, const std::vector<Eigen::Vector3d>& wo, std::vector<double>& out)>;
  SampleBatchFn sampleBatch;
  EvalBatchFn evalBatch;
  PdfBatchFn pdfBatch;
  // Entries in every value; 0 where only run time tells (a std::vector, an Eigen::VectorXd):
  // checkBsdf then takes the size of eval at wi's mirror direction.
  int components = 3;
  double exteriorIndex = 1, interiorIndex = 1;

  // The relative index across the surface; transmission peaks and cut-offs are sought only
  // where it is not 1.
  double relativeIndex() const { return interiorIndex / exteriorIndex; }
};

// out[k] = model.sample(wi, u[k]): one call of sampleBatch where the model has it.
void sampleDirections(const BsdfModel& model, const Eigen::Vector3d& wi,
                      const std::vector<BsdfUniforms>& u,
                      std::vector<std::optional<DirectionSample>>& out);

}  // namespace verity::chi2

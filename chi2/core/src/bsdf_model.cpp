#include <verity/chi2/bsdf_model.h>

namespace verity::chi2 {

void sampleDirections(const BsdfModel& model, const Eigen::Vector3d& wi,
                      const std::vector<BsdfUniforms>& u,
                      std::vector<std::optional<DirectionSample>>& out) {
  if (model.sampleBatch) return model.sampleBatch(wi, u, out);
  for (size_t k = 0; k < u.size(); ++k) out[k] = model.sample(wi, u[k]);
}

}  // namespace verity::chi2

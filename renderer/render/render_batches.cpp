#include "render/render_batches.h"

#include <fmt/format.h>

#include "core/hash.h"
#include "integrators/integrator_settings.h"
#include "render/renderer.h"

namespace verity {

uint64_t renderBatches(const SceneFile& file, const std::string& integrator, int maxBounces,
                       int batches, int spp, const std::string& key,
                       const std::function<void(const Film&)>& onBatch) {
  const auto render = makeIntegrator(
      overrideIntegrator(file.integrator, integratorOverrides(integrator, maxBounces)));
  uint64_t invalid = 0;
  for (int batch = 0; batch < batches; ++batch) {
    Film film(file.scene->camera().resolution());
    RenderOptions options;
    options.samplesPerPixel = spp;
    const std::unique_ptr<Sampler> sampler = file.sampler->clone();
    sampler->setSeed(hashString(fmt::format("{} batch {}", key, batch)));
    invalid += verity::render(*file.scene, *render, *sampler, film, options).invalidSamples;
    onBatch(film);
  }
  return invalid;
}

}  // namespace verity

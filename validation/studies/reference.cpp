#include "validation/studies/reference.h"

#include <fmt/format.h>

#include <fstream>

#include "core/error.h"
#include "core/hash.h"
#include "film/image_io.h"
#include "validation/studies/machine_info.h"
#include "validation/studies/relative_error.h"
#include "validation/studies/seeds.h"
#include "validation/studies/study_scene.h"
#include "validation/studies/timed_render.h"

namespace verity::studies {

ReferenceResult makeReference(const ReferenceConfig& config) {
  const SceneFile file = loadStudyScene(config.scene, config.resolution);
  const IntegratorSettings settings = studyIntegrator(file, config.integrator, config.maxBounces);
  const auto integrator = makeIntegrator(settings);
  const uint64_t seed =
      config.seed ? config.seed : hashValues(hashString("reference"), hashString(file.name));

  Film film(file.scene->camera().resolution());
  const TimedRender timed = timedRender(file, *integrator, film, config.spp, config.threads, seed);

  ImageChannels image = filmChannels(film, true);
  const double ownRelMse = referenceRelMse(image);
  const MachineInfo machine = machineInfo();
  const std::string revision = sourceRevision();
  image.attributes["verity:scene"] = config.scene.string();
  image.attributes["verity:integrator"] = settings.type;
  image.attributes["verity:max_bounces"] = std::to_string(settings.maxBounces);
  image.attributes["verity:spp"] = std::to_string(timed.stats.passes);
  image.attributes["verity:seed"] = std::to_string(seed);
  image.attributes["verity:revision"] = revision;

  ReferenceResult result;
  std::filesystem::create_directories(config.directory);
  result.image = config.directory / (file.name + ".exr");
  result.sidecar = config.directory / (file.name + ".json");
  // Half floats: a relative rounding error of at most 2⁻¹¹ per value, so the quantisation
  // adds at most about (2⁻¹¹)² ≈ 2.4e-7 to a measured relative MSE.
  writeExr(result.image, image, /*halfFloat=*/true);

  result.metadata = {
      {"scene", file.name},
      {"scene_file", config.scene.string()},
      {"image", result.image.filename().string()},
      {"width", film.width()},
      {"height", film.height()},
      {"integrator", settings.type},
      {"max_bounces", settings.maxBounces},
      {"spp", timed.stats.passes},
      {"seed", seed},
      {"wall_seconds", timed.wallSeconds},
      {"cpu_seconds", timed.cpuSeconds},
      {"rays", timed.stats.rays},
      {"invalid_samples", timed.stats.invalidSamples},
      {"threads", config.threads > 0 ? config.threads : machine.cores},
      {"machine", toJson(machine)},
      {"revision", revision},
      {"created", timestamp()},
      {"format", "OpenEXR, half float, ZIP; R, G, B, variance.R/G/B, samples"},
      // Every setting spelled out, so that the command remakes this image bit for bit at
      // `revision` (renders do not depend on the thread count).
      {"command", fmt::format("verity reference {} --spp {} --integrator {} --max-bounces {} "
                              "--resolution {} --seed {} --dir {}",
                              config.scene.string(), timed.stats.passes, settings.type,
                              settings.maxBounces, film.width(), seed, config.directory.string())},
      {"rel_mse", ownRelMse},
      {"rel_mse_epsilon", kRelEpsilon},
      {"rel_mse_note",
       "the reference's own estimated relative MSE: mean over pixels and channels of "
       "(variance / samples) / (mean^2 + epsilon); a study's relative MSE includes it"},
  };
  std::ofstream out(result.sidecar);
  if (!out) throw VerityError(result.sidecar.string(), "", "cannot write the sidecar");
  out << result.metadata.dump(2) << '\n';
  return result;
}

}  // namespace verity::studies

#include "validation/studies/reference.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "core/error.h"
#include "core/hash.h"
#include "core/version.h"
#include "film/image_io.h"
#include "sampling/sampler.h"
#include "validation/studies/machine_info.h"
#include "validation/studies/reference_match.h"
#include "validation/studies/relative_error.h"
#include "validation/studies/study_scene.h"
#include "validation/studies/timed_render.h"

namespace verity::studies {

ReferenceResult makeReference(const ReferenceConfig& config, const ProcessGroup& group) {
  const SceneFile file = loadScene(config.scene, SceneOverrides::atWidth(config.resolution));
  requireIndependentSamples(*file.sampler, config.scene, "a reference image's variance channels");
  const IntegratorSettings settings = studyIntegrator(file, config.integrator, config.maxBounces);
  const auto integrator = makeIntegrator(settings);
  const uint64_t seed =
      config.seed ? config.seed : hashValues(hashString("reference"), hashString(file.name));

  Film film(file.scene->camera().resolution());
  const int threads = group.threadsPerRank(config.threads);
  const TimedRender timed = timedRender(file, *file.sampler, *integrator, film, config.spp, threads,
                                        seed, 0, nullptr, group);
  if (!group.isRoot()) return {};

  ImageChannels image = filmChannels(film, true);
  const double ownRelMse = referenceRelMse(image);
  const MachineInfo machine = machineInfo();
  image.attributes["verity:scene"] = config.scene.string();
  image.attributes["verity:integrator"] = settings.type->name;
  image.attributes["verity:max_bounces"] = std::to_string(settings.maxBounces);
  image.attributes["verity:spp"] = std::to_string(timed.stats.passes);
  image.attributes["verity:seed"] = std::to_string(seed);
  image.attributes["verity:revision"] = kRevision;

  ReferenceResult result;
  std::filesystem::create_directories(config.directory);
  result.image = config.directory / (file.name + ".exr");
  result.sidecar = config.directory / (file.name + ".json");
  if (group.distributed())
    image.attributes["verity:processes"] = fmt::format(
        "{} MPI ranks, {} threads each; rank 0 on {}", group.size(), threads, group.hostName());
  // Half floats where they hold every value: a relative rounding error of at most 2⁻¹¹ per
  // value, so the quantisation adds at most about (2⁻¹¹)² ≈ 2.4e-7 to a measured relative
  // MSE. A brighter image (a visible emitter, say) is written in 32-bit floats instead: half
  // floats would store Inf. Written under a temporary name and renamed when whole: a job
  // killed meanwhile leaves no image that looks complete.
  // A reference with an infinite mean or variance (beyond 32-bit floats) would make every
  // error measured against it meaningless.
  refuseNonFinite(image, result.image,
                  "the reference's values exceed 32-bit floats; refusing to write it");
  const bool halfFloat = fitsHalfFloat(image);
  const std::filesystem::path writing = result.image.string() + ".writing";
  writeExr(writing, image, halfFloat);
  std::filesystem::rename(writing, result.image);

  result.metadata = {
      {"scene", file.name},
      {"scene_file", config.scene.string()},
      {"image", result.image.filename().string()},
      {"width", film.width()},
      {"height", film.height()},
      {"integrator", settings.type->name},
      {"max_bounces", settings.maxBounces},
      {"spp", timed.stats.passes},
      {"seed", seed},
      {"wall_seconds", timed.wallSeconds},
      {"cpu_seconds", timed.cpuSeconds},
      {"rays", timed.stats.rays},
      {"invalid_samples", timed.stats.invalidSamples},
      {"threads", threads > 0 ? threads : machine.cores},
      {"ranks", group.size()},
      {"machine", toJson(machine)},
      {"revision", kRevision},
      {"created", timestamp()},
      {"format", fmt::format("OpenEXR, {}, ZIP; R, G, B, variance.R/G/B, samples",
                             halfFloat ? "half float (samples 32-bit float)" : "32-bit float")},
      // Every setting spelled out, so that the command remakes this image bit for bit at
      // `revision` (renders do not depend on the thread count).
      {"command", fmt::format("verity reference {} --spp {} --integrator {} --max-bounces {} "
                              "--resolution {} --seed {} -o {}",
                              config.scene.string(), timed.stats.passes, settings.type->name,
                              settings.maxBounces, film.width(), seed, config.directory.string())},
      {"rel_mse", ownRelMse},
      {"rel_mse_epsilon", kRelEpsilon},
      {"rel_mse_note",
       "the reference's own estimated relative MSE: mean over pixels and channels of "
       "(variance / samples) / (mean^2 + epsilon); a study's relative MSE includes it"},
  };
  const std::filesystem::path sidecarWriting = result.sidecar.string() + ".writing";
  {
    std::ofstream out(sidecarWriting);
    if (!out) throw VerityError(result.sidecar.string(), "", "cannot write the sidecar");
    out << result.metadata.dump(2) << '\n';
  }
  std::filesystem::rename(sidecarWriting, result.sidecar);
  return result;
}

}  // namespace verity::studies

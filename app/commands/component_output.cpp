#include "commands/component_output.h"

#include <fmt/format.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "film/image_io.h"
#include "integrators/integrator_registry.h"

namespace verity {

namespace {

// Above this the component films would crowd out everything else on a workstation.
constexpr double kMaxBytes = 8.0 * (1 << 30);

}  // namespace

std::unique_ptr<ComponentImages> makeComponentImages(const std::string& option,
                                                     const IntegratorSettings& integrator,
                                                     const Vector2i& resolution,
                                                     const std::filesystem::path& dir) {
  const bool strategies = option == "--strategies";
  const IntegratorType& type = *integrator.type;
  const int maxBounces = integrator.maxBounces;
  if (strategies && !type.hasStrategies)
    throw VerityError(
        "", option,
        "per-strategy images need --integrator bdpt (the integrator is \"" + type.name + "\")");
  if (!strategies && !type.readsMaxBounces)
    throw VerityError("", option,
                      "per-path-length images need a path tracer, bdpt or light_tracer (the "
                      "integrator is \"" +
                          type.name + "\")");
  const auto kind =
      strategies ? ComponentLayout::Kind::Strategies : ComponentLayout::Kind::PathLengths;
  const uint64_t images = ComponentLayout::sizeFor(kind, maxBounces);
  const double bytes = ComponentImages::bytesNeeded(images, resolution);
  if (bytes > kMaxBytes)
    throw VerityError("", option,
                      fmt::format("{} images of {}×{} at max_bounces {} would need {:.1f} GiB "
                                  "(at most {:.0f}); lower --max-bounces or the resolution",
                                  images, resolution.x(), resolution.y(), maxBounces,
                                  bytes / (1 << 30), kMaxBytes / (1 << 30)));
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir) || access(dir.c_str(), W_OK) != 0)
    throw VerityError(
        dir.string(), option,
        "cannot write to this directory" + (error ? ": " + error.message() : std::string()));
  return std::make_unique<ComponentImages>(ComponentLayout(kind, maxBounces), resolution);
}

void writeComponentImages(const std::filesystem::path& dir, const ComponentImages& images,
                          const RenderRecord& record,
                          const std::map<std::string, std::string>& attributes) {
  const ComponentLayout& layout = images.layout();
  const bool strategies = layout.kind() == ComponentLayout::Kind::Strategies;
  nlohmann::json files = nlohmann::json::array();
  for (int i = 0; i < layout.size(); ++i) {
    const std::string file = layout.name(i) + ".exr";
    ImageChannels image = filmChannels(images.film(i), true);
    image.attributes = attributes;
    image.attributes["verity:component"] = layout.name(i);
    writeExr(dir / file, image);
    const ComponentLayout::Component& c = layout[i];
    nlohmann::json entry = {{"file", file}, {"bounces", c.bounces}};
    if (strategies) {
      entry["s"] = c.s;
      entry["t"] = c.t;
      entry["weighted"] = c.weighted;
    }
    files.push_back(entry);
  }
  const nlohmann::json manifest = {
      {"scene", record.scene},
      {"integrator", record.integrator},
      {"max_bounces", record.maxBounces},
      {"spp", record.spp},
      {"seed", record.seed},
      {"partial", record.partial},
      {"kind", strategies ? "strategies" : "path_lengths"},
      {"meaning",
       strategies
           ? "one image per BDPT strategy (s, t): s light subpath vertices (the point on the "
             "emitter included), t camera subpath vertices (the point on the lens included); "
             "the path has s + t vertices and bounces = s + t - 2 scattering events. "
             "weighted: the strategy's MIS-weighted contribution; the weighted images add up "
             "to the rendered image. unweighted: the strategy's contribution alone, an "
             "estimate of all paths of its length that it can sample. t = 0 (light paths "
             "hitting the lens) is not a strategy of this renderer. Each EXR has R, G, B "
             "(mean), variance.R/G/B (sample variance of one sample) and samples."
           : "one image per path length: the paths of `bounces` scattering events (0: "
             "emitters seen directly); the images add up to the rendered image. Each EXR "
             "has R, G, B (mean), variance.R/G/B (sample variance of one sample) and "
             "samples."},
      {"images", files}};
  std::ofstream out(dir / "manifest.json");
  out << manifest.dump(2) << '\n';
  if (!out) throw VerityError((dir / "manifest.json").string(), "", "cannot write the manifest");
}

}  // namespace verity

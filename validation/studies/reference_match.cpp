#include "validation/studies/reference_match.h"

#include <fmt/format.h>

#include <cmath>

#include "core/error.h"

namespace verity::studies {

namespace {

bool sameScene(const std::filesystem::path& recorded, const std::filesystem::path& scene) {
  std::error_code error;
  const bool equivalent = std::filesystem::equivalent(recorded, scene, error);
  // Both exist: they are the same file or not. Otherwise (the reference was made from
  // another directory) only the names can be compared.
  if (!error) return equivalent;
  return recorded.stem() == scene.stem();
}

}  // namespace

void refuseNonFinite(const ImageChannels& image, const std::filesystem::path& file,
                     const std::string& consequence) {
  for (const auto& [name, plane] : image.planes)
    for (size_t i = 0; i < plane.size(); ++i)
      if (!std::isfinite(plane[i]))
        throw VerityError(
            file.string(), "",
            fmt::format("channel {} at pixel ({}, {}) is {}: {}", name, i % size_t(image.width),
                        i / size_t(image.width), plane[i], consequence));
}

void checkReferenceMatches(const std::filesystem::path& referenceFile,
                           const ImageChannels& reference, const std::filesystem::path& scene,
                           const Vector2i& resolution, bool resolutionGiven, bool force,
                           const std::function<void(const std::string&)>& log) {
  refuseNonFinite(reference, referenceFile,
                  "every error measured against it would be meaningless; make the reference "
                  "again");
  if (reference.width != resolution.x() || reference.height != resolution.y())
    throw VerityError(
        referenceFile.string(), "",
        fmt::format("the reference is {}×{} pixels but the study renders {}×{}: "
                    "errors are measured pixel by pixel (make a reference at this "
                    "resolution{})",
                    reference.width, reference.height, resolution.x(), resolution.y(),
                    resolutionGiven ? ", or leave out --resolution" : " of this scene"));
  const auto it = reference.attributes.find("verity:scene");
  if (it == reference.attributes.end() || it->second.empty()) {
    if (log)
      log(
          fmt::format("{}: warning: the reference records no scene; cannot check that it is "
                      "one of {}",
                      referenceFile.string(), scene.string()));
    return;
  }
  if (sameScene(it->second, scene)) return;
  const std::string problem =
      fmt::format("the reference was made of scene \"{}\", not \"{}\"", it->second, scene.string());
  if (!force)
    throw VerityError(referenceFile.string(), "", problem + " (--force to use it anyway)");
  if (log)
    log(fmt::format("{}: warning: {}; using it anyway (--force)", referenceFile.string(), problem));
}

}  // namespace verity::studies

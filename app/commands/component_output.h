// `verity render --strategies DIR` and `--path-lengths DIR`: which integrators can split
// their estimate so, and the EXR images and manifest.json written to DIR.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "integrators/integrator_settings.h"
#include "render/component_images.h"

namespace verity {

// The images to record for `option` ("--strategies" or "--path-lengths") with `integrator`
// (its type and max bounces) at `resolution`; a clear error for an integrator that cannot produce
// them, a directory that cannot be written, or more images than fit in memory.
std::unique_ptr<ComponentImages> makeComponentImages(const std::string& option,
                                                     const IntegratorSettings& integrator,
                                                     const Vector2i& resolution,
                                                     const std::filesystem::path& dir);

// What the manifest says about the render the images come from.
struct RenderRecord {
  std::string scene, integrator;
  int maxBounces = 0;
  int spp = 0;  // samples per pixel taken (fewer than asked for when interrupted)
  uint64_t seed = 0;
  bool partial = false;
};

// One EXR per component (mean, variance and sample count, as --variance writes) carrying
// `attributes` and its own verity:component, and DIR/manifest.json describing each file.
void writeComponentImages(const std::filesystem::path& dir, const ComponentImages& images,
                          const RenderRecord& record,
                          const std::map<std::string, std::string>& attributes);

}  // namespace verity

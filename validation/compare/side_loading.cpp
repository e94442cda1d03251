#include "validation/compare/side_loading.h"

#include <fmt/format.h>

#include "core/error.h"
#include "film/image_io.h"
#include "validation/compare/exr_statistics.h"
#include "validation/compare/render_set_side.h"
#include "validation/compare/rgb_channels.h"
#include "validation/compare/variance_image_side.h"

namespace verity::validation {

namespace {

bool hasVarianceChannels(const ImageChannels& image) {
  for (const char* name : {"variance.R", "variance.G", "variance.B", "samples"})
    if (!image.planes.count(name)) return false;
  return true;
}

}  // namespace

// RenderSetSide's reading, here with the other reading of a side's files.
RenderSetSide RenderSetSide::load(const std::vector<std::filesystem::path>& files,
                                  const std::string& layer) {
  std::vector<std::string> names;
  std::vector<ImageChannels> images;
  for (const std::filesystem::path& file : files) {
    names.push_back(file.string());
    // Keep only R, G and B of each render while reading the next.
    images.push_back(rgbOnly(readExr(file), file.string(), layer));
  }
  return RenderSetSide(std::move(names), images, "");
}

std::unique_ptr<ComparisonSide> loadSide(const std::vector<std::filesystem::path>& files,
                                         const std::string& name, const std::string& layer) {
  if (files.empty())
    throw VerityError("", "side " + name, "no file given (-a A1.exr ... -b B1.exr ...)");
  if (files.size() > 1) return std::make_unique<RenderSetSide>(RenderSetSide::load(files, layer));
  const std::string file = files.front().string();
  const ImageChannels image = readExr(files.front());
  if (!hasVarianceChannels(image))
    throw VerityError(
        file, "",
        fmt::format("side {} is this one file, which has no variance channels (variance.R, "
                    "variance.G, variance.B and samples, as `verity render --variance` writes "
                    "them): give one image with them, or a set of at least {} independent "
                    "renders (-{} FILE1.exr FILE2.exr ...)",
                    name, RenderSetSide::kMinimumRenders, name == "A" ? "a" : "b"));
  return std::make_unique<VarianceImageSide>(pixelStatistics(image, file));
}

}  // namespace verity::validation

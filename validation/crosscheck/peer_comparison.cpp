#include "peer_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "film/image_io.h"
#include "render/render_batches.h"
#include "validation/compare/batch_regions.h"
#include "validation/compare/suite_samplers.h"

namespace verity::validation {

namespace {

// The relative difference of the whole image's mean (b − a) / a per channel, with its standard
// error, from two single-region batch statistics.
std::string relativeDifference(const PixelStatistics& a, const PixelStatistics& b) {
  std::string out;
  for (int c = 0; c < kChannels; ++c) {
    const double ma = a.mean[c][0], mb = b.mean[c][0];
    const double se = std::sqrt(a.variance[c][0] / a.samples[0] * mb * mb / (ma * ma) +
                                b.variance[c][0] / b.samples[0]) /
                      ma;
    out += fmt::format("{}{:+.2f}% ± {:.2f}%", c ? " / " : "", 100 * (mb / ma - 1), 100 * se);
  }
  return out;
}

}  // namespace

std::vector<std::filesystem::path> peerRenders(const std::filesystem::path& folder,
                                               const std::string& prefix) {
  std::vector<std::filesystem::path> renders;
  if (!std::filesystem::is_directory(folder)) return renders;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".exr" && entry.path().stem().string().starts_with(prefix))
      renders.push_back(entry.path());
  std::sort(renders.begin(), renders.end());
  return renders;
}

uint64_t compareWithPeer(const PeerComparison& setup, SceneFile file, int sceneIndex,
                         const std::string& scene,
                         const std::vector<std::filesystem::path>& renders,
                         const std::vector<const char*>& integrators, ComparisonFamily& family) {
  const Vector2i res = file.scene->camera().resolution();
  int tiles = 0;
  const std::vector<int> regionOf = tileRegions(res.x(), res.y(), setup.tileSize, &tiles);
  // Tiles for the tests; the whole image as one region for the table.
  const std::vector<int> whole(regionOf.size(), 0);
  BatchRegions peer(regionOf, tiles, scene + " " + setup.peer);
  BatchRegions peerImage(whole, 1, scene + " " + setup.peer + " image");
  for (const std::filesystem::path& r : renders) {
    const ImageChannels image = readExr(r);
    peer.addBatch(image);
    peerImage.addBatch(image);
  }
  uint64_t invalid = 0;
  for (size_t i = 0; i < integrators.size(); ++i) {
    const char* integratorName = integrators[i];
    const char* sampler = suiteSampler(sceneIndex, int(i));
    useSampler(file, sampler, setup.batchSpp);
    const std::string key =
        fmt::format("{}{} {} {}", setup.keyPrefix, scene, integratorName, sampler);
    BatchRegions ours(regionOf, tiles, key), oursImage(whole, 1, key + " image");
    invalid += renderBatches(file, integratorName, -1, setup.batches, setup.batchSpp, key,
                             [&](const Film& film) {
                               ours.addBatch(film);
                               oursImage.addBatch(film);
                             });
    fmt::print("| {} | {} | {} | {} |\n", scene, integratorName, sampler,
               relativeDifference(peerImage.statistics(), oursImage.statistics()));
    family.add(key, peer.statistics(), ours.statistics());
  }
  return invalid;
}

}  // namespace verity::validation

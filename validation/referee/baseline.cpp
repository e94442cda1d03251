#include "validation/referee/baseline.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "validation/referee/json_file.h"

namespace verity::validation {

namespace {

constexpr const char* kFormat = "verity-referee-baseline";
constexpr int kVersion = 1;

}  // namespace

void saveBaseline(const std::filesystem::path& file, const Baseline& b) {
  const TileGrid& grid = b.moments.grid();
  nlohmann::json tiles = nlohmann::json::array();
  for (int ty = 0; ty < grid.tilesY(); ++ty)
    for (int tx = 0; tx < grid.tilesX(); ++tx) {
      nlohmann::json mean = nlohmann::json::array(), second = nlohmann::json::array();
      for (const auto& m : b.moments.tile(ty * grid.tilesX() + tx)) {
        mean.push_back(m.mean);
        second.push_back(m.m2 / b.moments.renders());
      }
      tiles.push_back({{"x", tx}, {"y", ty}, {"mean", mean}, {"second_moment", second}});
    }
  const nlohmann::json j = {{"format", kFormat},
                            {"version", kVersion},
                            {"scene", b.scene},
                            {"command", b.command},
                            {"renderer_version", b.rendererVersion},
                            {"seed", b.seed},
                            {"width", grid.width},
                            {"height", grid.height},
                            {"tile_size", grid.tileSize},
                            {"renders", b.moments.renders()},
                            {"tiles", tiles}};
  std::ofstream out(file);
  out << j.dump(1) << "\n";
  if (!out) throw VerityError(file.string(), "", "cannot write the baseline");
}

Baseline loadBaseline(const std::filesystem::path& file) {
  const std::string name = file.string();
  const nlohmann::json j = readJsonFile(file, "baseline");
  const auto field = [&](const nlohmann::json& node, const std::string& key,
                         const std::string& path) -> const nlohmann::json& {
    if (!node.is_object() || !node.contains(key))
      throw VerityError(name, path + key, "missing: is this a baseline saved by --save-baseline?");
    return node.at(key);
  };
  try {
    if (field(j, "format", "/").get<std::string>() != kFormat ||
        field(j, "version", "/").get<int>() != kVersion)
      throw VerityError(name, "/format", fmt::format("not a {} of version {}", kFormat, kVersion));
    Baseline b;
    b.scene = field(j, "scene", "/").get<std::string>();
    b.command = field(j, "command", "/").get<std::string>();
    b.rendererVersion = field(j, "renderer_version", "/").get<std::string>();
    b.seed = field(j, "seed", "/").get<uint64_t>();
    const TileGrid grid{field(j, "width", "/").get<int>(), field(j, "height", "/").get<int>(),
                        field(j, "tile_size", "/").get<int>()};
    const int renders = field(j, "renders", "/").get<int>();
    if (grid.width < 1 || grid.height < 1 || grid.tileSize < 1 || renders < 2)
      throw VerityError(name, "/", "width, height and tile_size must be at least 1, renders 2");
    const nlohmann::json& tiles = field(j, "tiles", "/");
    if (!tiles.is_array() || tiles.size() != size_t(grid.count()))
      throw VerityError(name, "/tiles",
                        fmt::format("must hold the {} tiles of {}x{} pixels in tiles of {}",
                                    grid.count(), grid.width, grid.height, grid.tileSize));
    std::vector<std::array<TileMoments::Moments, kChannels>> moments(grid.count());
    for (int t = 0; t < grid.count(); ++t) {
      const std::string path = fmt::format("/tiles/{}/", t);
      const auto mean = field(tiles[t], "mean", path).get<std::vector<double>>();
      const auto second = field(tiles[t], "second_moment", path).get<std::vector<double>>();
      if (mean.size() != kChannels || second.size() != kChannels)
        throw VerityError(name, path, "mean and second_moment need 3 values (R, G, B)");
      for (int c = 0; c < kChannels; ++c) {
        if (!std::isfinite(mean[c]) || !std::isfinite(second[c]) || second[c] < 0)
          throw VerityError(name, path + "second_moment",
                            "values must be finite, second moments at least 0");
        moments[t][c] = {mean[c], second[c] * renders};
      }
    }
    b.moments = TileMoments(grid, renders, std::move(moments));
    return b;
  } catch (const nlohmann::json::exception& e) {
    throw VerityError(name, "", fmt::format("a field has the wrong type: {}", e.what()));
  }
}

void requireSameSetup(const Baseline& baseline, const std::filesystem::path& file,
                      const std::string& scene, int tileSize) {
  if (baseline.scene != scene)
    throw VerityError(file.string(), "/scene",
                      fmt::format("the baseline is of scene \"{}\", not \"{}\" (the scene is "
                                  "--scene, or else the command template)",
                                  baseline.scene, scene));
  if (baseline.moments.grid().tileSize != tileSize)
    throw VerityError(file.string(), "/tile_size",
                      fmt::format("the baseline has tiles of {} pixels, not --tile {}",
                                  baseline.moments.grid().tileSize, tileSize));
}

}  // namespace verity::validation

namespace verity::validation {

void requireNewSeeds(const Baseline& baseline, const std::filesystem::path& file, uint64_t seed,
                     int maxRenders) {
  // seed + 2i + 1 = base + 2j has a solution with 0 ≤ i < maxRenders, 0 ≤ j < N exactly when
  // the difference is even and j − i = d lies in [−(maxRenders − 1), N − 1].
  const __int128 difference = __int128(seed) + 1 - __int128(baseline.seed);
  if (difference % 2 != 0) return;
  const __int128 d = difference / 2;
  if (d >= -(maxRenders - 1) && d <= baseline.moments.renders() - 1)
    throw VerityError(file.string(), "/seed",
                      fmt::format("the baseline's renders had seeds {} + 2i; with --seed {} the "
                                  "new renders would repeat some: give another --seed (an even "
                                  "difference from the baseline's seed, or an odd one, is safe "
                                  "beyond {} renders)",
                                  baseline.seed, seed, baseline.moments.renders()));
}

}  // namespace verity::validation

// A suite of refereed comparisons in one JSON file, for CI (documented in docs/referee.md):
//   {"entries": [{"name": "cornell-path-vs-bdpt",       required, unique: the test case's name
//                 "scene": "cornell-box",               optional: the scene identifier
//                 "a": "CMD", "b": "CMD",               or "baseline": "FILE" and "b"
//                 "baseline": "FILE",                   relative to the manifest's folder
//                 "save_baseline": "FILE",              optional, with "a"
//                 "margin": 0.01,                       optional: --margin otherwise
//                 "spp": 16,                            optional: --spp otherwise
//                 "budget": {"initial_renders": 4, "max_renders": 64, "max_seconds": 120,
//                            "render_timeout": 60}},
//                                                       optional, each: the option otherwise
//                ...]}
// Unknown keys are refused, so that a misspelt budget is not silently the default.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace verity::validation {

struct ManifestEntry {
  std::string name, scene, a, b;
  std::filesystem::path baseline, saveBaseline;  // empty when not given
  std::optional<double> margin, maxSeconds, renderTimeout;
  std::optional<int> spp, initialRenders, maxRenders;
};

// Throws VerityError naming the file and the JSON path of the problem.
std::vector<ManifestEntry> loadManifest(const std::filesystem::path& file);

}  // namespace verity::validation

// Pieces shared by the studies: scenes at a chosen resolution, seeds, timing, the machine's
// description, relative errors against a reference, and JSON Lines files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "film/film.h"
#include "film/image_io.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace verity::studies {

// The ε in the denominator of the relative squared error (x − r)² / (r² + ε), the relative
// MSE of the adaptive-sampling literature (Rousselle, Knaus and Zwicker 2011, "Adaptive
// Sampling and Reconstruction using Greedy Error Minimization"): it keeps black and
// near-black pixels from dominating the mean. Issue 6 fixes ε = 1e-2.
inline constexpr double kRelEpsilon = 1e-2;

// Loads `file`; with width > 0 the camera renders width × (width · h / w) pixels (the
// scene's aspect ratio kept) by rewriting the camera's resolution before the scene is built.
SceneFile loadStudyScene(const std::filesystem::path& file, int width);
// The scene's JSON with the camera's resolution rewritten that way, or nullopt when the file
// is not JSON; throws VerityError when it cannot be read.
std::optional<nlohmann::json> sceneJsonAtWidth(const std::filesystem::path& file, int width);
// Every scene this project ships, sorted: scenes/*.json, scenes/stress/*.json and
// scenes/crosscheck/*.json under `scenesDir`.
std::vector<std::filesystem::path> shippedScenes(const std::filesystem::path& scenesDir);
// A shipped scene's name as the tests print it: "cornell-box", "stress/floor-40".
std::string shippedSceneName(const std::filesystem::path& file);

// The integrator settings of `file` with the type (any accepted spelling) and max bounces
// (if ≥ 0) overridden; throws VerityError for an unknown type.
IntegratorSettings studyIntegrator(const SceneFile& file, const std::string& type, int maxBounces);

// A stable hash of a string (64-bit FNV-1a), for seeds keyed by names.
uint64_t hashString(const std::string& s);
// The seed of run `run` of `integrator` at budget (`budgetType`, `budget`).
uint64_t runSeed(const std::string& integrator, const std::string& budgetType, double budget,
                 int run);

struct TimedRender {
  RenderStats stats;
  double wallSeconds = 0;  // around render() only: scene loading is not counted
  double cpuSeconds = 0;   // CPU time of the whole process (all threads) over the same span
};
// Renders spp samples per pixel, or, with timeLimit > 0, passes until timeLimit seconds have
// passed (at least one pass; the last pass may overrun the limit). `components`, if given,
// records the per-strategy or per-path-length images as well.
TimedRender timedRender(const SceneFile& file, const Integrator& integrator, Film& film, int spp,
                        int threads, uint64_t seed, double timeLimit = 0,
                        ComponentImages* components = nullptr);

// `batches` independent renders of `spp` samples per pixel with `integrator` (max bounces
// `maxBounces`, the file's when negative), batch i seeded by hashString("<key> batch <i>");
// each film is handed to `onBatch`. Returns the invalid samples of all batches.
uint64_t renderBatches(const SceneFile& file, const std::string& integrator, int maxBounces,
                       int batches, int spp, const std::string& key,
                       const std::function<void(const Film&)>& onBatch);

struct MachineInfo {
  std::string hostname, cpuModel;
  int cores = 0;
};
MachineInfo machineInfo();
nlohmann::json toJson(const MachineInfo& m);
// `git rev-parse HEAD` of the source tree, or "unknown".
std::string sourceRevision();
// The local time as ISO 8601.
std::string timestamp();

// Errors of an image against a reference of the same size (means in planes R, G, B).
struct ErrorStats {
  double relMse = 0;        // mean over pixels and channels of (x − r)² / (r² + ε)
  double meanVariance = 0;  // mean over pixels and channels of the variance of the pixel mean
  double relVariance = 0;   // mean of that variance / (r² + ε): relMse's expectation if unbiased
  size_t pixelsUsed = 0;    // pixels with a finite reference and at least one sample
};
ErrorStats compareToReference(const Film& film, const ImageChannels& reference);
// Per pixel sqrt(mean over channels of (x − r)² / (r² + ε)), row 0 at the top.
std::vector<float> relativeErrorImage(const Film& film, const ImageChannels& reference);
// The reference's own estimated relative MSE: mean of (variance / samples) / (r² + ε).
double referenceRelMse(const ImageChannels& reference);
// A float32 array as a NumPy .npy file (format 1.0), shape (height, width).
void writeNpy(const std::filesystem::path& file, const std::vector<float>& data, int width,
              int height);

// JSON Lines: every line one object. Unparsable lines (a run cut off mid-write) are skipped.
std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& file);
// Appends one line and flushes it to the file before returning.
void appendJsonLine(const std::filesystem::path& file, const nlohmann::json& record);

}  // namespace verity::studies

// Convergence, speed-up and BDPT strategy studies: seeded renders, each one a line of a JSON
// Lines file, so that a study that is interrupted resumes where it stopped.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace verity::studies {

struct ConvergenceConfig {
  std::filesystem::path scene;
  std::vector<std::string> integrators;
  int runs = 4;
  std::string budgetType = "spp";  // "spp" or "time" (seconds)
  std::vector<double> budgets;
  std::vector<int> threads = {0};
  std::filesystem::path reference;  // "": references/<scene>.exr
  std::filesystem::path output = "results.jsonl";
  int resolution = 0;  // image width; 0: the reference's
  int maxBounces = -1;
  // Saves the relative error image (.npy next to the output) of run 0 of each integrator at
  // the largest budget and the first thread count, for the report's false-colour images.
  bool errorImages = true;
};

struct StudyProgress {
  int done = 0, skipped = 0, total = 0;
};

// Runs, in this order: for each thread count, run index, budget and integrator (integrators
// alternate innermost so that a change in the machine's load hits them alike). Runs whose
// key (scene, resolution, integrator, max bounces, threads, budget type, budget, run) is
// already in the output are skipped. `log` gets one line per run.
StudyProgress runConvergenceStudy(const ConvergenceConfig& config,
                                  const std::function<void(const std::string&)>& log);

struct SpeedupConfig {
  std::filesystem::path scene;
  std::vector<std::string> integrators;
  std::vector<int> threads = {1, 2};
  int spp = 16;
  int repeats = 3;
  int resolution = 0;  // image width; 0: the scene's
  int maxBounces = -1;
  std::filesystem::path output = "speedup.jsonl";
};

// Times each integrator at each thread count; thread counts alternate (forwards, then
// backwards) within every repeat. Every render of an integrator uses the same seed, so all
// do the same work (renders are bit-identical across thread counts). Resumable like above.
StudyProgress runSpeedupStudy(const SpeedupConfig& config,
                              const std::function<void(const std::string&)>& log);

struct StrategiesConfig {
  std::filesystem::path scene;
  int spp = 64;
  int resolution = 0;  // image width; 0: the scene's
  // BDPT keeps (k + 1)(k + 4) films for max bounces k, so the scene's usual 64 is out of reach;
  // the record says how much of the full image the strategies up to k account for.
  int maxBounces = 6;
  int threads = 0;                  // 0: all cores
  std::filesystem::path reference;  // optional: the full image, for the share beyond k
  std::filesystem::path output = "strategies.jsonl";
};

// One BDPT render with the MIS-weighted image of every strategy (s, t), reduced to each
// strategy's share of the image: its mean over pixels and channels divided by the image's.
// The shares add up to 1. Resumable like above (key: scene, resolution, max bounces, spp).
StudyProgress runStrategiesStudy(const StrategiesConfig& config,
                                 const std::function<void(const std::string&)>& log);

}  // namespace verity::studies

// The BDPT strategies study: each strategy's share of the image, and each strategy's noise
// against its path length's image and the path tracer's at growing budgets.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "validation/studies/budget.h"
#include "validation/studies/study_records.h"

namespace verity::studies {

struct StrategiesConfig {
  std::filesystem::path scene;
  BudgetType budgetType = BudgetType::Spp;
  std::vector<double> budgets = {64};
  int runs = 1;
  int resolution = 0;  // image width; 0: the reference's, else the scene's
  // Path lengths are counted in bounces k = s + t − 2, as max bounces counts them (Veach's
  // length, in edges, is k + 1). BDPT keeps (k + 1)(k + 4) films for max bounces k, so the
  // scene's usual 64 is out of reach; the record says how much of the full image the
  // strategies up to k account for.
  int maxBounces = 5;
  int threads = 0;  // 0: all cores
  // The path tracer whose path-length images the strategies are set beside.
  std::string pathTracer = "path_tracer_mis";
  std::filesystem::path reference;  // optional: the full image, for the share beyond k
  // Use a reference that records another scene (never one of another resolution).
  bool force = false;
  std::filesystem::path output = "strategies.jsonl";
  // Saves the MIS-weighted strategy images of run 0 at the largest budget (.npy, float16,
  // next to the output) for the report's pyramid.
  bool images = true;
};

// Per run and budget (runs outermost, as in the convergence study), three renders of the same
// budget: BDPT with the weighted and unweighted image of every strategy (s, t); BDPT with its
// path-length images; the path tracer with its path-length images. One record per run and
// budget holds each strategy's share of the image (its weighted image's mean over pixels and
// channels, over the image's; the shares add up to 1) and the relative variances of
// strategy_variance.h of each strategy's unweighted and weighted image and of BDPT's and
// the path tracer's length-k images, all against r_k = the BDPT path-length render's
// length-k image and on the pixels where r_k is non-zero, so that the curves of one length
// average over the same pixels (in the scenes studied every strategy can sample every pixel
// of r_k; one that cannot shows as an unweighted mean short of r_k's).
// Records whose key (scene, resolution, max bounces, budget type, budget, run, path tracer)
// is already in the output are skipped. `log` gets one line per record.
StudyProgress runStrategiesStudy(const StrategiesConfig& config,
                                 const std::function<void(const std::string&)>& log);

}  // namespace verity::studies

#include "validation/referee/referee.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "core/error.h"
#include "validation/referee/moments_side.h"

namespace verity::validation {

std::string RefereeResult::verdictName() const {
  return verdict == Verdict::Undecided ? "INCONCLUSIVE" : validation::verdictName(verdict);
}

void checkRefereeOptions(const RefereeOptions& o) {
  ComparisonOptions comparison;
  comparison.tileSize = o.tileSize;
  comparison.alpha = o.alpha;
  checkComparisonOptions(comparison);
  if (!(o.alpha < 0.5))
    throw VerityError("", "--alpha",
                      fmt::format("the referee's level must be below 0.5 (two one-sided "
                                  "tests), not {}",
                                  o.alpha));
  if (!(o.margin > 0 && o.margin < 1))
    throw VerityError(
        "", "--margin",
        fmt::format("the relative margin must lie strictly between 0 and 1, not {}", o.margin));
  if (o.initialRenders < 2)
    throw VerityError(
        "", "--initial-renders",
        fmt::format("a side needs at least 2 renders for a variance, not {}", o.initialRenders));
  if (o.maxRenders < o.initialRenders)
    throw VerityError(
        "", "--max-renders",
        fmt::format("{} is below --initial-renders {}", o.maxRenders, o.initialRenders));
  if (!(o.maxSeconds >= 0) || !std::isfinite(o.maxSeconds))
    throw VerityError("", "--max-seconds",
                      fmt::format("must be a time of at least 0 seconds, not {}", o.maxSeconds));
}

std::vector<int> renderSchedule(const RefereeOptions& o) {
  std::vector<int> counts;
  for (long n = o.initialRenders;; n *= 2) {
    counts.push_back(int(std::min<long>(n, o.maxRenders)));
    if (n >= o.maxRenders) return counts;
  }
}

uint64_t renderSeed(uint64_t seed, Side side, int index) {
  return seed + 2 * uint64_t(index) + static_cast<uint64_t>(side);
}

RoundLevels roundLevels(const RefereeOptions& options, int round) {
  const double level =
      lookLevel(options.spending, options.alpha, round + 1, int(renderSchedule(options).size()));
  return {level, level};
}

namespace {

// When --max-seconds, counted from `start`, ends: the renders still running then are stopped.
RenderDeadline budgetEnd(const RefereeOptions& options,
                         std::chrono::steady_clock::time_point start) {
  if (!(options.maxSeconds > 0)) return std::nullopt;
  return start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                     std::chrono::duration<double>(options.maxSeconds));
}

}  // namespace

RefereeResult referee(RenderSource& source, const RefereeOptions& options,
                      const TileMoments* baseline) {
  checkRefereeOptions(options);
  if (baseline && (baseline->renders() < 2 || baseline->grid().tileSize != options.tileSize))
    throw VerityError("", "--tile",
                      fmt::format("the baseline has tiles of {} pixels and {} renders; the "
                                  "comparison needs the same tile size and 2 renders",
                                  baseline->grid().tileSize, baseline->renders()));
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // The budget stops the renders in flight at its end, not only the next round.
  const RenderDeadline deadline = budgetEnd(options, start);
  RefereeResult r;
  r.a = baseline ? *baseline : TileMoments(options.tileSize);
  r.b = TileMoments(options.tileSize);
  const std::vector<int> schedule = renderSchedule(options);
  r.plannedRounds = int(schedule.size());
  RoundDecision decision;
  for (int round = 0; round < r.plannedRounds; ++round) {
    std::vector<RenderRequest> requests;
    for (int i = r.b.renders(); i < schedule[round]; ++i) {
      if (!baseline) requests.push_back({Side::A, renderSeed(options.seed, Side::A, i)});
      requests.push_back({Side::B, renderSeed(options.seed, Side::B, i)});
    }
    std::vector<Rendered> images;
    try {
      images = source.render(requests, deadline);
    } catch (const RenderBudgetEnded& ended) {
      r.stopReason = fmt::format(
          "--max-seconds {} reached during round {} of {} ({}): {}", options.maxSeconds, round + 1,
          r.plannedRounds, round == 0 ? "no round was complete" : "that round decides nothing",
          ended.what());
      break;
    }
    for (size_t i = 0; i < images.size(); ++i)
      (requests[i].side == Side::A ? r.a : r.b)
          .add(images[i].image, images[i].label, options.layer);
    const TileGrid &gridA = r.a.grid(), &gridB = r.b.grid();
    if (gridA.width != gridB.width || gridA.height != gridB.height)
      throw VerityError(r.b.firstLabel(), "",
                        fmt::format("{}x{} pixels, while side A{} has {}x{}: both sides must "
                                    "render the same image size",
                                    gridB.width, gridB.height, baseline ? " (the baseline)" : "",
                                    gridA.width, gridA.height));
    ComparisonOptions comparison;
    comparison.tileSize = options.tileSize;
    const RoundLevels levels = roundLevels(options, round);
    comparison.alpha = levels.differ;
    comparison.detectableBias = false;
    r.comparison = compareSides(MomentsSide(r.a, "A"), MomentsSide(r.b, "B"), comparison);
    decision = decideRound(r.comparison, options.margin, levels.equivalence);
    r.rounds.push_back(
        {r.a.renders(), r.b.renders(), elapsed(), decision, r.comparison.holm.rejections});
    if (decision.verdict != Verdict::Undecided) {
      r.verdict = decision.verdict;
      break;
    }
    if (options.maxSeconds > 0 && elapsed() >= options.maxSeconds && round + 1 < r.plannedRounds) {
      r.stopReason = fmt::format("--max-seconds {} reached after {} of {} rounds",
                                 options.maxSeconds, round + 1, r.plannedRounds);
      break;
    }
  }
  if (r.rounds.empty()) return r;  // stopped in the first round: nothing to compare
  // The last look's comparison again, with its power figures for the report.
  ComparisonOptions last = r.comparison.options;
  last.detectableBias = true;
  r.comparison = compareSides(MomentsSide(r.a, "A"), MomentsSide(r.b, "B"), last);
  if (r.verdict != Verdict::Undecided) return r;
  if (r.stopReason.empty())
    r.stopReason = fmt::format("--max-renders {} reached after {} rounds", options.maxRenders,
                               r.plannedRounds);
  r.undecided = undecidedTests(decision);
  r.claimableMargin = claimableImageMargin(r.comparison, decision);
  return r;
}

}  // namespace verity::validation

namespace verity::validation {

TileMoments renderBaselineSide(RenderSource& source, const RefereeOptions& options) {
  checkRefereeOptions(options);
  std::vector<RenderRequest> requests;
  for (int i = 0; i < options.maxRenders; ++i)
    requests.push_back({Side::A, renderSeed(options.seed, Side::A, i)});
  const RenderDeadline deadline = budgetEnd(options, std::chrono::steady_clock::now());
  std::vector<Rendered> images;
  try {
    images = source.render(requests, deadline);
  } catch (const RenderBudgetEnded& ended) {
    throw VerityError("", "--max-seconds",
                      fmt::format("{} s passed before the baseline's {} renders were done, so "
                                  "no baseline was saved: {}",
                                  options.maxSeconds, options.maxRenders, ended.what()));
  }
  TileMoments moments(options.tileSize);
  for (const Rendered& image : images) moments.add(image.image, image.label, options.layer);
  return moments;
}

}  // namespace verity::validation

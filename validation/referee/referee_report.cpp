#include "validation/referee/referee_report.h"

#include <fmt/format.h>

#include <cmath>

#include "validation/compare/comparison_report.h"
#include "validation/compare/equivalence_report.h"

namespace verity::validation {

namespace {

std::string testName(const TileTest& t) {
  return fmt::format("tile ({}, {}) {}", t.tileX, t.tileY, kChannelNames[t.channel]);
}

}  // namespace

nlohmann::json refereeJson(const RefereeResult& r, const RefereeOptions& o) {
  nlohmann::json rounds = nlohmann::json::array();
  for (const RoundRecord& round : r.rounds)
    rounds.push_back({{"renders_a", round.rendersA},
                      {"renders_b", round.rendersB},
                      {"seconds", round.seconds},
                      {"differ_level", round.decision.differLevel},
                      {"equivalence_level", round.decision.equivalenceLevel},
                      {"holm_rejections", round.rejections},
                      {"equivalent_tests", round.decision.equivalentTests},
                      {"decision", verdictName(round.decision.verdict)}});
  nlohmann::json j = {{"verdict", r.verdictName()},
                      {"options",
                       {{"tile_size", o.tileSize},
                        {"alpha", o.alpha},
                        {"margin", o.margin},
                        {"initial_renders", o.initialRenders},
                        {"max_renders", o.maxRenders},
                        {"max_seconds", o.maxSeconds},
                        {"spending", spendingName(o.spending)},
                        {"seed", o.seed}}},
                      {"planned_rounds", r.plannedRounds},
                      {"rounds", rounds},
                      {"renders_a", r.rounds.empty() ? 0 : r.rounds.back().rendersA},
                      {"renders_b", r.rounds.empty() ? 0 : r.rounds.back().rendersB},
                      {"seconds", r.rounds.empty() ? 0.0 : r.rounds.back().seconds}};
  if (r.verdict == Verdict::Undecided) j["stop_reason"] = r.stopReason;
  if (r.rounds.empty()) return j;
  j["comparison"] = comparisonJson(r.comparison);
  j["equivalence"] = equivalenceJson(r.comparison, r.rounds.back().decision, o.margin);
  if (r.verdict == Verdict::Undecided) {
    j["claimable_margin"] = marginJson(r.claimableMargin);
    nlohmann::json undecided = nlohmann::json::array();
    for (size_t i : r.undecided)
      undecided.push_back({{"tile", {r.comparison.tests[i].tileX, r.comparison.tests[i].tileY}},
                           {"channel", kChannelNames[r.comparison.tests[i].channel]}});
    j["undecided"] = undecided;
  }
  return j;
}

std::string refereeSummary(const RefereeResult& r, const RefereeOptions& o) {
  std::string s = fmt::format(
      "referee: margin ±{} of A, level {} for DIFFER and for EQUIVALENT over at most {} rounds "
      "({} spending), tiles of {} pixels\n",
      o.margin, o.alpha, r.plannedRounds, spendingName(o.spending), o.tileSize);
  for (size_t k = 0; k < r.rounds.size(); ++k) {
    const RoundRecord& round = r.rounds[k];
    s += fmt::format(
        "  round {}: {} + {} renders, {:.1f} s: Holm rejects {} at level {:.3g}; {} of {} "
        "tests equivalent at level {:.3g}: {}\n",
        k + 1, round.rendersA, round.rendersB, round.seconds, round.rejections,
        round.decision.differLevel, round.decision.equivalentTests, r.comparison.tests.size(),
        round.decision.equivalenceLevel, verdictName(round.decision.verdict));
  }
  if (r.verdict == Verdict::Differ) {
    for (size_t i : r.comparison.worst(3))
      if (r.comparison.tests[i].rejected)
        s += fmt::format("  differs: {} (A {:.6g}, B {:.6g}, relative difference {:+.3g})\n",
                         testName(r.comparison.tests[i]), r.comparison.tests[i].pooled.a.mean,
                         r.comparison.tests[i].pooled.b.mean,
                         r.comparison.tests[i].relativeDifference);
  } else if (r.verdict == Verdict::Undecided && r.rounds.empty()) {
    s += fmt::format("  {}\n", r.stopReason);
  } else if (r.verdict == Verdict::Undecided) {
    s += fmt::format("  {}; {} tests undecided:", r.stopReason, r.undecided.size());
    for (size_t k = 0; k < std::min<size_t>(r.undecided.size(), 8); ++k)
      s += " " + testName(r.comparison.tests[r.undecided[k]]) + ",";
    if (r.undecided.size() > 8) s += " ...";
    s += fmt::format("\n  the margin that could have been claimed: {}\n",
                     marginText(r.claimableMargin));
  }
  return s + r.verdictName() + "\n";
}

}  // namespace verity::validation

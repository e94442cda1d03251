#include "validation/compare/comparison_family.h"

#include <fmt/format.h>
#include <verity/stats/power.h>

#include "validation/compare/comparison_report.h"

namespace verity::validation {

void ComparisonFamily::add(const std::string& name, const PixelStatistics& a,
                           const PixelStatistics& b) {
  ComparisonOptions options;
  options.tileSize = 1;
  options.alpha = level_;
  names_.push_back(name);
  results_.push_back(compareImages(a, b, options));
}

ComparisonFamily::Decision ComparisonFamily::decide(const std::string& title) const {
  std::vector<double> p;
  for (const ComparisonResult& r : results_)
    for (const TileTest& t : r.tests) p.push_back(t.welch.p);
  const HolmResult holm = holmBonferroni(p, level_);
  fmt::print("{}: {} tests, family-wise level {}, Holm rejections {}\n", title, p.size(), level_,
             holm.rejections);
  // Batches correlate the tiles of a splatting render, so every test is its own group: the
  // power is then a lower bound whatever the dependence (power.h).
  std::vector<PowerTerm> terms;
  for (const ComparisonResult& r : results_)
    for (const TileTest& t : r.tests)
      terms.push_back({0.5 * (t.pooled.a.mean + t.pooled.b.mean),
                       t.pooled.a.variance + t.pooled.b.variance, t.welch.df,
                       static_cast<int>(terms.size())});
  const Decision decision{static_cast<int>(p.size()), holm.rejections,
                          detectableRelativeBias(terms, static_cast<int>(p.size()), level_, 0.9)};
  fmt::print("  uniform relative bias detected with 90% power (lower bound): {:.2f}%\n",
             100 * decision.detectableBias);
  size_t i = 0;
  for (size_t c = 0; c < results_.size(); ++c) {
    double smallest = 1, adjusted = 1;
    int rejected = 0;
    for (size_t j = 0; j < results_[c].tests.size(); ++j, ++i) {
      smallest = std::min(smallest, p[i]);
      adjusted = std::min(adjusted, holm.adjusted[i]);
      rejected += holm.rejected[i];
    }
    fmt::print("  {:44} {:3} tests  smallest p {:9.3g}  Holm-adjusted {:6.3g}  {}\n", names_[c],
               results_[c].tests.size(), smallest, adjusted,
               rejected ? fmt::format("DIFFER ({} rejected)", rejected) : "agree");
    if (rejected) fmt::print("{}", comparisonSummary(results_[c], 3));
  }
  return decision;
}

}  // namespace verity::validation

// Several image comparisons decided together: one Holm correction over every tile test of
// every comparison, so that a suite of comparisons falsely reports a difference with
// probability at most its family-wise level, and the power of the whole family.
#pragma once

#include <string>
#include <vector>

#include "validation/compare/image_comparison.h"

namespace verity::validation {

class ComparisonFamily {
 public:
  explicit ComparisonFamily(double familyWiseLevel) : level_(familyWiseLevel) {}

  // Compares region statistics (batch_regions.h: one "pixel" per region, so tileSize 1).
  void add(const std::string& name, const PixelStatistics& a, const PixelStatistics& b);

  struct Decision {
    int tests = 0;
    int rejections = 0;
    double detectableBias = 0;  // uniform relative bias found with 90% power, lower bound
  };

  // Holm over every test of every comparison; prints each comparison's smallest p, its
  // Holm-adjusted value in the whole family, and the tiles of those that differ.
  Decision decide(const std::string& title) const;

 private:
  double level_;
  std::vector<std::string> names_;
  std::vector<ComparisonResult> results_;
};

}  // namespace verity::validation

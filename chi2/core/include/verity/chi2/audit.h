// Deterministic per-sample checks (no statistics): a value that is NaN, infinite or
// negative, a weight that disagrees with eval·|cos|/pdf, a sample pdf that disagrees with
// pdf(), a reciprocity violation, a sampled direction that is not a unit vector. Each kind
// keeps a count and its first example.
#pragma once

#include <array>
#include <string>

namespace verity::chi2 {

enum class Defect {
  NonFinite,    // NaN or ±Inf from eval, pdf, weight or a sampled direction
  Negative,     // a negative eval, pdf or weight
  Weight,       // weight ≠ eval·|cos θo| / pdf beyond kWeightTolerance
  SamplePdf,    // sample().pdf ≠ pdf(wi, wo) beyond kWeightTolerance
  Reciprocity,  // eval(wi,wo)·ηo² ≠ eval(wo,wi)·ηi² beyond kReciprocityTolerance
  NotUnit,      // a sampled direction whose length is not 1 (to 1e-3)
  Count
};

inline constexpr double kWeightTolerance = 1e-4;       // relative
inline constexpr double kReciprocityTolerance = 1e-3;  // relative
// Values below this are compared absolutely (weights and densities are O(1) or larger).
inline constexpr double kAbsoluteFloor = 1e-6;

// What each defect is called in reports ("weight != eval*cos/pdf", ...).
const char* defectName(Defect d);

// |a − b| ≤ rel · max(|a|, |b|) + floor·rel
bool relativelyClose(double a, double b, double rel);

class Audit {
 public:
  void record(Defect d, const std::string& example);
  void merge(const Audit& other);
  long long count(Defect d) const { return counts_[static_cast<int>(d)]; }
  bool clean() const;
  std::string describe() const;

 private:
  std::array<long long, static_cast<int>(Defect::Count)> counts_{};
  std::array<std::string, static_cast<int>(Defect::Count)> examples_{};
};

}  // namespace verity::chi2

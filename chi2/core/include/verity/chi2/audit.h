// Deterministic per-sample checks (no statistics): a value that is NaN, infinite or
// negative, a weight that disagrees with eval·|cos|/pdf, a sample pdf that disagrees with
// pdf(), a reciprocity violation, a sampled direction that is not a unit vector, a value of
// the wrong size. Each kind keeps a count and its first example; the three comparisons keep
// their worst |ratio − 1| too, with its example, and tell rounding from a bug: a failed
// comparison may come with the |ratio − 1| that rounding the directions alone gives its
// reference there (the reference's condition: a microfacet density from 1 − cos²θ near the
// normal, a Fresnel factor at its critical angle), and one beyond that is "beyond rounding".
// Measuring that costs 17 to 23 more evaluations (twice that for reciprocity, whose two sides
// are both measured), so a caller classifies the first few of each audit and every new worst
// (classifies()), not all of a BSDF that fails everywhere.
#pragma once

#include <array>
#include <limits>
#include <string>

namespace verity::chi2 {

enum class Defect {
  NonFinite,    // NaN or ±Inf from eval, pdf, weight or a sampled direction
  Negative,     // a negative eval, pdf or weight
  Weight,       // weight ≠ eval·|cos θo| / pdf beyond the weight tolerance
  SamplePdf,    // sample().pdf ≠ pdf(wi, wo) beyond the weight tolerance
  Reciprocity,  // eval(wi,wo)·ηo² ≠ eval(wo,wi)·ηi² beyond the reciprocity tolerance
  NotUnit,      // a sampled direction whose length is not 1 (to 1e-3)
  Size,         // a value whose number of components differs from the BSDF's
  Count
};

// The default relative tolerances (BsdfCheckOptions sets others).
inline constexpr double kWeightTolerance = 1e-4;
inline constexpr double kReciprocityTolerance = 1e-3;
// Values below this are compared absolutely (weights and densities are O(1) or larger).
inline constexpr double kAbsoluteFloor = 1e-6;
// How far rounding may move a component of a unit direction in [0.5, 1): 4 units in the last
// place of a float there (2⁻²⁴ each), what a few single-precision operations accumulate;
// smaller components by as many units of their own.
inline constexpr double kDirectionRounding = 4.0 / (1 << 24);
// The failed comparisons of each kind an audit classifies beside every new worst.
inline constexpr long long kClassifiedPerAudit = 16;

// What each defect is called in reports ("weight != eval*cos/pdf", ...).
const char* defectName(Defect d);

// |a − b| ≤ rel · max(|a|, |b|) + floor·rel
bool relativelyClose(double a, double b, double rel);

// |a/b − 1|, the deviation of a from its reference b: 0 where both are 0, +∞ where only b is.
double ratioDeviation(double a, double b);

// max(a/b, b/a) − 1: how far apart a and b are as a factor, whichever is the larger; 0 where
// both are 0, +∞ where only one is.
double factorDeviation(double a, double b);

// The largest |r − 1| of a ratio r on the side of 1 that r lies on, for a reference that
// rounding moves by a factor of up to 1 + spread either way: spread where r ≥ 1, and
// spread / (1 + spread) where r < 1 (a reference rounding may have lowered 7.8 times explains a
// ratio of 7.8 as well as one of 1/7.8).
double deviationWithinFactor(double ratio, double spread);

class Audit {
 public:
  void record(Defect d, const std::string& example);
  // A failed comparison whose |ratio − 1| is `deviation` (+∞ where the reference is 0), where
  // rounding alone moves the reference by up to `rounding` (|ratio − 1|), or NaN where it was
  // not classified.
  void record(Defect d, double deviation, double rounding, const std::string& example);
  // record(d, deviation, rounding(), example), calling rounding() (it costs evaluations) only
  // where the comparison is to be classified: one of the first kClassifiedPerAudit, or a new
  // worst (so the worst is always classified); else as not classified.
  template <class Rounding>
  void recordClassifying(Defect d, double deviation, Rounding&& rounding,
                         const std::string& example) {
    record(d, deviation,
           classifies(d, deviation) ? rounding() : std::numeric_limits<double>::quiet_NaN(),
           example);
  }
  void merge(const Audit& other);
  long long count(Defect d) const { return counts_[static_cast<int>(d)]; }
  // The first example recorded for d; "" when none was.
  const std::string& example(Defect d) const { return examples_[static_cast<int>(d)]; }
  // The largest deviation recorded for d, and where; 0 and "" when none was.
  double worst(Defect d) const { return worst_[static_cast<int>(d)]; }
  const std::string& worstExample(Defect d) const { return worstExamples_[static_cast<int>(d)]; }
  // Of the failed comparisons of d, those classified, those of them beyond what rounding gives
  // there, and the worst of those; 0, 0, 0 and "" when none was.
  long long classified(Defect d) const { return classified_[static_cast<int>(d)]; }
  long long beyondRounding(Defect d) const { return beyond_[static_cast<int>(d)]; }
  double worstBeyondRounding(Defect d) const { return worstBeyond_[static_cast<int>(d)]; }
  const std::string& worstBeyondRoundingExample(Defect d) const {
    return worstBeyondExamples_[static_cast<int>(d)];
  }
  // Every defect is a failed comparison, every one classified within rounding, the worst among
  // them (and there is one).
  bool onlyRounding() const;
  bool clean() const;
  std::string describe() const;
  // Whether the subject runs its per-sample comparisons (weight, sample pdf, reciprocity) on
  // the samples this audit receives: a test that audits a subsample of its samples turns them
  // off beyond it (TestOptions::auditedSamples). What is binned is checked finite either way.
  bool comparesSamples() const { return comparesSamples_; }
  void setComparesSamples(bool on) { comparesSamples_ = on; }
  // The seconds the checks took, which a Subject adds and merge() sums: a check's audit phase
  // (phase_times.h).
  void addSeconds(double seconds) { seconds_ += seconds; }
  double seconds() const { return seconds_; }

 private:
  bool classifies(Defect d, double deviation) const {
    const int i = static_cast<int>(d);
    return classified_[i] < kClassifiedPerAudit || deviation > worst_[i] ||
           worstExamples_[i].empty();
  }

  static constexpr int kKinds = static_cast<int>(Defect::Count);
  std::array<long long, kKinds> counts_{};
  std::array<std::string, kKinds> examples_{};
  std::array<double, kKinds> worst_{};
  std::array<std::string, kKinds> worstExamples_{};
  std::array<long long, kKinds> classified_{}, beyond_{};
  std::array<double, kKinds> worstBeyond_{};
  std::array<std::string, kKinds> worstBeyondExamples_{};
  double seconds_ = 0;
  bool comparesSamples_ = true;
};

}  // namespace verity::chi2

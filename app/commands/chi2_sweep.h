// `verity chi2 --sweep`: one of Verity's materials checked as a family (family_check.h), each
// swept key over its range, so that a user sees the mechanism on a material before writing a
// factory for their own BSDF.
#pragma once

#include <verity/chi2/family_check.h>

#include <string>
#include <vector>

namespace verity {

// One --sweep: a key of the material's JSON and its range, "alpha=1e-3:1:log".
struct SweptKey {
  std::string key;
  double lo = 0, hi = 0;
  bool logarithmic = false;
};

// "KEY=LO:HI" or "KEY=LO:HI:log"; VerityError naming --sweep and what is wrong.
SweptKey parseSweep(const std::string& text);

// Checks the family of `materialJson` with each swept key set to its values; prints the report
// and, with `outputPrefix`, writes PREFIX.md, PREFIX.json and PREFIX.xml (JUnit, one test case
// per configuration), and the figure of each configuration that did not pass, PREFIX-<k>.png
// for the k-th. Returns the family's verdict.
chi2::Verdict runChi2Sweep(const std::string& materialJson, const std::vector<SweptKey>& sweeps,
                           const chi2::FamilyOptions& options, const std::string& outputPrefix);

}  // namespace verity

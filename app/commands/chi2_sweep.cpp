#include "commands/chi2_sweep.h"

#include <fmt/format.h>
#include <unistd.h>

#include <charconv>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "chi2/suite/bsdf_subject.h"
#include "chi2/suite/figure.h"
#include "chi2/suite/suite.h"
#include "cli/output_paths.h"
#include "commands/check_progress_display.h"
#include "core/error.h"

namespace verity {

namespace {

double number(const std::string& text, const std::string& sweep, const char* what) {
  double v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (error != std::errc() || end != text.data() + text.size())
    throw VerityError("--sweep", "",
                      fmt::format("'{}': its {} '{}' is not a number", sweep, what, text));
  return v;
}

// The material's JSON with the swept keys set to `values`.
std::string materialAt(const nlohmann::json& base, const std::vector<SweptKey>& sweeps,
                       const std::vector<double>& values) {
  nlohmann::json m = base;
  for (size_t i = 0; i < sweeps.size(); ++i) m[sweeps[i].key] = values[i];
  return m.dump();
}

void writeText(const std::string& path, const std::string& text) {
  prepareOutputFile(path, "-o");
  std::ofstream out(path);
  out << text;
  if (!out) throw VerityError(path, "", "cannot be written");
}

}  // namespace

SweptKey parseSweep(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw VerityError("--sweep", "",
                      fmt::format("'{}': expected KEY=LO:HI or KEY=LO:HI:log", text));
  SweptKey s;
  s.key = text.substr(0, eq);
  std::vector<std::string> parts;
  for (size_t start = eq + 1;;) {
    const size_t colon = text.find(':', start);
    parts.push_back(text.substr(start, colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts.size() < 2 || parts.size() > 3 || (parts.size() == 3 && parts[2] != "log"))
    throw VerityError("--sweep", "",
                      fmt::format("'{}': expected KEY=LO:HI or KEY=LO:HI:log", text));
  s.lo = number(parts[0], text, "lower end");
  s.hi = number(parts[1], text, "upper end");
  s.logarithmic = parts.size() == 3;
  return s;
}

chi2::Verdict runChi2Sweep(const std::string& materialJson, const std::vector<SweptKey>& sweeps,
                           const chi2::FamilyOptions& options, const std::string& outputPrefix) {
  nlohmann::json base;
  try {
    base = nlohmann::json::parse(materialJson);
  } catch (const nlohmann::json::exception& e) {
    throw VerityError("--material", "", fmt::format("not JSON: {}", e.what()));
  }
  if (!base.is_object()) throw VerityError("--material", "", "expected a JSON object");
  std::vector<chi2::FamilyParameter> box;
  for (const SweptKey& s : sweeps) box.push_back({s.key, s.lo, s.hi, s.logarithmic});
  std::vector<chi2::FamilyConfiguration> configurations;
  try {
    configurations = chi2::familyConfigurations(box, options);
  } catch (const std::invalid_argument& e) {
    throw VerityError("--sweep", "", e.what());
  }
  // Every configuration's material, read before any check: a value the loader refuses is
  // bad input, named with its key and the configuration, not a failure found halfway.
  for (const chi2::FamilyConfiguration& c : configurations) {
    try {
      chi2::suite::makeMaterial(materialAt(base, sweeps, c.values));
    } catch (const VerityError& e) {
      throw VerityError("--sweep", e.jsonPath(),
                        fmt::format("{} (at {}): {}", materialJson, c.name, e.problem()));
    }
  }
  chi2::CheckProgress progress;
  chi2::FamilyOptions run = options;
  run.check.progress = &progress;
  std::optional<CheckProgressDisplay> display(std::in_place, progress, isatty(STDERR_FILENO));
  const chi2::FamilyResult r = chi2::checkBsdfFamily(
      [&](const std::vector<double>& values) {
        return chi2::materialModel(chi2::suite::makeMaterial(materialAt(base, sweeps, values)));
      },
      box, run);
  display.reset();
  std::cout << r.report();
  if (!outputPrefix.empty()) {
    // The figures of the configurations that did not pass, PREFIX-<k> for the k-th in the
    // family's order, listed under the Markdown table; the reports are written first, so that
    // a figure that cannot be drawn (no matplotlib) loses none of them.
    std::string figures;
    std::vector<size_t> drawn;
    for (size_t k = 0; k < r.results.size(); ++k)
      if (!r.results[k].passed()) {
        figures += fmt::format("- {}: {}-{}.png\n", r.configurations[k].name, outputPrefix, k);
        drawn.push_back(k);
      }
    writeText(outputPrefix + ".md",
              r.markdown() +
                  (figures.empty() ? "" : "\nFigures of those that did not pass:\n\n" + figures));
    writeText(outputPrefix + ".json", r.json());
    writeText(outputPrefix + ".xml", r.junit("verity chi2 " + materialJson));
    std::cout << fmt::format("  wrote {0}.md, {0}.json and {0}.xml (JUnit)\n", outputPrefix);
    for (size_t k : drawn)
      std::cout << fmt::format(
          "  figure of {}: {}\n", r.configurations[k].name,
          chi2::writeFigure(r.results[k].test, fmt::format("{}-{}", outputPrefix, k)));
  }
  return r.verdict();
}

}  // namespace verity

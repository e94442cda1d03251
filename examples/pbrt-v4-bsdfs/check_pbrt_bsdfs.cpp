// Checks pbrt-v4's BxDFs as families (verity::chi2::checkBsdfFamily) over the ranges of their
// parameters that pbrt's loader accepts, at a family-wise level of 1%, each configuration
// sized to find a 2% density error over 1/4 of the mass.
//
//   check_pbrt_bsdfs [--only NAME]... [--interior-points N] [--tolerance T]
//                    [--max-samples N] [--stochastic-samples N] [--max-depth N] [--output DIR]
//
// prints each family's report, writes DIR/NAME.md, .json and .txt and the figure data of every
// configuration that did not pass (DIR/NAME-K.json; plot_chi2.py draws it), and a Markdown
// summary of the families on stdout. Exit status: 0 when every family passed, 1 when one did
// not, 2 on bad arguments.
#include <pbrt/options.h>
#include <pbrt/pbrt.h>
#include <verity/chi2/figure_data.h>
#include <verity/chi2/phase_times.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>
#include <string>
#include <thread>

#include "families.h"

namespace {

struct Arguments {
  std::set<std::string> only;
  int interiorPoints = 4;
  double tolerance = 0;      // 0: the check's defaults
  long long maxSamples = 0;  // 0: the check's default budget
  long long stochasticSamples = 400'000;
  int maxDepth = 10;
  std::filesystem::path output = "pbrt-v4-bsdfs";
};

[[noreturn]] void badArgument(const std::string& message) {
  std::cerr << "check_pbrt_bsdfs: " << message << "\n";
  std::exit(2);
}

double number(const std::string& option, const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') badArgument(option + ": '" + text + "' is not a number");
  return value;
}

Arguments parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (i + 1 >= argc) badArgument(option + ": expected a value after it");
    const char* value = argv[++i];
    if (option == "--only") {
      a.only.insert(value);
    } else if (option == "--interior-points") {
      const double n = number(option, value);
      if (n < 0 || n != static_cast<int>(n)) badArgument(option + ": expected a count");
      a.interiorPoints = static_cast<int>(n);
    } else if (option == "--tolerance") {
      a.tolerance = number(option, value);
      if (!(a.tolerance > 0 && a.tolerance < 1)) badArgument(option + ": expected (0, 1)");
    } else if (option == "--max-samples") {
      const double n = number(option, value);
      if (n < 1000 || n != static_cast<long long>(n))
        badArgument(option + ": expected a count >= 1000");
      a.maxSamples = static_cast<long long>(n);
    } else if (option == "--stochastic-samples") {
      const double n = number(option, value);
      if (n < 2 || n != static_cast<long long>(n)) badArgument(option + ": expected a count >= 2");
      a.stochasticSamples = static_cast<long long>(n);
    } else if (option == "--max-depth") {
      const double n = number(option, value);
      if (n < 1 || n != static_cast<int>(n)) badArgument(option + ": expected a count >= 1");
      a.maxDepth = static_cast<int>(n);
    } else if (option == "--output") {
      a.output = value;
    } else {
      badArgument("unknown option '" + option + "'");
    }
  }
  return a;
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) badArgument("cannot write " + path.string());
}

// "  conductor: check 12 of 96" on the terminal while a family runs.
class ProgressLine {
 public:
  ProgressLine(const std::string& family, const verity::chi2::CheckProgress& progress)
      : thread_([this, family, &progress] {
          while (!done_) {
            std::fprintf(stderr, "\r  %s: check %lld of %lld ", family.c_str(),
                         progress.check.load(), progress.checks.load());
            for (int k = 0; k < 10 && !done_; ++k)
              std::this_thread::sleep_for(std::chrono::milliseconds(100));
          }
          std::fprintf(stderr, "\r%*s\r", static_cast<int>(family.size()) + 40, "");
        }) {}
  ~ProgressLine() {
    done_ = true;
    thread_.join();
  }

 private:
  std::atomic<bool> done_{false};
  std::thread thread_;
};

}  // namespace

int main(int argc, char** argv) {
  const Arguments args = parse(argc, argv);
  pbrt::PBRTOptions pbrtOptions;
  pbrtOptions.quiet = true;
  pbrt::InitPBRT(pbrtOptions);

  const pbrt_bsdfs::MetalRange metals = pbrt_bsdfs::namedMetalRange();
  std::vector<pbrt_bsdfs::Family> families = pbrt_bsdfs::families(metals, args.maxDepth);
  for (const std::string& name : args.only) {
    bool known = false;
    for (const auto& f : families) known |= f.name == name;
    if (!known) badArgument("--only: no family '" + name + "'");
  }
  std::filesystem::create_directories(args.output);

  std::printf(
      "pbrt-v4 in %s precision; named metals over %g-%g nm: eta %.4g to %.4g, k %.4g to %.4g\n\n",
      sizeof(pbrt::Float) == 4 ? "single" : "double", metals.lambdaMin, metals.lambdaMax,
      metals.etaMin, metals.etaMax, metals.kMin, metals.kMax);
  std::string summary =
      "| family | BxDF | configurations | passed | failed | inconclusive | seconds |\n"
      "|---|---|---|---|---|---|---|\n";
  bool allPassed = true;
  for (const pbrt_bsdfs::Family& family : families) {
    if (!args.only.empty() && !args.only.count(family.name)) continue;
    verity::chi2::FamilyOptions options;
    options.interiorPoints = args.interiorPoints;
    options.fromBelow = family.fromBelow;
    options.stochastic = family.stochastic;
    options.stochasticCheck.samples = args.stochasticSamples;
    options.configure = family.configure;
    // A failed comparison is within rounding where moving the sampled direction by 4 units in
    // the last place of pbrt's Float moves its reference as far.
    options.check.directionRounding = 2 * std::numeric_limits<pbrt::Float>::epsilon();
    if (args.tolerance > 0) {
      options.check.weightTolerance = args.tolerance;
      options.check.reciprocityTolerance = args.tolerance;
    }
    // A check whose target needs more is never PASSED; the budget bounds what it draws to learn
    // that (a lobe the quadrature cannot follow needs more samples than any budget).
    if (args.maxSamples > 0) options.check.maxSamples = args.maxSamples;
    verity::chi2::CheckProgress progress;
    options.check.progress = &progress;
    const auto start = std::chrono::steady_clock::now();
    verity::chi2::FamilyResult r;
    {
      ProgressLine line(family.name, progress);
      r = verity::chi2::checkBsdfFamily(family.bsdf, family.parameters, options);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::cout << "## " << family.name << ": " << family.description << "\n\n" << r.report() << "\n";
    const std::filesystem::path prefix = args.output / family.name;
    write(prefix.string() + ".md",
          "## " + family.name + ": `" + family.description + "`\n\n" + r.markdown());
    write(prefix.string() + ".json", r.json());
    write(prefix.string() + ".txt", r.report());
    for (size_t k = 0; k < r.results.size(); ++k)  // none in the mean-weight mode
      if (!r.results[k].passed())
        verity::chi2::writeFigureData(r.results[k].test,
                                      prefix.string() + "-" + std::to_string(k) + ".json");

    using verity::chi2::Verdict;
    summary += "| " + family.name + " | `" + family.description + "` | " +
               std::to_string(r.configurations.size()) + " | " +
               std::to_string(r.count(Verdict::Passed)) + " | " +
               std::to_string(r.count(Verdict::Failed)) + " | " +
               std::to_string(r.count(Verdict::Inconclusive)) + " | " +
               std::to_string(static_cast<int>(seconds + 0.5)) + " |\n";
    allPassed &= r.passed();
  }
  std::cout << summary;
  write(args.output / "summary.md", summary);
  pbrt::CleanupPBRT();
  return allPassed ? 0 : 1;
}

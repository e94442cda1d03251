#include "validation/compare_command.h"

#include <fmt/format.h>

#include <charconv>
#include <fstream>

#include "core/error.h"
#include "validation/comparison_report.h"
#include "validation/image_comparison.h"

namespace verity {

namespace {

constexpr int kAgree = 0, kDiffer = 1, kBadInput = 2;

struct CompareArgs {
  std::vector<std::string> images;
  // Read as text and parsed here, so that a malformed value is bad input (status 2) like
  // every other; CLI11's own conversion errors have exit codes of their own.
  std::string tile = "16";
  std::string alpha = "0.01";
  std::string json;
};

template <typename T>
T parseNumber(const std::string& text, const char* option) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || text.empty())
    throw VerityError("", option, fmt::format("\"{}\" is not a number", text));
  return value;
}

int run(const CompareArgs& args) {
  if (args.images.size() != 2)
    throw VerityError("", "",
                      fmt::format("compare needs exactly two images, A.exr and B.exr, "
                                  "not {}",
                                  args.images.size()));
  validation::ComparisonOptions options;
  options.tileSize = parseNumber<int>(args.tile, "--tile");
  options.alpha = parseNumber<double>(args.alpha, "--alpha");
  const validation::PixelStatistics a = validation::loadPixelStatistics(args.images[0]);
  const validation::PixelStatistics b = validation::loadPixelStatistics(args.images[1]);
  const validation::ComparisonResult result = validation::compareImages(a, b, options);
  fmt::print("{}", validation::comparisonSummary(result));
  if (!args.json.empty()) {
    std::ofstream out(args.json);
    out << validation::comparisonJson(result).dump(2) << "\n";
    if (!out) throw VerityError(args.json, "", "cannot write the JSON report");
    fmt::print("wrote {}\n", args.json);
  }
  return result.differ ? kDiffer : kAgree;
}

int runReportingErrors(const CompareArgs& args) {
  try {
    return run(args);
  } catch (const std::exception& e) {
    fmt::print(stderr, "verity: error: {}\n", e.what());
    return kBadInput;
  }
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Do two renders (made with --variance) agree? Welch t-tests per tile, Holm decision; "
      "exit status 0 agree, 1 differ, 2 bad input");
  cmd->add_option("images", args->images, "A.exr B.exr");
  cmd->add_option("--tile", args->tile, "Tile size in pixels (default 16)");
  cmd->add_option("--alpha", args->alpha,
                  "Family-wise significance level of the decision (default 0.01)");
  cmd->add_option("--json", args->json, "Also write every tile's test to this JSON file");
  cmd->callback([args] { throw CLI::RuntimeError(runReportingErrors(*args)); });
}

}  // namespace verity

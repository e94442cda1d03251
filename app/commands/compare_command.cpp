#include "commands/compare_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>

#include "cli/exit_status.h"
#include "cli/number_options.h"
#include "cli/output_paths.h"
#include "cli/subcommand.h"
#include "cli/verdict_command.h"
#include "core/error.h"
#include "validation/compare/compare_decision.h"
#include "validation/compare/distinct_files.h"
#include "validation/compare/image_comparison.h"
#include "validation/compare/side_loading.h"
#include "validation/compare/z_score_image.h"

namespace verity {

namespace {

constexpr int kAgree = 0, kDiffer = 1, kNotShownEquivalent = 3;

struct CompareArgs {
  std::vector<std::string> images;  // A.exr B.exr
  std::vector<std::string> a, b;    // -a A1.exr ..., -b B1.exr ...
  int tile = 16;
  double alpha = 0.01;
  double margin = 0;  // 0: no equivalence test
  std::string layer;
  std::string json;
  std::string zImage;
};

std::vector<std::filesystem::path> paths(const std::vector<std::string>& names) {
  return {names.begin(), names.end()};
}

// The two sides' files: two positional images, or -a and -b.
std::pair<std::vector<std::filesystem::path>, std::vector<std::filesystem::path>> sideFiles(
    const CompareArgs& args) {
  const bool sets = !args.a.empty() || !args.b.empty();
  if (sets && !args.images.empty())
    throw VerityError("", "-a/-b",
                      "give either two images (A.exr B.exr) or the sides with -a and -b, not "
                      "both");
  if (!sets) {
    if (args.images.size() != 2)
      throw VerityError("", "images",
                        fmt::format("compare needs two images, A.exr and B.exr, or the sides "
                                    "with -a A1.exr ... -b B1.exr ...; got {} images",
                                    args.images.size()));
    return {{args.images[0]}, {args.images[1]}};
  }
  if (args.a.empty() || args.b.empty())
    throw VerityError("", args.a.empty() ? "-a" : "-b",
                      "each side needs at least one file: -a A1.exr ... -b B1.exr ...");
  return {paths(args.a), paths(args.b)};
}

int run(const CompareArgs& args) {
  validation::ComparisonOptions options;
  options.tileSize = args.tile;
  options.alpha = args.alpha;
  validation::checkCompareOptions(options, args.margin);
  // Outputs are checked before any work, so that a verdict is never followed by an error.
  if (!args.zImage.empty()) {
    std::string extension = std::filesystem::path(args.zImage).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (extension != ".png")
      throw VerityError("", "--z-image",
                        "writes a PNG, so its name must end in .png, not \"" + args.zImage + "\"");
  }
  if (!args.json.empty()) prepareOutputFile(args.json, "-o");
  if (!args.zImage.empty()) prepareOutputFile(args.zImage, "--z-image");
  const auto [filesA, filesB] = sideFiles(args);
  std::vector<std::filesystem::path> all = filesA;
  all.insert(all.end(), filesB.begin(), filesB.end());
  validation::requireDistinctFiles(all);
  const auto a = validation::loadSide(filesA, "A", args.layer);
  const auto b = validation::loadSide(filesB, "B", args.layer);
  const validation::CompareDecision decision =
      validation::decideComparison(*a, *b, options, args.margin);
  const validation::ComparisonResult& result = decision.comparison;
  fmt::print("{}", decision.summary);
  if (!args.json.empty()) {
    std::ofstream out(args.json);
    out << decision.json.dump(2) << "\n";
    if (!out) throw VerityError(args.json, "", "cannot write the JSON report");
    fmt::print("wrote {}\n", args.json);
  }
  if (!args.zImage.empty()) {
    // Side A is the reference the sign convention (B below or above A) speaks of.
    const std::string caption = result.sideA.renderSet
                                    ? fmt::format("A: mean of {} renders", result.sideA.renders())
                                    : std::string("A: mean image");
    validation::writeZScoreImage(args.zImage, result, a->meanImage(), caption);
    fmt::print(
        "wrote {}: left A's mean image, right each tile's z over it in grey (blue: B below A, "
        "red: B above A, full colour from |z| = z_c = {:.2f}), outlined: rejected by Holm, "
        "hatched: untested\n",
        args.zImage, validation::zScoreSaturation(result));
  }
  if (result.differ) return kDiffer;
  return decision.equivalence && !decision.equivalence->allEquivalent() ? kNotShownEquivalent
                                                                        : kAgree;
}

}  // namespace

void addCompareCommand(CLI::App& app, const ProcessGroup& group) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = addSubcommand(
      app, "compare",
      "Do two sides estimate the same image? A side is one EXR with variance channels "
      "(verity render --variance) or, with -a/-b, a set of independent renders from any "
      "renderer. Welch t-tests per tile, Holm decision; exit status 0 agree, 1 differ, 2 bad "
      "input",
      MpiUse::OneProcess, group);
  cmd->add_option("images", args->images, "A.exr B.exr: two images with variance channels");
  cmd->add_option("-a", args->a,
                  "Side A: one EXR with variance channels, or several independent renders "
                  "(at least 2; the variance from their spread, df = renders - 1)")
      ->type_name("FILE");
  cmd->add_option("-b", args->b, "Side B, like -a")->type_name("FILE");
  cmd->add_option("--tile", args->tile, "Tile size in pixels")->check(wholeNumber(1));
  cmd->add_option("--alpha", args->alpha,
                  "Family-wise significance level of the Holm decision, above 0 and below 1")
      ->check(realNumber(0, false, 1, false));
  cmd->add_option("--margin", args->margin,
                  "Also test equivalence within this relative margin of A (two one-sided tests "
                  "per tile at --alpha); exit status 3 when the sides neither differ nor are "
                  "shown equivalent")
      ->check(realNumber(0, false, 1, false));
  cmd->add_option("--layer", args->layer,
                  "Read a set's R, G, B from this EXR layer (LAYER.R, LAYER.G, LAYER.B) when "
                  "its files have several")
      ->type_name("NAME");
  cmd->add_option("-o,--output", args->json,
                  "Also write every tile's test to this JSON file (missing folders are created)")
      ->type_name("FILE");
  cmd->add_option("--z-image", args->zImage,
                  "Write a PNG of A's mean image beside each tile's z-score over it, with a "
                  "colour bar (blue: B below A, red: B above; outlined: rejected; missing "
                  "folders are created)")
      ->type_name("FILE.png");
  cmd->callback([args] { throw CLI::RuntimeError(runVerdictCommand([&] { return run(*args); })); });
}

}  // namespace verity

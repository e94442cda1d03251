#include "commands/error_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cli/subcommand.h"
#include "core/error.h"
#include "validation/compare/distinct_files.h"
#include "validation/compare/rgb_channels.h"
#include "validation/studies/relative_error.h"

namespace verity {

namespace {

struct ErrorArgs {
  std::string reference;
  std::vector<std::string> images;
  std::string layer;
};

void run(const ErrorArgs& args) {
  // The mean and its standard error assume independent renders: no image twice.
  validation::requireDistinctFiles({args.images.begin(), args.images.end()});
  const ImageChannels reference = studies::readReference(args.reference);
  double sum = 0, sumSquares = 0;
  for (const std::string& file : args.images) {
    const ImageChannels image = readExr(file);
    const double e = studies::imageRelMse(
        image, validation::rgbChannelNames(image, file, args.layer), reference, file);
    fmt::print("relMSE {:.6e}  {}\n", e, file);
    sum += e;
    sumSquares += e * e;
  }
  const double n = double(args.images.size());
  const double mean = sum / n;
  if (args.images.size() > 1) {
    const double sd = std::sqrt(std::max(0.0, (sumSquares - n * mean * mean) / (n - 1)));
    fmt::print("mean relMSE {:.6e} ± {:.2e} (standard error over {} images)\n", mean,
               sd / std::sqrt(n), args.images.size());
  }
  // A reference with variance channels (verity reference, render --variance) states its own
  // error, which every relMSE above contains.
  if (reference.planes.count("samples") && reference.planes.count("variance.R"))
    fmt::print("the reference's own relMSE {:.3e} (contained in each figure above)\n",
               studies::referenceRelMse(reference));
}

}  // namespace

void addErrorCommand(CLI::App& app, const ProcessGroup& group) {
  auto args = std::make_shared<ErrorArgs>();
  CLI::App* cmd = addSubcommand(
      app, "error",
      "Relative MSE of images from any renderer against a reference image, mean over pixels "
      "and channels of (x - r)^2 / (r^2 + 0.01), as bench and the studies measure ours",
      MpiUse::OneProcess, group);
  cmd->add_option("images", args->images, "Images (.exr) to measure")
      ->required()
      ->type_name("IMAGE.exr");
  cmd->add_option("--reference", args->reference,
                  "Reference image (.exr with channels R, G, B) as large as the images")
      ->required()
      ->type_name("FILE");
  cmd->add_option("--layer", args->layer,
                  "Read the images' R, G, B from this EXR layer (LAYER.R, LAYER.G, LAYER.B) "
                  "when their files have several")
      ->type_name("NAME");
  cmd->callback([args] { run(*args); });
}

}  // namespace verity

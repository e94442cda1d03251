// `verity compare`'s refusals: bad input gets an error naming the file (or the option) and
// exit status 2; non-finite pixels in a set are left out of both sides and counted; and the
// channel rule reads EXRs as other renderers write them (rgb_channels.h). The images are
// synthetic (exponential pixel values, seeds fixed by name), written as EXR files here; the
// comparisons that run are decided by Holm at the default family-wise level 1% over 16×16
// tiles (one tile of 16×16 pixels: 3 tests).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "compare_cli.h"
#include "core/error.h"
#include "core/hash.h"
#include "film/image_io.h"
#include "validation/compare/rgb_channels.h"

namespace verity::validation {
namespace {

namespace fs = std::filesystem;
using testing::CompareOutcome;
using testing::runCompare;
using testing::sideArguments;

// Planes named `names` (R, G, B by default) of exponential values with mean 1.
ImageChannels noise(int width, int height, const std::string& seedName,
                    const std::vector<std::string>& names = {"R", "G", "B"}) {
  std::mt19937_64 rng(hashString(seedName));
  std::exponential_distribution<float> exp1(1.0f);
  ImageChannels image;
  image.width = width;
  image.height = height;
  for (const std::string& name : names) {
    auto& plane = image.planes[name];
    plane.resize(size_t(width) * height);
    for (float& v : plane) v = exp1(rng);
  }
  return image;
}

class CompareInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("verity-compare-inputs-") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes `image` as NAME.exr in the test's folder and returns its path.
  std::string write(const std::string& name, const ImageChannels& image, bool half = false) {
    const std::string path = (dir_ / (name + ".exr")).string();
    writeExr(path, image, half);
    return path;
  }
  // A set of `count` independent 16×16 noise renders named PREFIX0.exr, ...
  std::vector<std::string> set(const std::string& prefix, int count, int size = 16) {
    std::vector<std::string> files;
    for (int i = 0; i < count; ++i)
      files.push_back(write(fmt::format("{}{}", prefix, i),
                            noise(size, size, fmt::format("compare-inputs {} {}", prefix, i))));
    return files;
  }
  // Status 2 and an error on stderr containing every one of `words`.
  static void expectBadInput(const CompareOutcome& o, const std::vector<std::string>& words) {
    EXPECT_EQ(o.status, 2) << o.out << o.err;
    for (const std::string& w : words) EXPECT_NE(o.err.find(w), std::string::npos) << o.err;
  }

  fs::path dir_;
};

TEST_F(CompareInputs, SetsOfNoiseFromOneDistributionAgree) {
  // The baseline the refusals below depart from: two sets of 4 noise renders agree.
  const CompareOutcome o = runCompare(sideArguments(set("a", 4), set("b", 4)));
  EXPECT_EQ(o.status, 0) << o.out << o.err;
}

TEST_F(CompareInputs, MismatchedSizesNameTheFiles) {
  const auto a = set("a", 3);
  expectBadInput(runCompare(sideArguments(a, set("small", 3, 8))), {"16x16", "8x8", "small0.exr"});
  // Within a set too.
  auto mixed = set("b", 3);
  mixed.push_back(write("odd", noise(16, 8, "compare-inputs odd")));
  expectBadInput(runCompare(sideArguments(a, mixed)), {"odd.exr", "16x8"});
}

TEST_F(CompareInputs, MissingChannelsNameTheFileAndListItsChannels) {
  auto b = set("b", 2);
  b.push_back(write("luminance", noise(16, 16, "compare-inputs luminance", {"Y"})));
  expectBadInput(runCompare(sideArguments(set("a", 3), b)),
                 {"luminance.exr", "no R, G and B", "Y"});
}

TEST_F(CompareInputs, FewerRendersThanTheTestNeeds) {
  // One file is a side only with variance channels; a set needs at least 2 renders.
  expectBadInput(runCompare(sideArguments(set("a", 1), set("b", 3))),
                 {"a0.exr", "no variance channels", "at least 2"});
  expectBadInput(runCompare({write("x", noise(16, 16, "compare-inputs x")),
                             write("y", noise(16, 16, "compare-inputs y"))}),
                 {"x.exr", "no variance channels"});
}

TEST_F(CompareInputs, TheSameFileTwiceIsRefused) {
  const auto a = set("a", 3);
  // The same path, and the same file by another path.
  expectBadInput(runCompare(sideArguments({a[0], a[1], a[0]}, set("b", 3))),
                 {"a0.exr", "same file"});
  const std::string other = (dir_ / ".." / dir_.filename() / "a1.exr").string();
  expectBadInput(runCompare(sideArguments(a, {other, set("b", 2)[0]})), {"a1.exr", "same file"});
  // A byte-identical copy under another name.
  const fs::path copy = dir_ / "copy.exr";
  fs::copy_file(a[2], copy);
  auto b = set("b", 2);
  b.push_back(copy.string());
  expectBadInput(runCompare(sideArguments(a, b)), {"copy.exr", "a2.exr", "same bytes"});
  // The same render written again with other bytes (a header attribute more).
  ImageChannels again = readExr(a[1]);
  again.attributes["note"] = "written again";
  std::vector<std::string> withAgain = a;
  withAgain.push_back(write("again", again));
  expectBadInput(runCompare(sideArguments(withAgain, set("b", 2))),
                 {"again.exr", "a1.exr", "same R, G and B"});
}

TEST_F(CompareInputs, NonFinitePixelsOfASetAreLeftOutAndCounted) {
  const auto a = set("a", 4);
  auto b = set("b", 4);
  // A NaN in one render and an infinity in another: two pixels leave both sides, counted per
  // file; were they averaged in, tile (0, 0)'s mean would be NaN or infinite.
  ImageChannels doctored = readExr(b[1]);
  doctored.planes["G"][3 * 16 + 5] = std::nanf("");
  b[1] = write("nan", doctored);
  doctored = readExr(b[2]);
  doctored.planes["R"][7 * 16 + 2] = INFINITY;
  b[2] = write("inf", doctored);
  const std::string json = (dir_ / "report.json").string();
  std::vector<std::string> args = sideArguments(a, b);
  args.insert(args.end(), {"-o", json});
  const CompareOutcome o = runCompare(args);
  EXPECT_EQ(o.status, 0) << o.out << o.err;
  EXPECT_NE(o.out.find("nan.exr has 1 pixels with a non-finite value"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("inf.exr has 1 pixels with a non-finite value"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("2 pixels left out"), std::string::npos) << o.out;
  // One image with variance channels and a NaN is refused (Verity never writes one).
  ImageChannels variance = noise(16, 16, "compare-inputs variance",
                                 {"R", "G", "B", "variance.R", "variance.G", "variance.B"});
  variance.planes["samples"].assign(256, 4.0f);
  variance.planes["B"][17] = std::nanf("");
  expectBadInput(runCompare(sideArguments({write("variance", variance)}, b)),
                 {"variance.exr", "not finite"});
}

TEST_F(CompareInputs, OptionsOutOfRangeAreRefusedInWords) {
  const auto a = set("a", 2), b = set("b", 2);
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = sideArguments(a, b);
    args.insert(args.end(), extra.begin(), extra.end());
    return runCompare(args);
  };
  expectBadInput(with({"--tile", "0"}), {"--tile", "at least 1"});
  expectBadInput(with({"--tile", "8.5"}), {"--tile", "whole number"});
  expectBadInput(with({"--alpha", "1.5"}), {"--alpha", "a number above 0 and below 1, not 1.5"});
  expectBadInput(with({"--alpha", "often"}),
                 {"--alpha", "a number above 0 and below 1, not often"});
  // Two images and sides at once, or one side only.
  std::vector<std::string> both = sideArguments(a, b);
  both.insert(both.begin(), a[0]);
  expectBadInput(runCompare(both), {"not both"});
  expectBadInput(runCompare({"-a", a[0], a[1]}), {"-b"});
}

TEST_F(CompareInputs, PbrtStyleChannelNamesAreRead) {
  // pbrt-v4's GBufferFilm writes R, G, B, A with Albedo.R ... beside them; others write
  // one layer (default.R, rgb.R); half floats as often as floats.
  const auto names = [&](const std::string& file, const std::vector<std::string>& planes,
                         const std::string& layer = "") {
    const std::string path = write(file, noise(4, 4, "compare-inputs " + file, planes), true);
    return rgbChannelNames(readExr(path), path, layer);
  };
  using Names = std::array<std::string, kChannels>;
  EXPECT_EQ(names("pbrt", {"R", "G", "B", "A", "Albedo.R", "Albedo.G", "Albedo.B"}),
            (Names{"R", "G", "B"}));
  EXPECT_EQ(names("default", {"default.R", "default.G", "default.B"}),
            (Names{"default.R", "default.G", "default.B"}));
  EXPECT_EQ(names("rgb", {"rgb.R", "rgb.G", "rgb.B", "depth.Z"}),
            (Names{"rgb.R", "rgb.G", "rgb.B"}));
  EXPECT_EQ(
      names("nested", {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B"}),
      (Names{"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B"}));
  // Two layers with R, G and B: ambiguous unless --layer names one.
  const std::vector<std::string> two = {"left.R",  "left.G",  "left.B",
                                        "right.R", "right.G", "right.B"};
  try {
    names("two", two);
    ADD_FAILURE() << "two layers were not refused";
  } catch (const VerityError& e) {
    EXPECT_NE(std::string(e.what()).find("--layer"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("left, right"), std::string::npos) << e.what();
  }
  EXPECT_EQ(names("two-named", two, "right"), (Names{"right.R", "right.G", "right.B"}));
  EXPECT_THROW(names("missing", {"R", "G"}), VerityError);
  // Through the command: a set in layer "rgb" against a set with bare names, and --layer.
  std::vector<std::string> layered, bare = set("bare", 3), twoLayers;
  for (int i = 0; i < 3; ++i) {
    layered.push_back(write(
        fmt::format("layered{}", i),
        noise(16, 16, fmt::format("compare-inputs layered {}", i), {"rgb.R", "rgb.G", "rgb.B"}),
        true));
    twoLayers.push_back(write(fmt::format("two{}", i),
                              noise(16, 16, fmt::format("compare-inputs two {}", i), two), true));
  }
  EXPECT_EQ(runCompare(sideArguments(layered, bare)).status, 0);
  expectBadInput(runCompare(sideArguments(twoLayers, layered)), {"two0.exr", "--layer"});
}

}  // namespace
}  // namespace verity::validation

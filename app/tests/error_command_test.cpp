// `verity error`: the relative MSE of any renderer's images against a reference.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "film/image_io.h"
#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

// A 2 × 1 image whose R, G, B planes hold `r`, `g`, `b` (one value per pixel).
ImageChannels image(std::vector<float> r, std::vector<float> g, std::vector<float> b) {
  ImageChannels out;
  out.width = 2;
  out.height = 1;
  out.planes = {{"R", r}, {"G", g}, {"B", b}};
  return out;
}

// `verity error --reference REF IMAGES...` run in `dir`; its stdout in `*out`.
testing::Outcome errorCommand(const std::filesystem::path& dir, const std::string& ref,
                              const std::vector<std::string>& images, std::string* out) {
  std::string command = "'" VERITY_BINARY "' error --reference '" + ref + "'";
  for (const std::string& i : images) command += " '" + i + "'";
  const std::filesystem::path stdoutFile = dir / "stdout.txt";
  const testing::Outcome r =
      testing::run({"/bin/sh", "-c", command + " > '" + stdoutFile.string() + "'"});
  std::ifstream in(stdoutFile);
  *out = std::string(std::istreambuf_iterator<char>(in), {});
  return r;
}

double printedRelMse(const std::string& text, const std::string& file) {
  std::smatch m;
  const std::regex line("relMSE (\\S+)  " + file);
  if (!std::regex_search(text, m, line)) return NAN;
  return std::stod(m[1]);
}

TEST(ErrorCommand, RelativeMseOfEachImageAndTheirMean) {
  const std::filesystem::path dir = testing::freshTestDirectory("verity_error_");
  const std::string ref = (dir / "ref.exr").string(), a = (dir / "a.exr").string(),
                    b = (dir / "b.exr").string();
  // Reference pixels 1 and 0 in every channel; ε = 0.01.
  writeExr(ref, image({1, 0}, {1, 0}, {1, 0}));
  // a: R of pixel 0 off by 1 → 1 / 1.01; G of pixel 1 off by 0.1 → 0.01 / 0.01 = 1.
  writeExr(a, image({2, 0}, {1, 0.1f}, {1, 0}));
  // b: exact.
  writeExr(b, image({1, 0}, {1, 0}, {1, 0}));
  std::string out;
  const testing::Outcome r = errorCommand(dir, ref, {a, b}, &out);
  ASSERT_EQ(r.status, 0) << r.stderrText;
  const double expectedA = (1 / 1.01 + 0.1 * 0.1 / 0.01) / 6;
  EXPECT_NEAR(printedRelMse(out, a), expectedA, 1e-6 * expectedA) << out;
  EXPECT_EQ(printedRelMse(out, b), 0) << out;
  EXPECT_NE(out.find("mean relMSE"), std::string::npos) << out;
}

// Wrong sizes and non-finite pixels are errors naming the file; a reference pixel that is not
// finite is left out.
TEST(ErrorCommand, BadImagesAreErrorsNamingTheFile) {
  const std::filesystem::path dir = testing::freshTestDirectory("verity_error_");
  const std::string ref = (dir / "ref.exr").string(), nan = (dir / "nan.exr").string(),
                    small = (dir / "small.exr").string(), holes = (dir / "holes.exr").string();
  writeExr(ref, image({1, NAN}, {1, 1}, {1, 1}));
  writeExr(nan, image({1, 1}, {NAN, 1}, {1, 1}));
  ImageChannels one = image({1, 1}, {1, 1}, {1, 1});
  one.width = 1;
  for (auto& [name, plane] : one.planes) plane.resize(1);
  writeExr(small, one);
  std::string out;
  const testing::Outcome badPixel = errorCommand(dir, ref, {nan}, &out);
  EXPECT_EQ(badPixel.status, 2);
  EXPECT_NE(badPixel.stderrText.find(nan + ": pixel (0, 0) of channel G is nan"), std::string::npos)
      << badPixel.stderrText;
  const testing::Outcome size = errorCommand(dir, ref, {small}, &out);
  EXPECT_EQ(size.status, 2);
  EXPECT_NE(size.stderrText.find(small + ": an image of 1×1 against a reference of 2×1"),
            std::string::npos)
      << size.stderrText;
  // Pixel 1 of the reference is not finite in R, so the whole pixel is left out: 3 terms.
  writeExr(holes, image({2, 5}, {1, 5}, {1, 5}));
  const testing::Outcome skipped = errorCommand(dir, ref, {holes}, &out);
  ASSERT_EQ(skipped.status, 0) << skipped.stderrText;
  EXPECT_NEAR(printedRelMse(out, holes), (1 / 1.01) / 3, 1e-6);
}

}  // namespace
}  // namespace verity

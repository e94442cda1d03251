// References and what a study accepts as one.
//   - A reference whose values half floats cannot hold (a visible emitter of radiance 1e5) is
//     written in 32-bit floats, never with Inf; a dim one stays in half floats.
//   - A study refuses a reference of another scene unless forced, and one of another
//     resolution or holding Inf always, before it renders anything.
#include "validation/studies/reference.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>

#include "core/error.h"
#include "film/image_io.h"
#include "validation/studies/convergence.h"

namespace verity::studies {
namespace {

namespace fs = std::filesystem;

// An 8×8 scene: a quad light of radiance `emit` filling the middle of the view, seen
// directly, in front of a grey wall.
std::string sceneText(double emit) {
  return R"({
  "camera": {"transform": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0]}, "vfov": 40,
             "resolution": [8, 8]},
  "integrator": {"type": "path_tracer_mats", "max_bounces": 2},
  "materials": [{"name": "grey", "type": "lambertian", "albedo": 0.5},
                {"name": "light", "type": "diffuse light", "emit": )" +
         std::to_string(emit) + R"(}],
  "surfaces": [{"type": "quad", "size": 1, "material": "light"},
               {"type": "quad", "size": 10, "material": "grey",
                "transform": {"translate": [0, 0, -1]}}]
})";
}

class ReferenceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(testing::TempDir()) / ("verity-reference-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path writeScene(const std::string& name, double emit) {
    const fs::path file = dir_ / (name + ".json");
    std::ofstream(file) << sceneText(emit);
    return file;
  }
  ReferenceResult reference(const fs::path& scene, int width = 0) {
    ReferenceConfig config;
    config.scene = scene;
    config.spp = 8;
    config.resolution = width;
    config.directory = dir_ / "references";
    return makeReference(config);
  }
  ConvergenceConfig study(const fs::path& scene, const fs::path& referenceImage) {
    ConvergenceConfig config;
    config.scene = scene;
    config.integrators = {"path_tracer_mats"};
    config.runs = 1;
    config.budgets = {1};
    config.reference = referenceImage;
    config.output = dir_ / "results.jsonl";
    config.errorImages = false;
    return config;
  }

  fs::path dir_;
};

TEST_F(ReferenceTest, BrightReferenceIsWrittenInFullFloatWithoutInf) {
  const ReferenceResult r = reference(writeScene("bright", 1e5));
  const ImageChannels image = readExr(r.image);
  float largest = 0;
  for (const auto& [name, plane] : image.planes)
    for (float v : plane) {
      ASSERT_TRUE(std::isfinite(v)) << name;
      largest = std::max(largest, v);
    }
  // The light fills pixels: their mean is the radiance, 1e5 (beyond half floats).
  EXPECT_GT(largest, kHalfFloatMax);
  EXPECT_NE(r.metadata["format"].get<std::string>().find("32-bit float"), std::string::npos);
}

TEST_F(ReferenceTest, DimReferenceStaysInHalfFloats) {
  const ReferenceResult r = reference(writeScene("dim", 1));
  EXPECT_NE(r.metadata["format"].get<std::string>().find("half float"), std::string::npos);
}

TEST_F(ReferenceTest, HalfFloatExrRefusesValuesBeyondItsRange) {
  ImageChannels image;
  image.width = image.height = 1;
  image.planes["R"] = {1e5f};
  EXPECT_FALSE(fitsHalfFloat(image));
  EXPECT_THROW(writeExr(dir_ / "bright.exr", image, /*halfFloat=*/true), VerityError);
  EXPECT_NO_THROW(writeExr(dir_ / "bright.exr", image));
}

TEST_F(ReferenceTest, StudyRefusesAnotherScenesReferenceUnlessForced) {
  const fs::path a = writeScene("a", 1), b = writeScene("b", 2);
  const ReferenceResult ofB = reference(b);
  std::string error;
  try {
    runConvergenceStudy(study(a, ofB.image), nullptr);
  } catch (const VerityError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find(ofB.image.string()), std::string::npos) << error;
  EXPECT_NE(error.find("--force"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(dir_ / "results.jsonl")) << "nothing may be rendered";

  ConvergenceConfig forced = study(a, ofB.image);
  forced.force = true;
  std::vector<std::string> said;
  const StudyProgress p =
      runConvergenceStudy(forced, [&](const std::string& line) { said.push_back(line); });
  EXPECT_EQ(p.done, 1);
  ASSERT_FALSE(said.empty());
  EXPECT_NE(said[0].find("warning"), std::string::npos) << said[0];
}

TEST_F(ReferenceTest, StudyRefusesAReferenceOfAnotherResolution) {
  const fs::path a = writeScene("a", 1);
  const ReferenceResult small = reference(a, 4);
  ConvergenceConfig config = study(a, small.image);
  config.resolution = 8;
  try {
    runConvergenceStudy(config, nullptr);
    ADD_FAILURE() << "a 4×4 reference for an 8×8 study was accepted";
  } catch (const VerityError& e) {
    EXPECT_NE(std::string(e.what()).find("4×4"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "results.jsonl")) << "nothing may be rendered";
}

// A reference written before references were checked can hold Inf.
TEST_F(ReferenceTest, StudyRefusesAReferenceHoldingInf) {
  const fs::path a = writeScene("a", 1);
  ImageChannels image = readExr(reference(a).image);
  image.planes.at("variance.G")[3] = std::numeric_limits<float>::infinity();
  const fs::path broken = dir_ / "broken.exr";
  writeExr(broken, image);
  try {
    runConvergenceStudy(study(a, broken), nullptr);
    ADD_FAILURE() << "a reference holding Inf was accepted";
  } catch (const VerityError& e) {
    EXPECT_NE(std::string(e.what()).find("variance.G at pixel (3, 0)"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "results.jsonl")) << "nothing may be rendered";
}

TEST_F(ReferenceTest, StudyAcceptsItsOwnScenesReference) {
  const fs::path a = writeScene("a", 1);
  EXPECT_EQ(runConvergenceStudy(study(a, reference(a).image), nullptr).done, 1);
}

}  // namespace
}  // namespace verity::studies

// Bad input, the same in every command: exit status 2 and one line `verity: error: ...` that
// names the option, the file or the JSON path it is about (app/cli/exit_status.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::freshTestDirectory("verity_bad_input_");
    scene_ = (dir_ / "quad.json").string();
    writeScene(scene_, 16, 8);
  }
  static void writeScene(const std::string& file, int width, int height) {
    std::ofstream(file) << R"({
      "camera": {"transform": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0]},
                 "resolution": [)"
                        << width << ", " << height << R"(], "vfov": 30},
      "background": 1,
      "surfaces": [{"type": "sphere", "material": {"type": "lambertian", "albedo": 0.5}}]})";
  }
  testing::Outcome verity(const std::vector<std::string>& args) {
    std::vector<std::string> all = {VERITY_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    return testing::run(all);
  }

  std::filesystem::path dir_;
  std::string scene_;
};

TEST_F(BadInput, EveryCommandExitsWithTwoAndNamesWhatItIsAbout) {
  const std::string missing = (dir_ / "missing.json").string();
  const std::string missingExr = (dir_ / "missing.exr").string();
  const std::string out = (dir_ / "out.exr").string();
  const std::string jsonl = (dir_ / "out.jsonl").string();
  const std::string lambertian = R"({"type":"lambertian"})";
  struct Case {
    std::vector<std::string> args;
    std::string names;  // what the message must name
  };
  const Case cases[] = {
      {{"render", scene_, "--integrator", "nope", "-o", out}, "--integrator: "},
      {{"render", missing, "-o", out}, missing},
      {{"render", scene_, "-o", (dir_ / "x.jpg").string()}, "-o: "},
      {{"render", scene_, "--variance", "-o", (dir_ / "x.png").string()}, "--variance: "},
      {{"render", scene_, "--resolution", "100000", "-o", out}, "--resolution: "},
      {{"render", scene_, "--integrator", "normals", "--rr-depth", "2", "-o", out}, "--rr-depth: "},
      {{"render", scene_, "--sampler", "nope", "-o", out}, "--sampler: "},
      {{"render", scene_, "--sampler", "halton", "--variance", "-o", out}, "--sampler: "},
      {{"render", scene_, "--frobnicate"}, "--frobnicate"},
      {{"render", scene_, "--spp"}, "--spp"},
      {{"reference", missing, "-o", dir_.string()}, missing},
      {{"reference", scene_, "--integrator", "nope", "-o", dir_.string()}, "--integrator: "},
      {{"study", "convergence", scene_, "--integrator", "bdpt", "-o", jsonl}, "--spp or --time"},
      {{"study", "speedup", missing, "--integrator", "bdpt", "--threads", "1", "-o", jsonl},
       missing},
      {{"study", "speedup", scene_, "--integrator", "nope", "--threads", "1", "-o", jsonl},
       "--integrator: "},
      {{"report", missing, "-o", dir_.string()}, missing},
      {{"bench", missing}, missing},
      {{"bench", scene_, "--rr-depth", "2"}, "--rr-depth: "},
      {{"bench", scene_, "--rr-threshold", "0.5"}, "--rr-threshold: "},
      {{"render", scene_, "--rr-threshold", "0", "-o", out}, "--rr-threshold: "},
      {{"render", scene_, "--rr-threshold", "2", "-o", out}, "--rr-threshold: "},
      {{"error", missingExr, "--reference", missingExr}, missingExr},
      {{"compare", missingExr, missingExr}, missingExr},
      // Outputs are refused before the images are read (and so before any verdict is printed).
      {{"compare", missingExr, missingExr, "--z-image", (dir_ / "z.jpg").string()}, "--z-image: "},
      {{"compare", missingExr, missingExr, "-o", scene_ + "/report.json"}, "-o: cannot create"},
      {{"chi2", "--material", R"({"type":"nope"})"}, "nope"},
      {{"chi2", "--incoming", "10"}, "--material"},
      {{"chi2", "--material", R"({"type":"ggx"})", "--cells", "fine"},
       "--cells: fine not in {equal,grid}"},
      {{"chi2", "--material", lambertian, "--mass", "0.1"}, "--mass requires --detect"},
      {{"chi2", "--material", lambertian, "--detect", "0.01", "--samples", "10"}, "--detect"},
      {{"chi2", "--material", lambertian, "--detect", "0"}, "--detect: "},
      {{"chi2", "--material", lambertian, "--audited-samples", "0"},
       "--audited-samples: must be a whole number of at least 1, not 0"},
      {{"chi2", "--material", lambertian, "--alpha", "1"}, "--alpha: "},
      {{"chi2", "--material", lambertian, "--power", "0.001"}, "--power: "},
  };
  for (const Case& c : cases) {
    std::string command;
    for (const std::string& a : c.args) command += a + " ";
    const testing::Outcome r = verity(c.args);
    EXPECT_EQ(r.status, 2) << command << "\n" << r.stderrText;
    EXPECT_EQ(r.stderrText.rfind("verity: error: ", 0), 0u) << command << "\n" << r.stderrText;
    EXPECT_NE(r.stderrText.find(c.names), std::string::npos) << command << "\n" << r.stderrText;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

// --resolution too large is the option's fault, not the scene file's.
TEST_F(BadInput, AnImageTooLargeBlamesTheOption) {
  const testing::Outcome r =
      verity({"render", scene_, "--resolution", "100000", "-o", (dir_ / "x.exr").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.stderrText.find("quad.json"), std::string::npos) << r.stderrText;
  EXPECT_NE(r.stderrText.find("--resolution: 100000 pixels wide"), std::string::npos)
      << r.stderrText;
}

// A study whose reference has another size advises leaving out --resolution only when it was
// given.
TEST_F(BadInput, AStudyAdvisesOnlyWhatApplies) {
  const testing::Outcome reference =
      verity({"reference", scene_, "--spp", "1", "--threads", "1", "-o", (dir_ / "refs").string()});
  ASSERT_EQ(reference.status, 0) << reference.stderrText;
  const std::string square = (dir_ / "square.json").string();
  writeScene(square, 16, 16);
  const std::vector<std::string> study = {"study",
                                          "convergence",
                                          square,
                                          "--integrator",
                                          "path_tracer_nee",
                                          "--spp",
                                          "1",
                                          "--threads",
                                          "1",
                                          "--reference",
                                          (dir_ / "refs" / "quad.exr").string(),
                                          "-o",
                                          (dir_ / "study.jsonl").string()};
  const testing::Outcome atReferenceWidth = verity(study);
  EXPECT_EQ(atReferenceWidth.status, 2);
  EXPECT_NE(atReferenceWidth.stderrText.find("16×8"), std::string::npos)
      << atReferenceWidth.stderrText;
  EXPECT_EQ(atReferenceWidth.stderrText.find("--resolution"), std::string::npos)
      << atReferenceWidth.stderrText;
  std::vector<std::string> withResolution = study;
  withResolution.insert(withResolution.end(), {"--resolution", "16"});
  const testing::Outcome given = verity(withResolution);
  EXPECT_EQ(given.status, 2);
  EXPECT_NE(given.stderrText.find("leave out --resolution"), std::string::npos) << given.stderrText;
}

}  // namespace
}  // namespace verity

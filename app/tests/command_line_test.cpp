// The conventions every `verity` command shares: --version, --resolution, -o naming each
// command's output (and the one rule for missing folders), one --integrator option, typed
// numbers whose range errors are in words, defaults in --help, and status 2 for a command
// line that cannot be parsed.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "film/image_io.h"
#include "integrators/russian_roulette.h"
#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

class CommandLine : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::freshTestDirectory("verity_command_line_");
    // A 16 × 8 scene whose mesh is found relative to the scene file: a grey quad, lit by a
    // white background, that covers the middle of the frame (|x| < 0.47 and |y| < 0.93 of the
    // half-width and half-height at a field of view of 30 degrees).
    std::filesystem::create_directories(dir_ / "scene" / "meshes");
    std::ofstream(dir_ / "scene" / "meshes" / "quad.obj")
        << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n";
    scene_ = (dir_ / "scene" / "quad.json").string();
    std::ofstream(scene_) << R"({
      "camera": {"transform": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0]},
                 "resolution": [16, 8], "vfov": 30},
      "background": 1,
      "surfaces": [{"type": "mesh", "filename": "meshes/quad.obj",
                    "material": {"type": "lambertian", "albedo": 0.5}}]})";
  }
  testing::Outcome verity(const std::vector<std::string>& args) {
    std::vector<std::string> all = {VERITY_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    return testing::run(all);
  }
  // What `verity ARGS` prints on stdout (run from the folder `cwd`), and its status.
  std::pair<std::string, int> stdoutOf(const std::string& args,
                                       const std::filesystem::path& cwd = "/") {
    const std::filesystem::path out = dir_ / "stdout.txt";
    const testing::Outcome r = testing::run(
        {"/bin/sh", "-c",
         "cd '" + cwd.string() + "' && '" VERITY_BINARY "' " + args + " > '" + out.string() + "'"});
    std::ifstream in(out);
    return {std::string(std::istreambuf_iterator<char>(in), {}), r.status};
  }

  std::filesystem::path dir_;
  std::string scene_;
};

TEST_F(CommandLine, VersionNamesTheRevision) {
  const auto [text, status] = stdoutOf("--version");
  EXPECT_EQ(status, 0);
  EXPECT_TRUE(std::regex_match(text, std::regex("verity [0-9]+\\.[0-9]+\\.[0-9]+ \\(git "
                                                "([0-9a-f]{12}|unknown)\\)\n")))
      << text;
}

// The image is 8 × 4, the scene's aspect kept, and the mesh is found beside the scene although
// the command runs from elsewhere.
TEST_F(CommandLine, RenderAtAnotherResolution) {
  const std::string out = (dir_ / "small.exr").string();
  const auto [text, status] = stdoutOf("render '" + scene_ + "' --spp 1 --resolution 8 -o " + out);
  ASSERT_EQ(status, 0);
  const ImageChannels image = readExr(out);
  EXPECT_EQ(image.width, 8);
  EXPECT_EQ(image.height, 4);
  // The quad fills the middle of the frame, darker than the background of 1.
  EXPECT_LT(image.planes.at("R")[2 * 8 + 4], 0.9f);
}

// A variance estimated from the spread of a pixel's own samples is refused for a sampler whose
// samples are correlated (stratified, halton, sobol): it would overstate the variance of the
// mean and mislead verity compare. Without --variance the same scene renders.
TEST_F(CommandLine, VarianceChannelsNeedIndependentSamples) {
  for (const char* sampler : {"stratified", "halton", "sobol"}) {
    std::ifstream in(scene_);
    std::string json(std::istreambuf_iterator<char>(in), {});
    json.insert(json.find('{') + 1, std::string(R"("sampler": {"type": ")") + sampler + "\"},");
    const std::filesystem::path scene = dir_ / "scene" / (std::string(sampler) + ".json");
    std::ofstream(scene) << json;
    const std::string out = (dir_ / (std::string(sampler) + ".exr")).string();
    const testing::Outcome refused =
        verity({"render", scene.string(), "--spp", "4", "--variance", "-o", out});
    EXPECT_EQ(refused.status, 2) << sampler << "\n" << refused.stderrText;
    EXPECT_NE(refused.stderrText.find("sampler.type"), std::string::npos) << refused.stderrText;
    EXPECT_NE(refused.stderrText.find("independent"), std::string::npos) << refused.stderrText;
    EXPECT_FALSE(std::filesystem::exists(out));
    const testing::Outcome rendered = verity({"render", scene.string(), "--spp", "4", "-o", out});
    EXPECT_EQ(rendered.status, 0) << sampler << "\n" << rendered.stderrText;
  }
}

// --sampler renders with a registry sampler at its defaults in place of the scene's: the
// scene's own type by name gives the same image, another type another image; an unknown name
// and variance channels from correlated samples are refused naming the option.
TEST_F(CommandLine, RenderWithAnotherSampler) {
  const auto render = [&](const std::vector<std::string>& extra, const std::string& name) {
    std::vector<std::string> args = {"render", scene_, "--spp", "4",
                                     "--seed", "7",    "-o",    (dir_ / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return verity(args);
  };
  ASSERT_EQ(render({}, "scene.exr").status, 0);
  ASSERT_EQ(render({"--sampler", "Independent"}, "independent.exr").status, 0);
  ASSERT_EQ(render({"--sampler", "sobol"}, "sobol.exr").status, 0);
  EXPECT_EQ(readExr(dir_ / "scene.exr").planes, readExr(dir_ / "independent.exr").planes);
  EXPECT_NE(readExr(dir_ / "scene.exr").planes, readExr(dir_ / "sobol.exr").planes);
  const testing::Outcome unknown = render({"--sampler", "sobolev"}, "x.exr");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.stderrText.find("--sampler: unknown sampler type \"sobolev\""),
            std::string::npos)
      << unknown.stderrText;
  const testing::Outcome variance = render({"--sampler", "halton", "--variance"}, "y.exr");
  EXPECT_EQ(variance.status, 2);
  EXPECT_NE(variance.stderrText.find("--sampler: the variance channels"), std::string::npos)
      << variance.stderrText;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "y.exr"));
}

// --rr-depth and --rr-threshold override the integrator's "rr_depth" and "rr_threshold": their
// default values give the same image, others another; an integrator without roulette refuses
// them. The quad's paths make one bounce, of throughput 0.5: roulette decides there only at
// depth 1, and ends half the paths at threshold 1 and none at 0.25.
TEST_F(CommandLine, RouletteOverrides) {
  const auto render = [&](const std::vector<std::string>& extra, const std::string& name) {
    std::vector<std::string> args = {"render", scene_, "--spp", "4",
                                     "--seed", "7",    "-o",    (dir_ / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return verity(args);
  };
  ASSERT_EQ(render({}, "scene.exr").status, 0);
  const std::string depth = std::to_string(kDefaultRouletteDepth);
  // The scene names no integrator: it gets path_tracer_mats.
  const std::string threshold = fmt::format("{}", kPathTracerRouletteThreshold);
  ASSERT_EQ(render({"--rr-depth", depth, "--rr-threshold", threshold}, "default.exr").status, 0);
  ASSERT_EQ(render({"--rr-depth", "1", "--rr-threshold", "1"}, "one.exr").status, 0);
  ASSERT_EQ(render({"--rr-depth", "2", "--rr-threshold", "1"}, "two.exr").status, 0);
  ASSERT_EQ(render({"--rr-depth", "1", "--rr-threshold", "0.25"}, "quarter.exr").status, 0);
  const auto planes = [&](const char* name) { return readExr(dir_ / name).planes; };
  EXPECT_EQ(planes("scene.exr"), planes("default.exr"));
  EXPECT_NE(planes("one.exr"), planes("two.exr"));
  EXPECT_NE(planes("one.exr"), planes("quarter.exr"));
  const testing::Outcome refused = render({"--integrator", "normals", "--rr-depth", "2"}, "n.exr");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.stderrText.find("--rr-depth: the integrator \"normals\" has no Russian "
                                    "roulette"),
            std::string::npos)
      << refused.stderrText;
  const testing::Outcome refusedThreshold =
      render({"--integrator", "normals", "--rr-threshold", "0.5"}, "n.exr");
  EXPECT_EQ(refusedThreshold.status, 2);
  EXPECT_NE(refusedThreshold.stderrText.find("--rr-threshold: the integrator \"normals\" has "
                                             "no Russian roulette"),
            std::string::npos)
      << refusedThreshold.stderrText;
}

// -o names every command's output: a file (render, compare), a folder (reference), a prefix
// (chi2); missing folders on the way are created.
TEST_F(CommandLine, DashOCreatesMissingFolders) {
  const std::filesystem::path a = dir_ / "new" / "a" / "image.exr";
  ASSERT_EQ(verity({"render", scene_, "--spp", "2", "--variance", "-o", a.string()}).status, 0);
  EXPECT_TRUE(std::filesystem::exists(a));
  const std::filesystem::path references = dir_ / "new" / "references";
  const testing::Outcome reference =
      verity({"reference", scene_, "--spp", "2", "--threads", "1", "-o", references.string()});
  ASSERT_EQ(reference.status, 0) << reference.stderrText;
  EXPECT_TRUE(std::filesystem::exists(references / "quad.exr"));
  EXPECT_TRUE(std::filesystem::exists(references / "quad.json"));
  const std::filesystem::path json = dir_ / "new" / "b" / "report.json";
  const testing::Outcome compare =
      verity({"compare", a.string(), (references / "quad.exr").string(), "-o", json.string()});
  EXPECT_LE(compare.status, 1) << compare.stderrText;
  EXPECT_TRUE(std::filesystem::exists(json));
  const std::filesystem::path prefix = dir_ / "new" / "c" / "figure";
  verity({"chi2", "--material", R"({"type":"lambertian"})", "--samples", "20000", "-o",
          prefix.string()});
  EXPECT_TRUE(std::filesystem::exists(prefix.string() + ".json"));
}

// A folder that cannot be made is refused by name before any work, by every command.
TEST_F(CommandLine, DashOThroughAFileIsRefused) {
  std::ofstream(dir_ / "file") << "not a folder";
  const std::string blocked = (dir_ / "file" / "out").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"render", scene_, "--spp", "1", "-o", blocked + ".exr"},
        {"reference", scene_, "--spp", "1", "-o", blocked},
        {"study", "speedup", scene_, "--integrator", "path_tracer_nee", "--threads", "1", "--spp",
         "1", "--repeats", "1", "-o", blocked + ".jsonl"}}) {
    const testing::Outcome r = verity(args);
    EXPECT_NE(r.status, 0) << args[0];
    EXPECT_NE(r.stderrText.find("-o: cannot create the folder"), std::string::npos) << r.stderrText;
    EXPECT_EQ(r.stderrText.find("spp"), std::string::npos) << r.stderrText;
  }
}

// One spelling, --integrator, taking a list where a command compares several; an unknown
// member is named with the option as the user wrote it.
TEST_F(CommandLine, OneIntegratorOption) {
  const testing::Outcome r =
      verity({"study", "speedup", scene_, "--integrator", "path_tracer_nee,foo", "--threads", "1",
              "--spp", "1", "--repeats", "1", "-o", (dir_ / "speedup.jsonl").string()});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.stderrText.find("--integrator: "), std::string::npos) << r.stderrText;
  EXPECT_NE(r.stderrText.find("\"foo\""), std::string::npos) << r.stderrText;
  const testing::Outcome old =
      verity({"study", "speedup", scene_, "--integrator", "bdpt", "--integrators", "bdpt"});
  EXPECT_EQ(old.status, 2);
  EXPECT_NE(old.stderrText.find("--integrators"), std::string::npos) << old.stderrText;
}

// Counts are whole numbers (2.5 is refused, not rounded), ranges are said in words, and a
// command line that cannot be parsed exits with status 2 whatever the command.
TEST_F(CommandLine, NumbersAreTypedAndRangesSaidInWords) {
  const std::string out = (dir_ / "x.exr").string();
  const std::string ref = (dir_ / "x").string();
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const Case cases[] = {
      {{"render", scene_, "--spp", "0", "-o", out},
       "--spp: must be a whole number of at least 1, not 0"},
      {{"render", scene_, "--spp", "2.5", "-o", out},
       "--spp: must be a whole number of at least 1, not 2.5"},
      {{"render", scene_, "--resolution", "-3", "-o", out},
       "--resolution: must be a whole number of at least 1, not -3"},
      {{"render", scene_, "--threads", "-1", "-o", out},
       "--threads: must be a whole number of at least 0, not -1"},
      {{"reference", scene_, "--spp", "1.5", "-o", ref},
       "--spp: must be a whole number of at least 1, not 1.5"},
      {{"study", "convergence", scene_, "--integrator", "bdpt", "--spp", "4,2.5", "-o",
        ref + ".jsonl"},
       "--spp: must be a whole number of at least 1, not 2.5"},
      {{"study", "convergence", scene_, "--integrator", "bdpt", "--time", "0", "-o",
        ref + ".jsonl"},
       "--time: must be a number above 0, not 0"},
      {{"bench", scene_, "--repeats", "0"},
       "--repeats: must be a whole number of at least 1, not 0"},
      {{"compare", out, out, "--tile", "x"}, "--tile: must be a whole number of at least 1, not x"},
      {{"compare", out, out, "--alpha", "1"},
       "--alpha: must be a number above 0 and below 1, not 1"},
      {{"chi2", "--material", R"({"type":"lambertian"})", "--incoming", "91"},
       "--incoming: must be a number at least 0 and at most 90, not 91"},
  };
  for (const Case& c : cases) {
    const testing::Outcome r = verity(c.args);
    EXPECT_EQ(r.status, 2) << c.message << "\n" << r.stderrText;
    EXPECT_NE(r.stderrText.find(c.message), std::string::npos) << r.stderrText;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

// --help shows every option's default and what --threads 0 means.
TEST_F(CommandLine, HelpShowsDefaults) {
  const auto [render, renderStatus] = stdoutOf("render --help");
  EXPECT_EQ(renderStatus, 0);
  for (const char* text : {"--spp INT=the scene's", "0: all cores", "--resolution", "created"})
    EXPECT_NE(render.find(text), std::string::npos) << text << "\n" << render;
  const auto [chi2, chi2Status] = stdoutOf("chi2 --help");
  EXPECT_EQ(chi2Status, 0);
  for (const char* text :
       {"--samples INT=1000000", "--detect 0.02", "PREFIX", "--threads", "0: all cores"})
    EXPECT_NE(chi2.find(text), std::string::npos) << text << "\n" << chi2;
  const auto [study, studyStatus] = stdoutOf("study speedup --help");
  EXPECT_EQ(studyStatus, 0);
  for (const char* text : {"--threads INT=[1,2]", "--spp INT=16", "--output TEXT=speedup.jsonl"})
    EXPECT_NE(study.find(text), std::string::npos) << text << "\n" << study;
}

}  // namespace
}  // namespace verity

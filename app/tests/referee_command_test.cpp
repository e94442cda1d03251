// `verity referee` as users run it: through command templates, on the fake renderer
// (validation/referee/tests/fake_renderer.cpp) and on Verity's own integrators; its exit
// statuses, reports (JSON, JUnit, z-images), baselines and manifests, and every refusal
// (exit status 2, naming what it is about, before any render).
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

// The fake renderer, with pixels of sd 0.05 unless `extra` sets --noise: equal sides are
// EQUIVALENT within the fixture's 5% margin in two rounds (8 renders a side), where the
// renderer's own 0.25 took six (128 a side: seconds here, most of a minute a test under the
// sanitizers). What these tests check is the command, not the rounds' statistics
// (validation/referee/tests).
std::string fake(const std::string& extra = "") {
  const std::string noise = extra.find("--noise") == std::string::npos ? " --noise 0.05" : "";
  return std::string(FAKE_RENDERER) + " --seed {seed} --out {out}" + noise + extra;
}

std::string readText(const std::filesystem::path& file) {
  std::stringstream s;
  s << std::ifstream(file).rdbuf();
  return s.str();
}

testing::Outcome verity(std::vector<std::string> args) {
  args.insert(args.begin(), VERITY_BINARY);
  return testing::run(args);
}

class RefereeCommand : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::freshTestDirectory("verity_referee_"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // The fake renderer's small images: tiles of 4 pixels, a 5% margin at level 0.05.
  // These options, unless `args` gives them.
  std::vector<std::string> referee(std::vector<std::string> args) {
    const std::pair<std::string, std::string> defaults[] = {
        {"--tile", "4"},
        {"--margin", "0.05"},
        {"--alpha", "0.05"},
        {"--max-renders", "128"},
        {"--work-dir", (dir_ / "work").string()}};
    args.insert(args.begin(), "referee");
    for (const auto& [option, value] : defaults)
      if (std::find(args.begin(), args.end(), option) == args.end())
        args.insert(args.end(), {option, value});
    return args;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(RefereeCommand, ExitStatusIsTheDecision) {
  EXPECT_EQ(verity(referee({"--a", fake(), "--b", fake()})).status, 0);
  EXPECT_EQ(verity(referee({"--a", fake(), "--b", fake(" --bias 0.2")})).status, 1);
  // Four renders of very noisy images decide nothing.
  const testing::Outcome undecided =
      verity(referee({"--a", fake(" --noise 3"), "--b", fake(" --noise 3"), "--max-renders", "4"}));
  EXPECT_EQ(undecided.status, 3) << undecided.stderrText;
}

// Ctrl-C ends the rounds with no decision (exit status 130, as an interrupted render) once
// the renders in flight are done, and the referee's own folder of renders goes with it.
TEST_F(RefereeCommand, CtrlCEndsWithoutADecisionAndLeavesNoRenders) {
  const std::filesystem::path tmp = dir_ / "tmp";  // the referee's temp folder (TMPDIR)
  std::filesystem::create_directories(tmp);
  const std::string slow = "sleep 1; " + fake();
  const std::string stderrFile = path("stderr.txt");
  const pid_t pid = testing::spawn({"/usr/bin/env", "TMPDIR=" + tmp.string(), VERITY_BINARY,
                                    "referee", "--a", slow, "--b", slow, "--tile", "4"},
                                   stderrFile);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // in the first round
  kill(pid, SIGINT);
  const testing::Outcome o = testing::finish(pid, stderrFile);
  EXPECT_EQ(o.status, 130) << o.stderrText;
  EXPECT_NE(o.stderrText.find("interrupted"), std::string::npos) << o.stderrText;
  EXPECT_TRUE(std::filesystem::is_empty(tmp)) << "the renders' folder was left behind";
}

// A render that hangs ends the referee at its --render-timeout with exit status 2, naming the
// command; the budget (--max-seconds) ends renders still running with INCONCLUSIVE (3). Both
// leave neither the referee's folder of renders nor a process behind.
TEST_F(RefereeCommand, HungRendersEndAtTheirLimitsAndLeaveNothingBehind) {
  const std::filesystem::path tmp = dir_ / "tmp";  // the referee's temp folder (TMPDIR)
  std::filesystem::create_directories(tmp);
  const auto run = [&](std::vector<std::string> args) {
    args.insert(args.begin(), {"/usr/bin/env", "TMPDIR=" + tmp.string(), VERITY_BINARY, "referee",
                               "--tile", "4"});
    const auto start = std::chrono::steady_clock::now();
    const testing::Outcome o = testing::run(args);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60);
    EXPECT_TRUE(std::filesystem::is_empty(tmp)) << "the renders' folder was left behind";
    return o;
  };
  const testing::Outcome hung =
      run({"--a", fake(), "--b", "sleep 986.25; " + fake(), "--render-timeout", "1"});
  EXPECT_EQ(hung.status, 2) << hung.stderrText;
  EXPECT_NE(hung.stderrText.find("side B (seed 1) `sleep 986.25;"), std::string::npos)
      << hung.stderrText;
  EXPECT_NE(hung.stderrText.find("ran past its limit of 1 s per render"), std::string::npos)
      << hung.stderrText;
  // The same limit from a manifest entry's budget, and a bad one refused before any render.
  const std::string manifest = path("suite.json");
  const auto writeManifest = [&](const std::string& timeout) {
    std::ofstream(manifest) << nlohmann::json{
        {"entries",
         {{{"name", "hung"},
           {"a", fake()},
           {"b", "sleep 986.75; " + fake()},
           {"budget", {{"render_timeout", nlohmann::json::parse(timeout)}}}}}}};
  };
  writeManifest("1");
  const testing::Outcome fromManifest = run({"--manifest", manifest});
  EXPECT_EQ(fromManifest.status, 2) << fromManifest.stderrText;
  EXPECT_NE(fromManifest.stderrText.find("ran past its limit of 1 s per render"), std::string::npos)
      << fromManifest.stderrText;
  writeManifest("-1");
  const testing::Outcome refused = run({"--manifest", manifest});
  EXPECT_EQ(refused.status, 2) << refused.stderrText;
  EXPECT_NE(refused.stderrText.find("budget/render_timeout"), std::string::npos)
      << refused.stderrText;
  const std::string json = path("budget.json");
  const testing::Outcome budget =
      run({"--a", "sleep 986.5; " + fake(), "--b", fake(), "--max-seconds", "1", "--json", json});
  EXPECT_EQ(budget.status, 3) << budget.stderrText;
  const nlohmann::json entry = nlohmann::json::parse(std::ifstream(json))["entries"][0];
  EXPECT_EQ(entry["verdict"], "INCONCLUSIVE");
  EXPECT_NE(entry["stop_reason"].get<std::string>().find("--max-seconds 1 reached during round 1"),
            std::string::npos)
      << entry.dump();
  for (const auto& process : std::filesystem::directory_iterator("/proc")) {
    std::ifstream file(process.path() / "cmdline", std::ios::binary);
    const std::string cmdline((std::istreambuf_iterator<char>(file)), {});
    EXPECT_EQ(cmdline.find("986."), std::string::npos) << "a render outlived the referee";
  }
}

TEST_F(RefereeCommand, JsonCarriesTheRoundsAndTiles) {
  const std::string json = path("out/report.json");
  ASSERT_EQ(verity(referee({"--a", fake(), "--b", fake(" --bias 0.2"), "--json", json,
                            "--renderer-version", "fake 1"}))
                .status,
            1);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  ASSERT_EQ(j["entries"].size(), 1u);
  const nlohmann::json& e = j["entries"][0];
  EXPECT_EQ(e["verdict"], "DIFFER");
  EXPECT_EQ(e["renderer_version"], "fake 1");
  ASSERT_FALSE(e["rounds"].empty());
  EXPECT_EQ(e["rounds"].back()["decision"], "DIFFER");
  EXPECT_GE(e["rounds"][0]["renders_b"].get<int>(), 4);
  EXPECT_TRUE(e["rounds"][0].contains("seconds"));
  EXPECT_EQ(e["comparison"]["tile_tests"].size(), 12u);  // 4 tiles, 3 channels
  EXPECT_EQ(e["equivalence"]["tests"].size(), 12u);
  EXPECT_EQ(j["exit_status"], 1);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "work") && !std::filesystem::is_empty(dir_ / "work"));
}

TEST_F(RefereeCommand, BaselineIsSavedThenDecidesTheNewSideAlone) {
  const std::string baseline = path("base/fake.json");
  const testing::Outcome saved = verity(referee(
      {"--a", fake(), "--save-baseline", baseline, "--max-renders", "16", "--scene", "fake"}));
  ASSERT_EQ(saved.status, 0) << saved.stderrText;
  const nlohmann::json b = nlohmann::json::parse(std::ifstream(baseline));
  EXPECT_EQ(b["renders"], 16);
  EXPECT_EQ(b["scene"], "fake");
  EXPECT_EQ(b["tiles"].size(), 4u);
  EXPECT_EQ(verity(referee({"--baseline", baseline, "--b", fake(), "--scene", "fake"})).status, 0);
  EXPECT_EQ(verity(referee({"--baseline", baseline, "--b", fake(" --bias 0.2 --biased-tiles 1"),
                            "--scene", "fake"}))
                .status,
            1);
  // Another scene, tile size or image size is refused.
  testing::Outcome o = verity(referee({"--baseline", baseline, "--b", fake(), "--scene", "other"}));
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.stderrText.find(baseline + ": /scene: the baseline is of scene \"fake\""),
            std::string::npos)
      << o.stderrText;
  o = verity(referee({"--baseline", baseline, "--b", fake(), "--scene", "fake", "--tile", "2"}));
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.stderrText.find("/tile_size"), std::string::npos) << o.stderrText;
  o = verity(referee({"--baseline", baseline, "--b", fake(" --size 8 4"), "--scene", "fake"}));
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.stderrText.find("b-1.exr: 8x4 pixels, while side A (the baseline) has 8x8"),
            std::string::npos)
      << o.stderrText;
}

TEST_F(RefereeCommand, ManifestRunsASuiteWithJunitAndZImagesPerEntry) {
  const std::string manifest = path("suite.json");
  std::ofstream(manifest) << nlohmann::json{
      {"entries",
       {{{"name", "same"}, {"a", fake()}, {"b", fake()}},
        {{"name", "biased"}, {"a", fake()}, {"b", fake(" --bias 0.2")}},
        {{"name", "noisy"},
         {"a", fake(" --noise 3")},
         {"b", fake(" --noise 3")},
         {"budget", {{"max_renders", 4}}}}}}};
  const std::string junit = path("out/junit.xml");
  const testing::Outcome o =
      verity(referee({"--manifest", manifest, "--junit", junit, "--z-image", path("z/z.png"),
                      "--json", path("suite-report.json")}));
  EXPECT_EQ(o.status, 1) << o.stderrText;  // DIFFER outranks INCONCLUSIVE
  const std::string xml = readText(junit);
  EXPECT_NE(xml.find("<testsuite name=\"verity referee\" tests=\"3\" failures=\"1\" errors=\"1\""),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testcase name=\"same\""), std::string::npos);
  EXPECT_NE(xml.find("<failure type=\"DIFFER\""), std::string::npos);
  EXPECT_NE(xml.find("<error type=\"INCONCLUSIVE\""), std::string::npos);
  for (const char* name : {"z-same.png", "z-biased.png", "z-noisy.png"})
    EXPECT_TRUE(std::filesystem::exists(dir_ / "z" / name)) << name;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(path("suite-report.json")));
  EXPECT_EQ(j["entries"].size(), 3u);
  EXPECT_EQ(j["entries"][2]["verdict"], "INCONCLUSIVE");
  EXPECT_TRUE(j["entries"][2].contains("claimable_margin"));
  EXPECT_FALSE(j["entries"][2]["undecided"].empty());
}

// Every refusal: exit status 2, one `verity: error:` naming the option, file or command, and
// no render started (the work folder stays empty).
TEST_F(RefereeCommand, BadInputIsRefusedBeforeAnyRender) {
  const std::string missing = path("missing.json");
  const std::string aFile = path("a-file");
  std::ofstream(aFile) << "not a folder";
  const std::string manifest = path("bad-manifest.json");
  std::ofstream(manifest) << R"({"entries": [{"name": "x", "a": "r {seed} {out}",
                                 "b": "r {seed} {out}", "budget": {"max_render": 9}}]})";
  struct Case {
    std::vector<std::string> args;
    std::string names;
  };
  const Case cases[] = {
      {{"--a", "r --out {out}", "--b", fake()}, "--a: \"r --out {out}\" has no {seed}"},
      {{"--a", fake(), "--b", "r --seed {seed}"}, "--b: "},
      {{"--a", fake()}, "--b: side B needs a render command"},
      {{"--b", fake()}, "--a: side A needs a render command or --baseline"},
      {{"--a", fake(), "--baseline", missing, "--b", fake()}, "--baseline: "},
      {{"--baseline", missing, "--b", fake()}, missing + ": cannot read the baseline"},
      {{"--a", fake(), "--b", fake(), "--spp", "4"}, "--spp: no render command has"},
      {{"--a", fake(" -n {spp}"), "--b", fake()}, "--a: "},
      {{"--a", fake(), "--b", fake(), "--z-image", path("z.jpg")}, "--z-image: "},
      {{"--a", fake(), "--b", fake(), "--json", aFile + "/r.json"}, "--json: cannot create"},
      {{"--a", fake(), "--b", fake(), "--junit", aFile + "/j.xml"}, "--junit: cannot create"},
      {{"--a", fake(), "--b", fake(), "--save-baseline", aFile + "/b.json"},
       "--save-baseline: cannot create"},
      {{"--baseline", dir_.string(), "--b", fake()}, dir_.string() + ": cannot read the baseline"},
      {{"--a", fake(), "--b", fake(), "--margin", "0"}, "--margin"},
      {{"--a", fake(), "--b", fake(), "--max-renders", "2", "--initial-renders", "4"},
       "--max-renders: 2 is below --initial-renders 4"},
      {{"--a", fake(), "--b", fake(), "--spending", "linear"}, "--spending: "},
      {{"--manifest", manifest}, "/entries/0/budget/max_render: unknown key"},
      {{"--manifest", manifest, "--a", fake()}, "--a: is given per entry"},
      {{"--manifest", missing}, missing + ": cannot read the manifest"},
  };
  for (const Case& c : cases) {
    const testing::Outcome o = verity(referee(c.args));
    EXPECT_EQ(o.status, 2) << c.names;
    EXPECT_NE(o.stderrText.find("verity: error: "), std::string::npos) << o.stderrText;
    EXPECT_NE(o.stderrText.find(c.names), std::string::npos) << c.names << "\n" << o.stderrText;
    EXPECT_TRUE(!std::filesystem::exists(dir_ / "work") || std::filesystem::is_empty(dir_ / "work"))
        << c.names;
  }
}

TEST_F(RefereeCommand, AFailingRenderNamesTheCommandAndShowsItsStderr) {
  const testing::Outcome o = verity(referee({"--a", fake(), "--b", fake(" --fail")}));
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.stderrText.find("the render command of side B"), std::string::npos) << o.stderrText;
  EXPECT_NE(o.stderrText.find("--fail"), std::string::npos) << o.stderrText;
  EXPECT_NE(o.stderrText.find("fake renderer: failing as asked"), std::string::npos)
      << o.stderrText;
}

// Verity's integrators against each other, rendered by `verity render` through command
// templates: unbiased estimators of one image are EQUIVALENT within 15% (16 pixels wide, 16
// spp, tiles of 8); cutting the paths to
// one bounce changes the image, and the referee says DIFFER. Tiny renders: seconds.
// The renders go to a fresh temporary folder that the referee removes.
class RefereeOnVerity : public ::testing::TestWithParam<const char*> {};

TEST_P(RefereeOnVerity, IntegratorsAreEquivalentAndCutPathsDiffer) {
  const std::string scene = std::string(VERITY_SCENES_DIR) + "/" + GetParam();
  const auto render = [&](const std::string& integrator, const std::string& extra = "") {
    return std::string(VERITY_BINARY) + " render " + scene +
           " --resolution 16 --spp 16 --threads 1 --integrator " + integrator + extra +
           " --seed {seed} -o {out}";
  };
  const std::vector<std::string> common = {"referee", "--tile",  "8",    "--margin",
                                           "0.15",    "--alpha", "0.05", "--max-renders",
                                           "64",      "--jobs",  "2"};
  std::vector<std::string> same = common;
  same.insert(same.end(), {"--a", render("path_tracer_nee"), "--b", render("bdpt")});
  const testing::Outcome equivalent = verity(same);
  EXPECT_EQ(equivalent.status, 0) << equivalent.stderrText;
  std::vector<std::string> cut = common;
  cut.insert(cut.end(), {"--a", render("path_tracer_nee"), "--b",
                         render("path_tracer_nee", " --max-bounces 1")});
  const testing::Outcome differ = verity(cut);
  EXPECT_EQ(differ.status, 1) << differ.stderrText;
}

INSTANTIATE_TEST_SUITE_P(Scenes, RefereeOnVerity,
                         ::testing::Values("cornell-box.json", "glossy-cornell-box.json"),
                         [](const auto& info) {
                           std::string n = info.param;
                           n = n.substr(0, n.find('.'));
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace verity

namespace verity {
namespace {

// `verity compare --margin` runs the referee's equivalence test on sets already rendered: exit
// status 0 EQUIVALENT, 1 DIFFER, 3 neither; the JSON says EQUIVALENT or "not shown".
class CompareMargin : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::freshTestDirectory("verity_compare_margin_"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // `count` renders of the fake renderer, seeds first, first + 2, ..., with pixels of sd 0.1
  // (the renderer's own 0.25 needed 32 renders a side to show 10% equivalence).
  std::vector<std::string> renders(const std::string& name, int count, uint64_t first,
                                   const std::string& extra = "") {
    std::vector<std::string> files;
    for (int i = 0; i < count; ++i) {
      files.push_back((dir_ / (name + std::to_string(i) + ".exr")).string());
      std::vector<std::string> args = {FAKE_RENDERER, "--seed",     std::to_string(first + 2 * i),
                                       "--out",       files.back(), "--noise",
                                       "0.1"};
      std::istringstream words(extra);
      for (std::string w; words >> w;) args.push_back(w);
      EXPECT_EQ(testing::run(args).status, 0);
    }
    return files;
  }
  testing::Outcome compare(const std::vector<std::string>& a, const std::vector<std::string>& b,
                           std::vector<std::string> extra) {
    std::vector<std::string> args = {"compare", "--tile", "4", "--alpha", "0.05"};
    args.push_back("-a");
    args.insert(args.end(), a.begin(), a.end());
    args.push_back("-b");
    args.insert(args.end(), b.begin(), b.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return verity(args);
  }
  std::filesystem::path dir_;
};

TEST_F(CompareMargin, SaysEquivalentDifferOrNeither) {
  const auto a = renders("a", 8, 0), b = renders("b", 8, 1);
  const std::string json = (dir_ / "report.json").string();
  EXPECT_EQ(compare(a, b, {"--margin", "0.1", "-o", json}).status, 0);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  EXPECT_EQ(j["equivalence"]["verdict"], "EQUIVALENT");
  EXPECT_EQ(j["equivalence"]["tests"].size(), 12u);
  EXPECT_EQ(compare(a, renders("biased", 8, 1, "--bias 0.2"), {"--margin", "0.1"}).status, 1);
  const auto few = std::vector<std::string>(a.begin(), a.begin() + 3);
  const testing::Outcome neither =
      compare(few, std::vector<std::string>(b.begin(), b.begin() + 3), {"--margin", "0.01"});
  EXPECT_EQ(neither.status, 3);
  // Without --margin, compare's statuses are unchanged: 0 agree.
  EXPECT_EQ(compare(few, std::vector<std::string>(b.begin(), b.begin() + 3), {}).status, 0);
  const testing::Outcome refused =
      verity({"compare", a[0], a[1], "--margin", "0.05", "--alpha", "0.6"});
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.stderrText.find("--alpha: with --margin"), std::string::npos)
      << refused.stderrText;
}

}  // namespace
}  // namespace verity

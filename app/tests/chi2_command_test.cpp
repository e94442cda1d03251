// `verity chi2` tests a material with the index of refraction the material itself states: a
// rough dielectric passes from outside, from inside and with an index below 1, and no second
// copy of the index can be given on the command line (a default of 1 beside the material's
// 1.5 failed every reciprocity check by 1.5²).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

testing::Outcome chi2(const std::string& material, std::vector<std::string> extra) {
  std::vector<std::string> args = {VERITY_BINARY, "chi2",      "--material",
                                   material,      "--samples", "200000"};
  args.insert(args.end(), extra.begin(), extra.end());
  return testing::run(args);
}

// The command's exit status, stdout and stderr.
struct Printed {
  int status;
  std::string stdoutText, stderrText;
};
Printed printed(const std::vector<std::string>& args) {
  const std::filesystem::path out = testing::freshTestDirectory("verity-chi2-") / "stdout.txt";
  std::string command = "'" VERITY_BINARY "' chi2";
  for (const std::string& a : args) command += " '" + a + "'";
  const testing::Outcome r = testing::run({"/bin/sh", "-c", command + " > '" + out.string() + "'"});
  std::ifstream in(out);
  return {r.status, std::string(std::istreambuf_iterator<char>(in), {}), r.stderrText};
}

std::string roughDielectric(double ior) {
  return fmt::format(R"({{"type":"rough_dielectric","distribution":"beckmann","alpha":0.4,)"
                     R"("ior":{}}})",
                     ior);
}

TEST(Chi2Command, RoughDielectricsPassWithTheirOwnIndex) {
  for (const double ior : {1.5, 0.6667})
    for (const bool inside : {false, true}) {
      std::vector<std::string> extra = {"--incoming", "45"};
      if (inside) extra.push_back("--inside");
      const testing::Outcome r = chi2(roughDielectric(ior), extra);
      EXPECT_EQ(r.status, 0) << "ior " << ior << (inside ? " inside" : " outside") << "\n"
                             << r.stderrText;
    }
}

TEST(Chi2Command, TheIndexIsNotASecondOption) {
  const testing::Outcome r = chi2(roughDielectric(1.5), {"--incoming", "45", "--ior", "1.5"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.stderrText.find("--ior"), std::string::npos) << r.stderrText;
}

// -o PREFIX writes the figure PREFIX.png and its data PREFIX.json.
TEST(Chi2Command, OutputWritesTheFigureAndItsData) {
  const std::filesystem::path prefix = testing::freshTestDirectory("verity-chi2-") / "ggx";
  const testing::Outcome r =
      chi2(R"({"type":"ggx","alpha":0.1})", {"--incoming", "45", "-o", prefix.string()});
  EXPECT_EQ(r.status, 0) << r.stderrText;
  std::ifstream png(prefix.string() + ".png", std::ios::binary);
  char magic[8] = {};
  png.read(magic, 8);
  EXPECT_EQ(std::string(magic, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_TRUE(std::filesystem::exists(prefix.string() + ".json"));
}

// --cells equal histograms in cells of equal probability, and the figure's data say so.
TEST(Chi2Command, EqualCellsAreTheCellsOfTheFigure) {
  const std::filesystem::path prefix = testing::freshTestDirectory("verity-chi2-") / "ggx";
  const testing::Outcome r = chi2(R"({"type":"ggx","alpha":0.1})",
                                  {"--incoming", "45", "--cells", "equal", "-o", prefix.string()});
  EXPECT_EQ(r.status, 0) << r.stderrText;
  std::ifstream data(prefix.string() + ".json");
  const std::string json((std::istreambuf_iterator<char>(data)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find(R"("uniform":false)"), std::string::npos);
  EXPECT_NE(json.find("64x32 equal-probability cells"), std::string::npos);
}

// A prefix whose folder cannot be made (a file stands in its way) is refused before the test.
TEST(Chi2Command, AnUnwritableOutputIsAnError) {
  const std::filesystem::path dir = testing::freshTestDirectory("verity-chi2-");
  std::ofstream(dir / "file") << "not a folder";
  const testing::Outcome r =
      chi2(R"({"type":"lambertian","albedo":0.5})", {"-o", (dir / "file" / "figure").string()});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.stderrText.find("-o: cannot create the folder \"" + (dir / "file").string()),
            std::string::npos)
      << r.stderrText;
  EXPECT_EQ(r.stderrText.find("PASSED"), std::string::npos) << r.stderrText;
}

// Every verdict states what it could have caught.
TEST(Chi2Command, APassStatesWhatItCouldHaveCaught) {
  const Printed r = printed({"--material", R"({"type":"lambertian"})", "--samples", "200000"});
  EXPECT_EQ(r.status, 0) << r.stderrText;
  EXPECT_NE(r.stdoutText.find("PASSED in"), std::string::npos) << r.stdoutText;
  EXPECT_NE(r.stdoutText.find("density error over cells holding 1/4 of the mass"),
            std::string::npos)
      << r.stdoutText;
  EXPECT_NE(r.stdoutText.find("would have been found with 90% probability"), std::string::npos)
      << r.stdoutText;
}

// A failure of the statistical tests alone says that a correct material fails so at the level's
// rate. At --alpha 0.999 a correct Lambertian fails one of its two tests with probability 0.999
// (any seed but one in a thousand; --power must then exceed the per-test level of 0.968), and
// its samples agree with eval and pdf one by one.
TEST(Chi2Command, AStatisticalFailureSaysHowOftenACorrectMaterialFails) {
  const std::string hint = "only the statistical tests failed, which a correct material does";
  const Printed failed = printed({"--material", R"({"type":"lambertian"})", "--samples", "200000",
                                  "--alpha", "0.999", "--power", "0.99"});
  EXPECT_EQ(failed.status, 1) << failed.stdoutText << failed.stderrText;
  EXPECT_NE(failed.stdoutText.find(hint + " with probability 0.999 (--alpha)"), std::string::npos)
      << failed.stdoutText;
  const Printed passed = printed({"--material", R"({"type":"lambertian"})", "--samples", "200000"});
  EXPECT_EQ(passed.status, 0) << passed.stderrText;
  EXPECT_EQ(passed.stdoutText.find(hint), std::string::npos) << passed.stdoutText;
}

// --threads, as the rendering commands have it (cli/threads_option.h): one thread runs the
// check to its verdict, and a negative count is refused by name.
TEST(Chi2Command, ThreadsAreTheRenderCommandsOption) {
  const Printed one =
      printed({"--material", R"({"type":"lambertian"})", "--samples", "200000", "--threads", "1"});
  EXPECT_EQ(one.status, 0) << one.stderrText;
  EXPECT_NE(one.stdoutText.find("PASSED in"), std::string::npos) << one.stdoutText;
  const Printed negative = printed({"--material", R"({"type":"lambertian"})", "--threads", "-1"});
  EXPECT_EQ(negative.status, 2) << negative.stderrText;
  EXPECT_NE(negative.stderrText.find("--threads: must be a whole number of at least 0, not -1"),
            std::string::npos)
      << negative.stderrText;
}

// The report and the figure's data are the same on 1, 2 and 3 threads but for the seconds (the
// samples come from streams fixed per block, the cells and integrals per cell): a rough
// dielectric on equal cells, whose refraction and reciprocity checks run on every sample.
TEST(Chi2Command, OneTwoAndThreeThreadsGiveTheSameReportAndData) {
  const std::filesystem::path dir = testing::freshTestDirectory("verity-chi2-");
  auto run = [&](const std::string& threads) {
    const std::string prefix = (dir / ("t" + threads)).string();
    const Printed r =
        printed({"--material", R"({"type":"rough_dielectric","alpha":0.3})", "--incoming", "45",
                 "--samples", "300000", "--threads", threads, "-o", prefix});
    EXPECT_EQ(r.status, 0) << r.stderrText;
    std::ifstream in(prefix + ".json");
    const std::string data((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(data.find(R"("phases")"), std::string::npos);
    const std::string report =
        std::regex_replace(r.stdoutText, std::regex(R"(in [0-9.]+ s|wrote .*\n)"), "");
    return report +
           std::regex_replace(data, std::regex(R"("phases":\{[^}]*\},?|"seconds":[^,}]*,?)"), "");
  };
  const std::string one = run("1");
  EXPECT_NE(one.find("PASSED"), std::string::npos) << one.substr(0, 2000);
  for (const std::string threads : {"2", "3"})
    EXPECT_EQ(run(threads), one) << threads << " threads";
}

// --detect chooses the sample count; a target beyond --max-samples is INCONCLUSIVE (status 3).
TEST(Chi2Command, DetectChoosesTheSamplesAndABudgetTooSmallIsInconclusive) {
  const std::vector<std::string> lambertian = {"--material", R"({"type":"lambertian"})", "--detect",
                                               "0.05"};
  const Printed chosen = printed(lambertian);
  EXPECT_EQ(chosen.status, 0) << chosen.stderrText;
  EXPECT_NE(chosen.stdoutText.find("chosen to find a 5% density error"), std::string::npos)
      << chosen.stdoutText;
  std::vector<std::string> small = lambertian;
  small.insert(small.end(), {"--max-samples", "1000"});
  const Printed budget = printed(small);
  EXPECT_EQ(budget.status, 3) << budget.stdoutText << budget.stderrText;
  EXPECT_NE(budget.stdoutText.find("more than the budget of 1000"), std::string::npos)
      << budget.stdoutText;
  EXPECT_EQ(budget.stdoutText.find("PASSED"), std::string::npos) << budget.stdoutText;
}

// Smooth glass and a mirror have only delta lobes: the command checks them on draws of their
// own (directions for the material's own index, shares and albedos) rather than ending
// INCONCLUSIVE with nothing checked.
TEST(Chi2Command, DeltaLobesAreChecked) {
  for (const char* material :
       {R"({"type":"dielectric","ior":1.5})", R"({"type":"metal","roughness":0})"}) {
    const Printed r = printed({"--material", material, "--incoming", "30", "--samples", "100000"});
    EXPECT_EQ(r.status, 0) << material << "\n" << r.stdoutText << r.stderrText;
    EXPECT_NE(r.stdoutText.find("PASSED with the delta lobes"), std::string::npos) << r.stdoutText;
  }
  const Printed glass =
      printed({"--material", R"({"type":"dielectric","ior":1.5})", "--samples", "100000"});
  EXPECT_NE(glass.stdoutText.find("refraction for eta 1.5"), std::string::npos) << glass.stdoutText;
}

// An inconclusive run shows no statistic of a test that did not run.
TEST(Chi2Command, AnInconclusiveRunPrintsNoStatisticOfATestThatDidNotRun) {
  const Printed r = printed({"--material", R"({"type":"lambertian"})", "--samples", "8"});
  EXPECT_EQ(r.status, 3) << r.stdoutText << r.stderrText;
  EXPECT_NE(r.stdoutText.find("chi-square: not run"), std::string::npos) << r.stdoutText;
  EXPECT_EQ(r.stdoutText.find("p-value"), std::string::npos) << r.stdoutText;
}

}  // namespace
}  // namespace verity

namespace verity {
namespace {

TEST(Chi2Command, SweepChecksTheMaterialAsAFamilyAndWritesItsReports) {
  // A rough dielectric over its roughness (log) and index, from above and below at one
  // incidence: 4 corners and 1 interior point, 10 configurations of 10⁵ samples.
  const std::filesystem::path dir = testing::freshTestDirectory("verity-chi2-sweep-");
  const std::string prefix = (dir / "family" / "glass").string();
  const Printed p =
      printed({"--material", R"({"type":"rough_dielectric"})", "--sweep", "alpha=0.05:1:log",
               "--sweep", "ior=1.2:2", "--incidences", "45", "--from-below", "--interior-points",
               "1", "--samples", "100000", "-o", prefix});
  EXPECT_EQ(p.status, 0) << p.stdoutText << p.stderrText;
  EXPECT_NE(p.stdoutText.find("10 configurations, 20 statistical tests at a family-wise level "
                              "of 0.01"),
            std::string::npos)
      << p.stdoutText;
  EXPECT_NE(p.stdoutText.find("PASSED       alpha=0.05 ior=1.2 at 45° from below"),
            std::string::npos)
      << p.stdoutText;
  std::ifstream junit(prefix + ".xml");
  const std::string xml(std::istreambuf_iterator<char>(junit), {});
  EXPECT_NE(xml.find(R"(tests="10" failures="0" errors="0")"), std::string::npos) << xml;
  EXPECT_TRUE(std::filesystem::exists(prefix + ".md"));
  EXPECT_TRUE(std::filesystem::exists(prefix + ".json"));
}

TEST(Chi2Command, ASweepDrawsTheFigureOfEachConfigurationThatDidNotPass) {
  // 50 samples are too few for a chi-square test: both configurations are INCONCLUSIVE, exit
  // status 3, each an error in the JUnit file and a figure listed under the Markdown table.
  const std::filesystem::path dir = testing::freshTestDirectory("verity-chi2-sweep-figures-");
  const std::string prefix = (dir / "ggx").string();
  const Printed p =
      printed({"--material", R"({"type":"ggx"})", "--sweep", "alpha=0.1:0.2", "--incidences", "30",
               "--interior-points", "0", "--samples", "50", "-o", prefix});
  EXPECT_EQ(p.status, 3) << p.stdoutText << p.stderrText;
  for (const char* k : {"-0", "-1"}) {
    EXPECT_TRUE(std::filesystem::exists(prefix + k + ".png")) << k;
    EXPECT_NE(p.stdoutText.find(prefix + k + ".png"), std::string::npos) << p.stdoutText;
  }
  std::ifstream junit(prefix + ".xml"), markdown(prefix + ".md");
  const std::string xml(std::istreambuf_iterator<char>(junit), {});
  EXPECT_NE(xml.find(R"(tests="2" failures="0" errors="2")"), std::string::npos) << xml;
  const std::string md(std::istreambuf_iterator<char>(markdown), {});
  EXPECT_NE(md.find("- alpha=0.2 at 30° from above: " + prefix + "-1.png"), std::string::npos)
      << md;
}

TEST(Chi2Command, ASweepChecksAFloatMaterialAtTheDirectionItSees) {
  // GGX α 4 at η 1.01 from 30°: its refraction ends in a jump (D > 0 at the horizon) on a cone
  // that the check computes from wi. Given wi in double, the material saw it rounded to float
  // and ended its lobe 3·10⁻⁸ further, and with 2·10⁶ samples one landed beyond the check's edge,
  // in a cell expecting 3·10⁻¹¹: FAILED outright. The family's wi is float, unit there. That
  // float wi is up to 3·10⁻⁸ from unit length in double, where the material renormalises it:
  // with the cone declared from the raw wi, 85° from above and 30° from below each had samples
  // in a sliver 2·10⁻⁹ wide beyond the check's edge and FAILED; the check now declares its cones
  // from the renormalised wi. At the per-test level of the 96-configuration family that found
  // them (5.2·10⁻⁵ per test: 4.2·10⁻⁴ over these eight tests).
  const Printed p = printed({"--material", R"({"type":"rough_dielectric"})", "--sweep", "alpha=4:4",
                             "--sweep", "ior=1.01:1.01", "--incidences", "30,85", "--from-below",
                             "--interior-points", "0", "--alpha", "0.000418"});
  EXPECT_EQ(p.status, 0) << p.stdoutText << p.stderrText;
}

TEST(Chi2Command, ASweepOutsideWhatTheLoaderAcceptsIsBadInput) {
  // α's accepted range starts at 10⁻⁴: refused before any check, naming the key.
  const Printed below = printed({"--material", R"({"type":"ggx"})", "--sweep", "alpha=1e-5:1:log"});
  EXPECT_EQ(below.status, 2);
  EXPECT_NE(below.stderrText.find("--sweep: alpha:"), std::string::npos) << below.stderrText;
  EXPECT_NE(below.stderrText.find("expected a number in [0.0001, 4]"), std::string::npos)
      << below.stderrText;
  const Printed malformed = printed({"--material", R"({"type":"ggx"})", "--sweep", "alpha"});
  EXPECT_EQ(malformed.status, 2);
  EXPECT_NE(malformed.stderrText.find("expected KEY=LO:HI"), std::string::npos)
      << malformed.stderrText;
  const Printed single =
      printed({"--material", R"({"type":"ggx"})", "--sweep", "alpha=0.1:1", "--incoming", "30"});
  EXPECT_EQ(single.status, 2);
}

}  // namespace
}  // namespace verity

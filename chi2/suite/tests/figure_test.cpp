// The figure's data file: the histogram as rows of constant y, the domain's axes and bin
// edges, and every verdict with the chi-square p-value, as plot_chi2.py reads them.
#include "chi2/suite/figure.h"

#include <gtest/gtest.h>
#include <verity/chi2/figure_data.h>
#include <verity/chi2/partition.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "scratch_folder.h"

namespace verity::chi2 {

namespace {

nlohmann::json figureData(const TestResult& r) {
  return nlohmann::json::parse(figureJson(r));
}

Domain threeByTwo() {
  Domain d = squareDomain(2);
  d.nx = 3;
  return d;
}

// A 3 × 2 square histogram whose chi-square test fails: 60/40 against 50/50 in one row.
TestResult smallResult(const Domain& domain) {
  TestResult r;
  r.subject = "a made-up subject";
  r.domain = domain;
  r.significance = 0.01;
  r.samples = r.valid = 300;
  r.observed = {60, 40, 50, 50, 50, 50};
  r.expected = {50, 50, 50, 50, 50, 50};
  r.chiSquare = chiSquareTest(r.expected, r.observed, 1e-12);
  r.integral = checkIntegral(1.0, r.samples, r.valid, r.significance);
  return r;
}

}  // namespace

TEST(FrameworkFigure, DataHoldsTheHistogramByRowsAndTheVerdicts) {
  const Domain d = threeByTwo();
  const nlohmann::json j = figureData(smallResult(d));
  EXPECT_EQ(j["domain"]["kind"], "square");
  EXPECT_EQ(j["domain"]["x_label"], "x");
  EXPECT_EQ(j["domain"]["x_edges"].size(), 4u);
  EXPECT_DOUBLE_EQ(j["domain"]["x_edges"][1].get<double>(), 1.0 / 3);
  // One list of y edges per strip, the same three on the grid.
  EXPECT_EQ(j["domain"]["y_edges"],
            nlohmann::json({{0.0, 0.5, 1.0}, {0.0, 0.5, 1.0}, {0.0, 0.5, 1.0}}));
  EXPECT_EQ(j["domain"]["uniform"], true);
  // Row j holds the cells of constant y, from y0 up (numpy's (ny, nx) layout).
  EXPECT_EQ(j["observed"], nlohmann::json({{60, 40, 50}, {50, 50, 50}}));
  EXPECT_EQ(j["expected"][1][2], 50.0);
  // X² = 4 on 5 dof: p = 0.5494, which passes; a level above it fails.
  EXPECT_NEAR(j["chi_square"]["p_value"].get<double>(), 0.5494, 1e-4);
  EXPECT_EQ(j["chi_square"]["passed"], true);
  EXPECT_EQ(j["integral"]["passed"], true);
  EXPECT_EQ(j["audit"]["passed"], true);
  EXPECT_EQ(j["verdict"], "PASSED");
  EXPECT_EQ(j["inconclusive_reason"], "");
  TestResult strict = smallResult(d);
  strict.significance = 0.6;
  EXPECT_EQ(figureData(strict)["chi_square"]["passed"], false);
  EXPECT_EQ(figureData(strict)["verdict"], "FAILED");
}

TEST(FrameworkFigure, AxesAreNamedFromTheDomain) {
  const nlohmann::json sphere = figureData(smallResult(sphereDomain(1)))["domain"];
  EXPECT_EQ(sphere["x_label"], "φ (radians)");
  EXPECT_EQ(sphere["y_label"], "cos θ");
  EXPECT_DOUBLE_EQ(sphere["x_edges"].back().get<double>(), 2 * std::numbers::pi);
  EXPECT_EQ(sphere["y_edges"], nlohmann::json({{-1.0, 1.0}, {-1.0, 1.0}}));
  EXPECT_EQ(figureData(smallResult(diskDomain(1)))["domain"]["y_label"], "y");
  EXPECT_EQ(figureData(smallResult(triangleDomain(1)))["domain"]["kind"], "triangle");
}

TEST(FrameworkFigure, WritesTheDataFileAndAPng) {
  const suite::ScratchFolder folder("verity-figure-test");
  const std::filesystem::path& dir = folder.path();
  const TestResult r = smallResult(threeByTwo());
  const std::string png = writeFigure(r, (dir / "small").string());
  EXPECT_EQ(png, (dir / "small.png").string());
  std::ifstream data(dir / "small.json");
  EXPECT_EQ(nlohmann::json::parse(data), figureData(r));
  std::ifstream image(png, std::ios::binary);
  char magic[4] = {};
  image.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), "\x89PNG");
}

TEST(FrameworkFigure, EqualProbabilityCellsCarryEachStripsEdges) {
  // Cells of equal mass under x + 3y: each strip is cut at its own heights, which the data
  // carry and the figure draws.
  const Domain d =
      equalProbabilityCells(threeByTwo(), [](double x, double y) { return x + 3 * y; });
  ASSERT_FALSE(d.uniform());
  const TestResult r = smallResult(d);
  const nlohmann::json j = figureData(r)["domain"];
  EXPECT_EQ(j["uniform"], false);
  EXPECT_NE(j["name"].get<std::string>().find("equal-probability"), std::string::npos);
  for (int i = 0; i <= d.nx; ++i) EXPECT_EQ(j["x_edges"][i].get<double>(), d.xEdge(i));
  for (int i = 0; i < d.nx; ++i)
    for (int k = 0; k <= d.ny; ++k) EXPECT_EQ(j["y_edges"][i][k].get<double>(), d.yEdge(i, k));
  EXPECT_NE(d.yEdge(0, 1), d.yEdge(2, 1));  // the strips' cuts differ
  const suite::ScratchFolder folder("verity-figure-test");
  std::ifstream image(writeFigure(r, (folder.path() / "equal").string()), std::ios::binary);
  char magic[4] = {};
  image.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), "\x89PNG");
}

}  // namespace verity::chi2

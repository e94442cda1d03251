// Bidirectional path tracing and light tracing against the path tracer with next-event
// estimation in Cornell boxes: with a mirror and a smooth glass sphere (delta vertices on
// both subpaths, caustics, the glass ball's reflection), and with a rough conductor, a rough
// dielectric and an emitting background besides the area light. The expectations must
// agree over the whole image and over the regions that see each sphere directly; the light
// tracer, which cannot see through a delta surface from the camera, is compared on the
// pixels that see only non-delta surfaces.
//
// Each estimate is a mean over independent one-sample passes of a region's pixel sum (see
// bdpt_test_util.h); every comparison is a two-sided z-test, family-wise level 1% over all
// comparisons in this file with a Bonferroni correction.
#include <gtest/gtest.h>

#include "integrators/tests/bdpt_test_util.h"

namespace verity {
namespace {

using bdpt_test::cornellBox;
using bdpt_test::estimateRegions;
using bdpt_test::RegionEstimate;

// Regions: 0 pixels that see only non-delta surfaces (no sphere and no background within
// one pixel: the light tracer sees neither delta surfaces nor the background directly),
// 1 pixels entirely on sphere a, 2 entirely on sphere b, 3 the rest. Whole-image sums add
// them up.
enum Region { kOther = 0, kSphereA = 1, kSphereB = 2, kMixed = 3, kRegions = 4 };

std::vector<int> classify(const std::string& text) {
  SceneFile file = loadSceneText(text, "/tmp/bdpt-cornell.json");
  const Camera& camera = file.scene->camera();
  const Vector2i res = camera.resolution();
  const auto& shapes = file.scene->shapes();
  const Shape* sphereA = shapes[shapes.size() - 2].get();
  const Shape* sphereB = shapes.back().get();
  // What a 5×5 grid of points in each pixel sees: bit 0 other surfaces, bit 1 sphere a,
  // bit 2 sphere b, bit 3 the background.
  std::vector<int> seen(size_t(res.x()) * res.y(), 0);
  for (int y = 0; y < res.y(); ++y)
    for (int x = 0; x < res.x(); ++x)
      for (int j = 0; j <= 4; ++j)
        for (int i = 0; i <= 4; ++i) {
          SurfaceInteraction si;
          const Ray ray =
              camera.generateRay(Point2f(x + i / 4.0f, y + j / 4.0f), Point2f(0.5f, 0.5f));
          const bool hit = file.scene->intersect(ray, si);
          seen[size_t(y) * res.x() + x] |= !hit                  ? 8
                                           : si.shape == sphereA ? 2
                                           : si.shape == sphereB ? 4
                                                                 : 1;
        }
  std::vector<int> region(seen.size(), kMixed);
  for (int y = 0; y < res.y(); ++y)
    for (int x = 0; x < res.x(); ++x) {
      const int s = seen[size_t(y) * res.x() + x];
      if (s == 2) region[size_t(y) * res.x() + x] = kSphereA;
      if (s == 4) region[size_t(y) * res.x() + x] = kSphereB;
      // Only non-delta surfaces here and in the 8 neighbours (a sliver of a sphere between
      // the grid points cannot hide in the pixel).
      bool clear = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = std::clamp(x + dx, 0, res.x() - 1),
                    yy = std::clamp(y + dy, 0, res.y() - 1);
          clear &= seen[size_t(yy) * res.x() + xx] == 1;
        }
      if (clear) region[size_t(y) * res.x() + x] = kOther;
    }
  return region;
}

RegionEstimate total(const std::vector<RegionEstimate>& r) {
  // The regions of one pass are correlated; their sum's standard error is bounded by the
  // sum of their standard errors (the bound is exact for perfect correlation).
  RegionEstimate t;
  for (const auto& e : r) {
    t.mean += e.mean;
    t.standardError += e.standardError;
    t.invalidSamples = e.invalidSamples;
  }
  return t;
}

// Comparisons: 2 scenes × (bdpt: 4 regions + total; light tracer: 1 region) × 3 channels.
constexpr int kTests = 2 * 6 * 3;
constexpr int kMaxBounces = 6;

struct CornellCase {
  const char* name;
  std::string a, b, extra;
};

void PrintTo(const CornellCase& c, std::ostream* os) {
  *os << c.name;
}

class BdptCornell : public ::testing::TestWithParam<CornellCase> {};

TEST_P(BdptCornell, AgreesWithNextEventPathTracer) {
  const CornellCase& c = GetParam();
  const std::string text = cornellBox(c.a, c.b, c.extra);
  const std::vector<int> region = classify(text);
  ASSERT_GT(std::count(region.begin(), region.end(), kOther), 200);
  ASSERT_GT(std::count(region.begin(), region.end(), kSphereA), 15);
  ASSERT_GT(std::count(region.begin(), region.end(), kSphereB), 15);
  const auto regionOf = [&](int x, int y) { return region[size_t(y) * 32 + x]; };
  const double z = bdpt_test::bonferroniZ(0.01, kTests);

  const auto reference =
      estimateRegions(text, "path_tracer_nee", kMaxBounces, 400, 1000, kRegions, regionOf);
  const auto bdpt = estimateRegions(text, "bdpt", kMaxBounces, 200, 2000, kRegions, regionOf);
  const auto light =
      estimateRegions(text, "light_tracer", kMaxBounces, 300, 3000, kRegions, regionOf);
  const char* names[] = {"non-delta pixels", "sphere a", "sphere b", "mixed pixels"};
  for (int r = 0; r < kRegions; ++r)
    bdpt_test::expectSameMean(bdpt[r], reference[r], z, std::string("bdpt, ") + names[r]);
  bdpt_test::expectSameMean(total(bdpt), total(reference), z, "bdpt, whole image");
  bdpt_test::expectSameMean(light[kOther], reference[kOther], z, "light tracer, non-delta pixels");
  // Sphere b (glass, or the rough dielectric) must show what is behind and reflected in it:
  // the seed's BDPT lost the glass ball's reflection.
  EXPECT_GT(bdpt[kSphereB].mean.sum(), 0.5 * reference[kSphereB].mean.sum());
  EXPECT_EQ(reference[0].invalidSamples + bdpt[0].invalidSamples + light[0].invalidSamples, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, BdptCornell,
    ::testing::Values(
        CornellCase{"MirrorAndGlass", R"("type": "metal", "albedo": 1, "roughness": 0)",
                    R"("type": "dielectric", "ior": 1.5)", ""},
        CornellCase{"RoughConductorRoughGlassAndBackground",
                    R"("type": "ggx", "alpha": 0.2, "albedo": 0.9)",
                    R"("type": "rough_dielectric", "distribution": "ggx", "alpha": 0.2,
                        "ior": 1.5)",
                    R"("background": 0.4,)"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace verity

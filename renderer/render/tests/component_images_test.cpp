// The per-strategy and per-path-length images: the weighted strategy images and the
// path-length images add up to the rendered image (to float rounding: the image adds each
// sample's parts in float, the components in double), every pixel of every component has
// the image's sample count, and the components are bit-identical for any thread count.
#include <gtest/gtest.h>

#include "integrators/integrator_registry.h"
#include "integrators/tests/bdpt_test_util.h"

namespace verity {
namespace {

const std::string kDiffuseBox = bdpt_test::diffuseCornellBox();

struct Rendered {
  Film film;
  std::unique_ptr<ComponentImages> components;
};

Rendered renderWith(const std::string& integrator, ComponentLayout::Kind kind, int maxBounces,
                    int threads, int spp) {
  SceneFile file = loadSceneText(kDiffuseBox, "/tmp/component-images.json");
  IntegratorSettings settings = file.integrator;
  settings.type = findIntegratorType(integrator);
  settings.maxBounces = maxBounces;
  const Vector2i res = file.scene->camera().resolution();
  Rendered out{Film(res),
               std::make_unique<ComponentImages>(ComponentLayout(kind, maxBounces), res)};
  RenderOptions options;
  options.samplesPerPixel = spp;
  options.threads = threads;
  options.components = out.components.get();
  file.sampler->setSeed(7);
  render(*file.scene, *makeIntegrator(settings), *file.sampler, out.film, options);
  return out;
}

// Σ of the images the layout adds up (the weighted ones) equals the image in every pixel.
void expectComponentsAddUp(const Rendered& r) {
  const ComponentLayout& layout = r.components->layout();
  double total = 0;
  for (int y = 0; y < r.film.height(); ++y)
    for (int x = 0; x < r.film.width(); ++x) {
      Eigen::Array3d sum = Eigen::Array3d::Zero();
      for (int i = 0; i < layout.size(); ++i) {
        ASSERT_EQ(r.components->film(i).count(x, y), r.film.count(x, y));
        if (layout[i].weighted) sum += r.components->film(i).mean(x, y).cast<double>();
      }
      const Eigen::Array3d image = r.film.mean(x, y).cast<double>();
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(sum[c], image[c], 1e-5 * image[c] + 1e-9) << "pixel " << x << ", " << y;
      total += image.sum();
    }
  EXPECT_GT(total, 0);
}

TEST(ComponentImages, WeightedStrategiesAddUpToTheBdptImage) {
  expectComponentsAddUp(renderWith("bdpt", ComponentLayout::Kind::Strategies, 4, 0, 4));
}

TEST(ComponentImages, PathLengthsAddUpToTheImage) {
  for (const IntegratorType& type : integratorTypes()) {
    if (!type.readsMaxBounces) continue;
    const std::string& integrator = type.name;
    SCOPED_TRACE(integrator);
    expectComponentsAddUp(renderWith(integrator, ComponentLayout::Kind::PathLengths, 5, 0, 4));
  }
}

TEST(ComponentImages, BitIdenticalForAnyThreadCount) {
  const Rendered one = renderWith("bdpt", ComponentLayout::Kind::Strategies, 3, 1, 2);
  const Rendered three = renderWith("bdpt", ComponentLayout::Kind::Strategies, 3, 3, 2);
  const ComponentLayout& layout = one.components->layout();
  for (int i = 0; i < layout.size(); ++i)
    for (int y = 0; y < one.film.height(); ++y)
      for (int x = 0; x < one.film.width(); ++x) {
        ASSERT_TRUE(
            (one.components->film(i).mean(x, y) == three.components->film(i).mean(x, y)).all())
            << layout.name(i);
        ASSERT_TRUE((one.components->film(i).sampleVariance(x, y) ==
                     three.components->film(i).sampleVariance(x, y))
                        .all())
            << layout.name(i);
      }
}

TEST(ComponentLayout, EveryStrategyUpToMaxBouncesTwice) {
  for (int maxBounces : {0, 1, 7, 12}) {
    const ComponentLayout layout(ComponentLayout::Kind::Strategies, maxBounces);
    // k + 2 strategies (s = 0 … k + 1) of each length k, weighted and unweighted.
    EXPECT_EQ(layout.size(), (maxBounces + 1) * (maxBounces + 4));
    EXPECT_EQ(ComponentLayout::sizeFor(ComponentLayout::Kind::Strategies, maxBounces),
              uint64_t(layout.size()));
    for (int i = 0; i < layout.size(); ++i) {
      const auto& c = layout[i];
      EXPECT_EQ(c.s + c.t - 2, c.bounces);
      EXPECT_EQ(layout.strategyIndex(c.s, c.t, c.weighted), i) << layout.name(i);
    }
    EXPECT_EQ(layout.strategyIndex(0, maxBounces + 3, true), -1);
    EXPECT_EQ(layout.pathLengthIndex(0), -1);
  }
  const ComponentLayout lengths(ComponentLayout::Kind::PathLengths, 9);
  EXPECT_EQ(lengths.size(), 10);
  EXPECT_EQ(lengths.name(9), "k9");
  EXPECT_EQ(lengths.pathLengthIndex(10), -1);
  EXPECT_EQ(ComponentLayout(ComponentLayout::Kind::Strategies, 2).name(3), "s1_t1_unweighted");
}

}  // namespace
}  // namespace verity

// Lookups at any finite or infinite coordinate stay defined: a checkerboard's parity and an
// image's wrapping must not go through integer conversions that overflow.
#include <gtest/gtest.h>

#include "textures/checker.h"
#include "textures/image_texture.h"

namespace verity {
namespace {

TextureQuery at(const Point3f& p, const Point2f& uv = Point2f::Zero()) {
  return {uv, p};
}

TEST(CheckerTexture, AlternatesAcrossCellsOnBothSidesOfZero) {
  const Color3 black = Color3::Zero(), white = Color3::Ones();
  const CheckerTexture checker(TexturedColor(black), TexturedColor(white), 2.0f);  // cells of 0.5
  EXPECT_EQ(checker.eval(at(Point3f(0.1f, 0.1f, 0.1f))).x(), 0.0f);
  EXPECT_EQ(checker.eval(at(Point3f(0.6f, 0.1f, 0.1f))).x(), 1.0f);
  EXPECT_EQ(checker.eval(at(Point3f(-0.1f, 0.1f, 0.1f))).x(), 1.0f);
  EXPECT_EQ(checker.eval(at(Point3f(-0.6f, 0.1f, 0.1f))).x(), 0.0f);
  EXPECT_EQ(checker.eval(at(Point3f(0.6f, 0.6f, -0.1f))).x(), 1.0f);
}

TEST(CheckerTexture, CoordinatesBeyondIntegersGiveOneOfItsColours) {
  const Color3 black = Color3::Zero(), white = Color3::Ones();
  const CheckerTexture checker(TexturedColor(black), TexturedColor(white), 3e38f);
  for (const Point3f& p : {Point3f(1e15f, -1e15f, 3.0f), Point3f(kInfinity, 0, 0)}) {
    const Color3 c = checker.eval(at(p));
    EXPECT_TRUE((c == black).all() || (c == white).all()) << c.transpose();
  }
}

// A solid texture's transform places its frame in the world: the pattern moves with it.
TEST(CheckerTexture, ATransformMovesThePattern) {
  const Color3 black = Color3::Zero(), white = Color3::Ones();
  Matrix4f toWorld = Matrix4f::Identity();
  toWorld.topLeftCorner<3, 3>() << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // 90° about z
  toWorld.topRightCorner<3, 1>() = Vector3f(10.5f, 0, 0);
  const CheckerTexture plain(TexturedColor(black), TexturedColor(white), 2.0f);
  const CheckerTexture moved(TexturedColor(black), TexturedColor(white), 2.0f,
                             SolidMapping(Transform(toWorld)));
  for (const Point3f& p :
       {Point3f(0.1f, 0.2f, 0.3f), Point3f(0.6f, -0.7f, 0.1f), Point3f(-1.3f, 0.35f, 2.2f)}) {
    const Point3f world = toWorld.topLeftCorner<3, 3>() * p + toWorld.topRightCorner<3, 1>();
    EXPECT_EQ(moved.eval(at(world)).x(), plain.eval(at(p)).x()) << p.transpose();
  }
  // Half a cell along x in the world is a move along y of the texture's frame.
  EXPECT_NE(moved.eval(at(Point3f(10.6f, 0.1f, 0.1f))).x(),
            moved.eval(at(Point3f(10.6f, 0.6f, 0.1f))).x());
}

TEST(ImageTexture, RepeatsForAnyFiniteUvAndStaysFiniteOtherwise) {
  const ImageTexture image(VERITY_SOURCE_DIR "/scenes/textures/tiles.png", "filename");
  const Point2f uv(0.3f, 0.7f);
  const Color3 inside = image.eval(at(Point3f::Zero(), uv));
  EXPECT_TRUE(inside.isApprox(image.eval(at(Point3f::Zero(), uv + Point2f(2, -3))), 1e-4f));
  for (const Point2f& far :
       {Point2f(3e38f, -3e38f), Point2f(kInfinity, 0.5f), Point2f(std::nanf(""), 0.5f)}) {
    const Color3 c = image.eval(at(Point3f::Zero(), far));
    EXPECT_TRUE(c.allFinite()) << far.transpose();
    EXPECT_TRUE((c.array() >= 0).all() && (c.array() <= 1).all()) << c.transpose();
  }
}

}  // namespace
}  // namespace verity

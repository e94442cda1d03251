// Rays that leave a surface never find that surface again, and never pass a blocker lying just
// in front of it: the ray offsets measured against Embree's own intersection arithmetic, family
// by family. Each family places one primitive (quad, triangle or sphere) at random
// scales from 1e-4 to 1e5, either in a plane through the origin on one axis (exact zeros in
// one coordinate: the case that made next-event estimation 21% dark) or under a random
// rotation and translation, and leaves it with head-on and grazing rays on both sides, rays
// from area samples (emission), and shadow rays towards near and far lights. A parallel
// copy of the primitive a thousandth of its size away (or further, where the coordinates are
// so large that floats cannot resolve that gap) must block every shadow ray that crosses it.
// Every family traces at least 10^7 rays; none may hit its own surface.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <pcg_random.hpp>
#include <random>

#include "loader/scene_loader.h"
#include "sampling/warp.h"

namespace verity {
namespace {

constexpr long kRaysPerFamily = 10'000'000;
constexpr int kPlacements = 250;
// What floats resolve at a coordinate's magnitude, with room to spare: 2^10 units in the last
// place, so that a light or a blocker this close is really on its side of the surface.
constexpr double kResolvable = 0x1p-14;

enum class Kind { Quad, Triangle, Sphere };
constexpr int kRandomRotation = -1;

struct Family {
  const char* name;
  Kind kind;
  int axis;  // the plane through the origin the primitive lies in (its normal axis), or random
};

const Family kFamilies[] = {{"quad_plane_x", Kind::Quad, 0},
                            {"quad_plane_y", Kind::Quad, 1},
                            {"quad_plane_z", Kind::Quad, 2},
                            {"triangle_plane_x", Kind::Triangle, 0},
                            {"triangle_plane_y", Kind::Triangle, 1},
                            {"triangle_plane_z", Kind::Triangle, 2},
                            {"quad_rotated", Kind::Quad, kRandomRotation},
                            {"triangle_rotated", Kind::Triangle, kRandomRotation},
                            {"sphere_rotated", Kind::Sphere, kRandomRotation}};

// The local primitive: a 2×2 quad or a triangle in z = 0 (normal +z), or a unit sphere.
const Eigen::Vector3d kTriangle[3] = {{-1, -1, 0}, {1, -1, 0}, {-0.2, 1, 0}};

std::string matrixJson(const Eigen::Matrix4d& m) {
  std::string s;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) s += fmt::format("{}{:.17g}", s.empty() ? "" : ", ", m(r, c));
  return "{\"matrix\": [" + s + "]}";
}

std::string surfaceJson(Kind kind, const Eigen::Matrix4d& toWorld) {
  const std::string transform = matrixJson(toWorld);
  const char* material = R"("material": {"type": "lambertian"})";
  if (kind == Kind::Quad)
    return fmt::format(R"({{"type": "quad", "size": 2, {}, "transform": {}}})", material,
                       transform);
  if (kind == Kind::Sphere)
    return fmt::format(R"({{"type": "sphere", "radius": 1, {}, "transform": {}}})", material,
                       transform);
  std::string positions;
  for (const Eigen::Vector3d& v : kTriangle)
    positions += fmt::format("{}[{}, {}, {}]", positions.empty() ? "" : ", ", v.x(), v.y(), v.z());
  return fmt::format(R"({{"type": "triangle", "positions": [{}], {}, "transform": {}}})", positions,
                     material, transform);
}

SceneFile sceneOf(const std::vector<std::string>& surfaces) {
  std::string list;
  for (const std::string& s : surfaces) list += (list.empty() ? "" : ", ") + s;
  return loadSceneText(R"({"camera": {"transform": {"from": [0, 0, 1], "at": [0, 0, 0]}},
                           "surfaces": [)" +
                           list + "]}",
                       "/tmp/ray-offset-family.json");
}

struct Placement {
  Eigen::Matrix4d toWorld = Eigen::Matrix4d::Identity();
  double scale = 1;
  double resolvable = 0;  // the smallest distance floats resolve in the world, kResolvable·|p|
  double gap = 0;         // the blocker's distance, in units of the size
};

// Local z goes to `axis` by a cyclic permutation (exact zeros stay zeros), after a rotation
// about local z; or a random rotation. Then a translation of 0.1 to 1000 sizes, within the
// plane for the axis families.
Placement randomPlacement(const Family& family, pcg32& rng) {
  std::uniform_real_distribution<double> uniform(0, 1);
  Placement out;
  out.scale = std::pow(10.0, -4 + 9 * uniform(rng));
  Eigen::Matrix3d rotation;
  if (family.axis == kRandomRotation) {
    rotation = Eigen::Quaterniond(Eigen::Vector4d::NullaryExpr([&] {
                                    return std::normal_distribution<double>()(rng);
                                  }).normalized())
                   .toRotationMatrix();
  } else {
    Eigen::Matrix3d permutation = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i) permutation((family.axis + 1 + i) % 3, i) = 1;
    // Row `axis` of the product is (0, 0, 1) exactly, whatever the angle's cosine and sine.
    rotation = permutation * Eigen::AngleAxisd(2 * kPi * uniform(rng), Eigen::Vector3d::UnitZ());
  }
  Eigen::Vector3d translation =
      Eigen::Vector3d::NullaryExpr([&] { return std::normal_distribution<double>()(rng); });
  if (family.axis != kRandomRotation) translation[family.axis] = 0;
  translation *= std::pow(10.0, -1 + 4 * uniform(rng)) * out.scale / translation.norm();
  out.toWorld.topLeftCorner<3, 3>() = out.scale * rotation;
  out.toWorld.topRightCorner<3, 1>() = translation;
  out.resolvable = kResolvable * (translation.cwiseAbs().maxCoeff() + 2 * out.scale);
  out.gap = std::max(1e-3, out.resolvable / out.scale);
  return out;
}

// The blocker: the primitive moved by the gap along its normal (a sphere: the concentric
// sphere that much larger).
Eigen::Matrix4d blockerOf(Kind kind, const Placement& placement) {
  Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
  if (kind == Kind::Sphere)
    local.topLeftCorner<3, 3>() *= 1 + placement.gap;
  else
    local(2, 3) = placement.gap;
  return placement.toWorld * local;
}

// A point on the local primitive at least `margin` inside its edges, and its local normal.
Eigen::Vector3d localPoint(Kind kind, pcg32& rng, double margin) {
  std::uniform_real_distribution<double> uniform(0, 1);
  if (kind == Kind::Sphere)
    return warp::squareToUniformSphere(Point2f(uniform(rng), uniform(rng))).cast<double>();
  if (kind == Kind::Quad)
    return {(1 - margin) * (2 * uniform(rng) - 1), (1 - margin) * (2 * uniform(rng) - 1), 0};
  // Barycentrics at least `margin` from every edge.
  double b1 = uniform(rng), b2 = uniform(rng);
  if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
  const double b0 = 1 - b1 - b2;
  const double m = margin, s = 1 - 3 * m;
  return (m + s * b0) * kTriangle[0] + (m + s * b1) * kTriangle[1] + (m + s * b2) * kTriangle[2];
}

// A direction on the side of `n` at an elevation angle (from the tangent plane) drawn
// log-uniformly between `lowest` and 1 radian.
Vector3f grazing(const Normal3f& n, pcg32& rng, double lowest = 1e-4) {
  std::uniform_real_distribution<double> uniform(0, 1);
  const double elevation = std::pow(10.0, std::log10(lowest) * (1 - uniform(rng)));
  const double phi = 2 * kPi * uniform(rng);
  const Frame frame(n);
  return frame
      .toWorld(Vector3f(float(std::cos(elevation) * std::cos(phi)),
                        float(std::cos(elevation) * std::sin(phi)), float(std::sin(elevation))))
      .normalized();
}

Vector3f cosineAround(const Normal3f& n, pcg32& rng) {
  std::uniform_real_distribution<float> uniform(0, 1);
  return Frame(n).toWorld(warp::squareToCosineHemisphere(Point2f(uniform(rng), uniform(rng))));
}

struct Tally {
  long rays = 0, selfHits = 0, blockerRays = 0, missedBlockers = 0;
  std::vector<std::string> examples;
  void fail(long* counter, const std::string& what) {
    ++*counter;
    if (examples.size() < 5) examples.push_back(what);
  }
};

class RayOffsetFamily : public ::testing::TestWithParam<Family> {};

TEST_P(RayOffsetFamily, NoSelfIntersectionAndNoMissedBlocker) {
  const Family family = GetParam();
  pcg32 rng(std::hash<std::string>{}(family.name));  // fixed by the family's name
  std::uniform_real_distribution<float> uniform(0, 1);
  const bool sphere = family.kind == Kind::Sphere;
  Tally tally;
  for (int placementIndex = 0; placementIndex < kPlacements; ++placementIndex) {
    const Placement placement = randomPlacement(family, rng);
    const SceneFile alone = sceneOf({surfaceJson(family.kind, placement.toWorld)});
    const SceneFile blocked =
        sceneOf({surfaceJson(family.kind, placement.toWorld),
                 surfaceJson(family.kind, blockerOf(family.kind, placement))});
    const Shape& subject = *alone.scene->shapes().front();
    const Eigen::Matrix3d linear = placement.toWorld.topLeftCorner<3, 3>();
    const Eigen::Vector3d translation = placement.toWorld.topRightCorner<3, 1>();
    const Normal3f frontNormal = (linear * Eigen::Vector3d::UnitZ()).normalized().cast<float>();
    const double size = placement.scale;
    const auto where = [&](const Point3f& p) {
      return fmt::format("scale {:.3g}, point ({:.9g}, {:.9g}, {:.9g})", size, p.x(), p.y(), p.z());
    };
    // A hit on the subject is its own surface, except a sphere's far side, reached from inside.
    const auto selfHit = [&](const SurfaceInteraction& from, const Ray& ray) {
      SurfaceInteraction next;
      if (!alone.scene->intersect(ray, next)) return false;
      return !sphere || (next.p - from.p).norm() < 1e-5 * size;
    };

    while (tally.rays < kRaysPerFamily * (placementIndex + 1) / kPlacements) {
      const Eigen::Vector3d local = localPoint(family.kind, rng, 2 * placement.gap);
      const Point3f target = (linear * local + translation).cast<float>();
      // Arrive from the side away from the blocker (a sphere: from outside).
      const Normal3f towardsBlocker =
          sphere ? Normal3f((linear * local).normalized().cast<float>()) : frontNormal;
      const Vector3f arrival = -cosineAround(towardsBlocker, rng);
      SurfaceInteraction si;
      if (!alone.scene->intersect(Ray(target - float(4 * size) * arrival, arrival), si)) continue;

      // Leaving head-on and grazing, on both sides (a sphere's inside only grazing, so that
      // its far side stays more than 1e-5 sizes away).
      for (const float side : {1.0f, -1.0f}) {
        const Normal3f n = side * si.ng;
        Vector3f directions[2] = {cosineAround(n, rng), grazing(n, rng)};
        for (int k = (sphere && side < 0) ? 1 : 0; k < 2; ++k) {
          ++tally.rays;
          if (selfHit(si, si.spawnRay(directions[k])))
            tally.fail(&tally.selfHits,
                       fmt::format("leaving {} {} at {}", k ? "grazing" : "head-on",
                                   side > 0 ? "front" : "back", where(si.p)));
        }
      }

      // Emission from an area sample.
      const ShapeSample emitter = subject.sampleArea(Point2f(uniform(rng), uniform(rng)));
      ++tally.rays;
      if (selfHit({.p = emitter.p},
                  spawnRay(emitter.p, emitter.pError, emitter.n, cosineAround(emitter.n, rng))))
        tally.fail(&tally.selfHits, "emitted from " + where(emitter.p));

      // Shadow rays to lights near (a hundredth of the size, or 16 times what floats resolve
      // there) and far (a thousand sizes) away, grazing or head-on, on the outside: nothing is
      // between them but the surface itself. A grazing light stays above what floats resolve.
      const double near = std::max(1e-2 * size, 16 * placement.resolvable);
      for (const double distance : {near, 1e3 * size}) {
        const Normal3f n = sphere ? si.ng : Normal3f(si.ng * (uniform(rng) < 0.5f ? 1 : -1));
        const double lowest = std::max(1e-4, std::asin(placement.resolvable / distance));
        const Vector3f d = uniform(rng) < 0.5f ? grazing(n, rng, lowest) : cosineAround(n, rng);
        const Point3f light = si.p + float(distance) * d;
        ++tally.rays;
        if (alone.scene->occluded(si.spawnRayTo(light, Vector3f::Zero(), -d)))
          tally.fail(&tally.selfHits,
                     fmt::format("shadow ray to a light {:.3g} sizes away, from {}",
                                 distance / size, where(si.p)));
      }

      // A shadow ray through the blocker, at up to 60° from its normal, to a light ten gaps
      // beyond it: the margin kept from the edges keeps the crossing inside the blocker.
      Vector3f d = cosineAround(towardsBlocker, rng);
      if (d.dot(towardsBlocker) < 0.5f) continue;
      const Point3f light = si.p + float(10 * placement.gap * size / d.dot(towardsBlocker)) * d;
      ++tally.rays;
      ++tally.blockerRays;
      if (!blocked.scene->occluded(si.spawnRayTo(light, Vector3f::Zero(), -d)))
        tally.fail(&tally.missedBlockers, "blocker missed from " + where(si.p));
    }
  }
  fmt::print("{}: {} rays ({} through a blocker), {} self-intersections, {} missed blockers\n",
             family.name, tally.rays, tally.blockerRays, tally.selfHits, tally.missedBlockers);
  for (const std::string& e : tally.examples) fmt::print("  {}\n", e);
  EXPECT_GE(tally.rays, kRaysPerFamily);
  EXPECT_GT(tally.blockerRays, kRaysPerFamily / 20);
  EXPECT_EQ(tally.selfHits, 0);
  EXPECT_EQ(tally.missedBlockers, 0);
}

INSTANTIATE_TEST_SUITE_P(Families, RayOffsetFamily, ::testing::ValuesIn(kFamilies),
                         [](const ::testing::TestParamInfo<Family>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace verity

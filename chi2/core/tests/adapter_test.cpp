// The adapters on code written as another renderer writes it (toys with their own vector
// and colour types, no Verity type): correct ones pass, and each planted mistake is
// rejected by the check named for it. Links verity_chi2_core only, as an outside project does.
//
// Level: the correct subjects are CorrectChecks checks of two statistical tests each, at a
// family-wise level of 1% with Šidák's correction; the broken ones use the same level.
#include <gtest/gtest.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/significance.h>
#include <verity/chi2/warp_adapter.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <numbers>

#include "phong_toy.h"

namespace verity::chi2 {

namespace {

using phong_toy::Flaw;
using phong_toy::Vec3;

// The checks that must pass: 2 incidences of the Phong lobe, 5 warps, 1 vector-type variant,
// 1 lobe that returns pdf 0 for "no sample".
constexpr int kCorrectChecks = 9;
const double kLevel = sidakLevel(0.01, kStatisticalTestsPerCheck* kCorrectChecks);
constexpr long long kSamples = 200'000;
constexpr double kExponent = 20.5;

BsdfModel phongModel(Flaw flaw) {
  const phong_toy::Phong p(kExponent, flaw);
  return bsdfModel<Vec3>(
      [p](const Vec3& wi, const BsdfUniforms& u) { return p.sample(wi, u.xy.x, u.xy.y); },
      [p](const Vec3& wi, const Vec3& wo) { return p.eval(wi, wo); },
      [p](const Vec3& wi, const Vec3& wo) { return p.pdf(wi, wo); });
}

CheckResult checkPhong(Flaw flaw, double degrees, const std::string& name) {
  BsdfCheckOptions o;
  o.name = "adapter phong " + name;
  o.significance = kLevel;
  o.samples = kSamples;
  const double t = degrees * std::numbers::pi / 180;
  return checkBsdf(phongModel(flaw), Vec3{std::sin(t), 0, std::cos(t)}, o);
}

// Every check that failed, for the message.
std::string failed(const CheckResult& r) {
  std::string s;
  for (const std::string& f : r.failures()) s += "[" + f + "] ";
  return s + "\n" + r.report();
}

}  // namespace

// pbrt's convention: a sample whose pdf is 0 is no sample. A lobe that returns one (weight 0,
// pdf 0) below the horizon rather than nothing is counted as declining, not as a defect.
TEST(BsdfAdapter, ASampleOfPdfZeroIsNoSample) {
  const phong_toy::Phong p(kExponent, Flaw::None);
  const BsdfModel model = bsdfModel<Vec3>(
      [p](const Vec3& wi, const BsdfUniforms& u) -> std::optional<phong_toy::Sample> {
        if (auto s = p.sample(wi, u.xy.x, u.xy.y)) return s;
        return phong_toy::Sample{};
      },
      [p](const Vec3& wi, const Vec3& wo) { return p.eval(wi, wo); },
      [p](const Vec3& wi, const Vec3& wo) { return p.pdf(wi, wo); });
  BsdfCheckOptions o;
  o.name = "adapter phong pdf 0 as no sample";
  o.significance = kLevel;
  o.samples = kSamples;
  const double t = 75 * std::numbers::pi / 180;
  const CheckResult r = checkBsdf(model, Vec3{std::sin(t), 0, std::cos(t)}, o);
  EXPECT_TRUE(r.passed()) << failed(r);
  EXPECT_LT(r.test.valid, r.test.samples) << "the lobe at 75 degrees must lose samples";
}

TEST(BsdfAdapter, CorrectPhongPasses) {
  for (double degrees : {30.0, 75.0}) {
    const CheckResult r = checkPhong(Flaw::None, degrees, "correct " + std::to_string(degrees));
    EXPECT_TRUE(r.passed()) << failed(r);
    EXPECT_GT(r.test.valid, 0);
  }
}

TEST(BsdfAdapter, WrongPdfNormalisationIsRejectedByTheIntegral) {
  const CheckResult r = checkPhong(Flaw::PdfNormalisation, 30, "pdf normalisation");
  EXPECT_TRUE(r.failed("pdf integral")) << failed(r);
  // The shape is right and the weight consistent with eval/pdf: only the integral sees it.
  EXPECT_FALSE(r.failed("weight != eval*cos/pdf")) << failed(r);
}

TEST(BsdfAdapter, WeightInconsistentWithEvalIsRejected) {
  const CheckResult r = checkPhong(Flaw::Weight, 30, "weight");
  EXPECT_TRUE(r.failed("weight != eval*cos/pdf")) << failed(r);
}

TEST(BsdfAdapter, NonReciprocalEvalIsRejected) {
  const CheckResult r = checkPhong(Flaw::NonReciprocal, 30, "reciprocity");
  EXPECT_TRUE(r.failed("reciprocity")) << failed(r);
}

TEST(BsdfAdapter, NanAwayFromTheLobeIsRejected) {
  const CheckResult r = checkPhong(Flaw::UnclampedLobe, 30, "nan");
  EXPECT_TRUE(r.failed("non-finite value")) << failed(r);
}

TEST(BsdfAdapter, SamplePdfDisagreeingWithPdfIsRejected) {
  const CheckResult r = checkPhong(Flaw::SamplePdf, 30, "sample pdf");
  EXPECT_TRUE(r.failed("sample pdf != pdf()")) << failed(r);
}

// The vector and value types are read through .x(), .x, .r or [i]: the same lobe with
// std::array directions and a scalar (grey) value.
TEST(BsdfAdapter, ArrayVectorsAndScalarValuesAreRead) {
  using A = std::array<float, 3>;
  const phong_toy::Phong p(kExponent, Flaw::None);
  auto vec = [](const A& a) { return Vec3{a[0], a[1], a[2]}; };
  const BsdfModel m = bsdfModel<A>(
      [p, vec](const A& wi, const BsdfUniforms& u) -> std::optional<SampledDirection<A, float>> {
        const auto s = p.sample(vec(wi), u.xy.x, u.xy.y);
        if (!s) return std::nullopt;
        return SampledDirection<A, float>{
            {float(s->wo.x), float(s->wo.y), float(s->wo.z)}, s->weight.r, s->pdf};
      },
      [p, vec](const A& wi, const A& wo) { return p.eval(vec(wi), vec(wo)).r; },
      [p, vec](const A& wi, const A& wo) { return float(p.pdf(vec(wi), vec(wo))); });
  EXPECT_EQ(m.components, 1);
  BsdfCheckOptions o;
  o.name = "adapter phong std::array";
  o.significance = kLevel;
  o.samples = kSamples;
  const CheckResult r = checkBsdf(m, A{0.5f, 0, 0.8660254f}, o);
  EXPECT_TRUE(r.passed()) << failed(r);
}

TEST(VectorAccess, ReadsAndMakesEachKindOfType) {
  struct Members {
    float x, y, z;
  };
  struct Colour {
    double r, g, b;
  };
  const Eigen::Vector3d p(0.25, -0.5, 2);
  EXPECT_EQ(readVector3(makeVector3<Members>(p)), p);
  EXPECT_EQ(readVector3(makeVector3<Colour>(p)), p);
  EXPECT_EQ(readVector3(makeVector3<std::array<double, 3>>(p)), p);
  EXPECT_EQ(readVector3(makeVector3<Eigen::Vector3f>(p)), p);
  EXPECT_EQ(readVector2(Uniform2{0.25, 0.75}.operator Eigen::Vector2f()),
            Eigen::Vector2d(0.25, 0.75));
  EXPECT_EQ(ValueAccess<float>::read(0.5f).matrix(), Eigen::VectorXd::Constant(1, 0.5));
}

// Toy warps, written from the formulas.
namespace {

struct Vec2 {
  float x = 0, y = 0;
};

// Shirley & Chiu 1997, "A low distortion map between disk and square".
Vec2 concentricDisk(const Vec2& u) {
  const double a = 2 * u.x - 1, b = 2 * u.y - 1;
  if (a == 0 && b == 0) return {};
  const double pi = std::numbers::pi;
  const bool wide = std::fabs(a) > std::fabs(b);
  const double r = wide ? a : b, phi = wide ? pi / 4 * (b / a) : pi / 2 - pi / 4 * (a / b);
  return {float(r * std::cos(phi)), float(r * std::sin(phi))};
}
// The polar map with the radius left linear in u: too many points near the centre.
Vec2 linearRadiusDisk(const Vec2& u) {
  const double phi = 2 * std::numbers::pi * u.y;
  return {float(u.x * std::cos(phi)), float(u.x * std::sin(phi))};
}
double diskPdf(const Vec2& p) {
  return p.x * p.x + p.y * p.y <= 1 ? 1 / std::numbers::pi : 0;
}

// Malley's method: the concentric disk lifted to the hemisphere, pdf = cos θ / π.
Vec3 cosineHemisphere(const Vec2& u) {
  const Vec2 d = concentricDisk(u);
  return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
}
double cosinePdf(const Vec3& w) {
  return w.z > 0 ? w.z / std::numbers::pi : 0;
}

Vec3 uniformSphere(const Vec2& u) {
  const double z = 1 - 2 * double(u.x), r = std::sqrt(std::max(0.0, 1 - z * z));
  const double phi = 2 * std::numbers::pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Barycentrics by the square-root map (Osada et al. 2002, "Shape distributions").
Vec2 uniformTriangle(const Vec2& u) {
  const float s = std::sqrt(u.x);
  return {1 - s, u.y * s};
}

CheckResult runWarp(const WarpModel& m, const std::string& name) {
  WarpCheckOptions o;
  o.name = "adapter warp " + name;
  o.significance = kLevel;
  o.samples = kSamples;
  return checkWarp(m, o);
}

}  // namespace

TEST(WarpAdapter, CorrectWarpsPass) {
  const std::pair<WarpModel, const char*> warps[] = {
      {squareWarp<Vec2>([](const Vec2& u) { return u; }, [](const Vec2&) { return 1.0; }),
       "square"},
      {diskWarp<Vec2>(concentricDisk, diskPdf), "concentric disk"},
      {triangleWarp<Vec2>(uniformTriangle, [](const Vec2&) { return 2.0; }), "triangle"},
      {hemisphereWarp<Vec3>(cosineHemisphere, cosinePdf), "cosine hemisphere"},
      {sphereWarp<Vec3>(uniformSphere, [](const Vec3&) { return 1 / (4 * std::numbers::pi); }),
       "sphere"},
  };
  for (const auto& [model, name] : warps) {
    const CheckResult r = runWarp(model, name);
    EXPECT_TRUE(r.passed()) << name << ": " << failed(r);
  }
}

TEST(WarpAdapter, WrongShapeIsRejectedByChiSquare) {
  const CheckResult r = runWarp(diskWarp<Vec2>(linearRadiusDisk, diskPdf), "linear radius");
  EXPECT_TRUE(r.failed("chi-square")) << failed(r);
  EXPECT_FALSE(r.failed("pdf integral")) << failed(r);
}

TEST(WarpAdapter, WrongNormalisationIsRejectedByTheIntegral) {
  // The uniform sphere's density with the hemisphere's constant.
  const CheckResult r = runWarp(
      sphereWarp<Vec3>(uniformSphere, [](const Vec3&) { return 1 / (2 * std::numbers::pi); }),
      "sphere normalisation");
  EXPECT_TRUE(r.failed("pdf integral")) << failed(r);
  EXPECT_FALSE(r.failed("chi-square")) << failed(r);
}

TEST(WarpAdapter, NonUnitDirectionIsRejected) {
  // The hemisphere point of Malley's method left on the disk (z = 0): not a direction.
  const CheckResult r = runWarp(hemisphereWarp<Vec3>(
                                    [](const Vec2& u) {
                                      const Vec2 d = concentricDisk(u);
                                      return Vec3{d.x, d.y, 0};
                                    },
                                    cosinePdf),
                                "not lifted");
  EXPECT_TRUE(r.failed("direction not a unit vector")) << failed(r);
}

}  // namespace verity::chi2

#include "shapes/sphere.h"

#include "params/key.h"
#include "sampling/warp.h"

namespace verity {

Sphere::Sphere(const Transform& toWorld, float radius) {
  float scale = 1;
  toWorld.isSimilarity(&scale);
  center_ = toWorld.point(Point3f::Zero());
  radius_ = radius * scale;
  rotation_ = toWorld.matrix().topLeftCorner<3, 3>() / scale;
  pError_ = pointErrorBound(center_.cwiseAbs() + Vector3f::Constant(radius_));
}

unsigned Sphere::attach(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
  v[0] = center_.x();
  v[1] = center_.y();
  v[2] = center_.z();
  v[3] = radius_;
  rtcCommitGeometry(geom);
  const unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

void Sphere::completeHit(const Ray& ray, const RTCHit&, float t, SurfaceInteraction& si) const {
  // Re-project the hit onto the surface: removes the error of o + t·d.
  const Vector3f d = (ray(t) - center_).normalized();
  si.p = center_ + radius_ * d;
  si.pError = pError_;
  si.ng = d;
  si.shading = Frame(d);
  const Vector3f local = rotation_.transpose() * d;
  const float phi = std::atan2(local.z(), local.x());
  const float theta = std::asin(std::clamp(local.y(), -1.0f, 1.0f));
  si.uv = Point2f(1 - (phi + kPi) * kInv2Pi, (theta + kPi / 2) * kInvPi);
}

Bounds3f Sphere::bounds() const {
  Bounds3f b;
  b.expand(center_ - Vector3f::Constant(radius_));
  b.expand(center_ + Vector3f::Constant(radius_));
  return b;
}

ShapeSample Sphere::sampleArea(const Point2f& u) const {
  const Vector3f d = warp::squareToUniformSphere(u);
  return {center_ + radius_ * d, d, pError_, 1.0f / area()};
}

// Samples the cone of directions that the sphere subtends (Shirley, Wang and Zimmerman 1996,
// "Monte Carlo Techniques for Direct Lighting Calculations"); inside the sphere, by area.
std::optional<ShapeSample> Sphere::sampleSolidAngle(const Point3f& ref, const Point2f& u) const {
  const Vector3f toCenter = center_ - ref;
  const float dist2 = toCenter.squaredNorm();
  const float r2 = radius_ * radius_;
  if (dist2 <= r2 * 1.0001f) return Shape::sampleSolidAngle(ref, u);
  const float dist = std::sqrt(dist2);
  const float sin2ThetaMax = r2 / dist2;
  const float cosThetaMax = safeSqrt(1 - sin2ThetaMax);
  // 1 − cos θmax without cancellation for small, distant spheres.
  const float oneMinusCos = sin2ThetaMax / (1 + cosThetaMax);
  const float z = 1 - u.x() * oneMinusCos;
  const float sinTheta = safeSqrt(1 - z * z);
  const float phi = 2 * kPi * u.y();
  const Frame frame(toCenter / dist);
  const Vector3f w = frame.toWorld(Vector3f(sinTheta * std::cos(phi), sinTheta * std::sin(phi), z));
  // Nearest intersection of ref + s·w with the sphere.
  const float b = w.dot(toCenter);
  const float disc = r2 - (toCenter - b * w).squaredNorm();
  const float s = b - safeSqrt(disc);
  const Vector3f n = (ref + s * w - center_).normalized();
  ShapeSample sample{center_ + radius_ * n, n, pError_, 1.0f / (2 * kPi * oneMinusCos)};
  if (!std::isfinite(sample.pdf)) return std::nullopt;
  return sample;
}

float Sphere::pdfSolidAngle(const Point3f& ref, const Point3f& p, const Normal3f& n) const {
  const float dist2 = (center_ - ref).squaredNorm();
  const float r2 = radius_ * radius_;
  if (dist2 <= r2 * 1.0001f) return Shape::pdfSolidAngle(ref, p, n);
  const float sin2ThetaMax = r2 / dist2;
  const float oneMinusCos = sin2ThetaMax / (1 + safeSqrt(1 - sin2ThetaMax));
  return 1.0f / (2 * kPi * oneMinusCos);
}

double Sphere::solidAngleEstimate(const Point3f& ref) const {
  const double dist2 = (center_ - ref).cast<double>().squaredNorm();
  const double r2 = double{radius_} * radius_;
  if (dist2 <= r2) return 2 * double{kPi};
  const double sin2ThetaMax = r2 / dist2;
  return 2 * double{kPi} * sin2ThetaMax / (1 + std::sqrt(1 - sin2ThetaMax));
}

namespace {

const Key<float> kRadius{.name = "radius",
                         .defaultValue = 1,
                         .allowed = Range::positive(),
                         .meaning = "the radius, in local units"};

}  // namespace

ShapeType sphereType() {
  return {"sphere",
          {},
          "a sphere about the local origin; its poles on the local y axis",
          declarations(kRadius),
          [](const JsonNode& node, const Transform& toWorld) -> std::unique_ptr<Shape> {
            const float radius = node.get(kRadius);
            if (!toWorld.isSimilarity(nullptr))
              node[{"transform"}].fail(
                  "a sphere's transform must scale uniformly (no shear or non-uniform scale)");
            return std::make_unique<Sphere>(toWorld, radius);
          }};
}

}  // namespace verity

#include "shapes/quad.h"

#include "params/key.h"

namespace verity {

Quad::Quad(const Transform& toWorld, const Vector2f& size) {
  const float hw = size.x() / 2, hh = size.y() / 2;
  corner_ = toWorld.point(Point3f(-hw, -hh, 0));
  edgeU_ = toWorld.point(Point3f(hw, -hh, 0)) - corner_;
  edgeV_ = toWorld.point(Point3f(-hw, hh, 0)) - corner_;
  const Vector3f cross = edgeU_.cross(edgeV_);
  area_ = cross.norm();
  normal_ = cross / area_;
  // A mirroring transform keeps the local +z side as the front.
  const Normal3f localFront = toWorld.normal(Normal3f::UnitZ());
  if (localFront.dot(normal_) < 0) normal_ = -normal_;
  pError_ = pointErrorBound(corner_.cwiseAbs() + edgeU_.cwiseAbs() + edgeV_.cwiseAbs());
}

double Quad::solidAngleEstimate(const Point3f& ref) const {
  return planarSolidAngleEstimate(area_, corner_ + 0.5f * (edgeU_ + edgeV_), normal_, ref);
}

unsigned Quad::attach(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4));
  const Point3f corners[4] = {corner_, corner_ + edgeU_, corner_ + edgeU_ + edgeV_,
                              corner_ + edgeV_};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = corners[i][k];
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), 1));
  for (unsigned i = 0; i < 4; ++i) idx[i] = i;
  rtcCommitGeometry(geom);
  const unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

void Quad::completeHit(const Ray&, const RTCHit& hit, float, SurfaceInteraction& si) const {
  // For a parallelogram Embree's bilinear (u, v) are the edge coordinates.
  si.uv = Point2f(hit.u, hit.v);
  si.p = corner_ + hit.u * edgeU_ + hit.v * edgeV_;
  si.pError = pError_;
  si.ng = normal_;
  si.shading.n = normal_;
  si.shading.s = edgeU_.normalized();
  si.shading.t = normal_.cross(si.shading.s);
}

Bounds3f Quad::bounds() const {
  Bounds3f b;
  b.expand(corner_);
  b.expand(corner_ + edgeU_);
  b.expand(corner_ + edgeV_);
  b.expand(corner_ + edgeU_ + edgeV_);
  return b;
}

ShapeSample Quad::sampleArea(const Point2f& u) const {
  return {corner_ + u.x() * edgeU_ + u.y() * edgeV_, normal_, pError_, 1.0f / area_};
}

namespace {

const Key<Vector2f> kQuadSize{.name = "size",
                              .defaultValue = Vector2f(1, 1),
                              .allowed = Range::positive(),
                              .meaning = "the side lengths along local x and y"};

}  // namespace

ShapeType quadType() {
  return {"quad",
          {},
          "a rectangle centred in the local xy-plane, front side +z",
          declarations(kQuadSize),
          [](const JsonNode& node, const Transform& toWorld) -> std::unique_ptr<Shape> {
            return std::make_unique<Quad>(toWorld, node.get(kQuadSize));
          }};
}

}  // namespace verity

#include "shapes/triangle_mesh.h"

#include "sampling/warp.h"

namespace verity {

TriangleMesh::TriangleMesh(MeshData data) : data_(std::move(data)) {
  std::vector<double> areas(primitiveCount());
  for (size_t i = 0; i < areas.size(); ++i) {
    const Point3f& a = data_.positions[data_.indices[3 * i]];
    const Point3f& b = data_.positions[data_.indices[3 * i + 1]];
    const Point3f& c = data_.positions[data_.indices[3 * i + 2]];
    const double area = 0.5 * (b - a).cast<double>().cross((c - a).cast<double>()).norm();
    areas[i] = std::isfinite(area) ? area : 0.0;
  }
  areas_ = Distribution1D(areas);
  faceNormals_.resize(primitiveCount());
  for (size_t i = 0; i < faceNormals_.size(); ++i) faceNormals_[i] = computeFaceNormal(i);
}

unsigned TriangleMesh::attach(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                             data_.positions.data(), 0, sizeof(Point3f), data_.positions.size());
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, data_.indices.data(),
                             0, 3 * sizeof(uint32_t), primitiveCount());
  rtcCommitGeometry(geom);
  const unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

// All three vertices bound the error, not the barycentric-weighted ones: near a vertex at the
// origin, Embree's test still rounds in proportion to the far vertices.
Vector3f TriangleMesh::pointError(size_t tri) const {
  return pointErrorBound(data_.positions[data_.indices[3 * tri]].cwiseAbs() +
                         data_.positions[data_.indices[3 * tri + 1]].cwiseAbs() +
                         data_.positions[data_.indices[3 * tri + 2]].cwiseAbs());
}

Normal3f TriangleMesh::computeFaceNormal(size_t tri) const {
  const Point3f& a = data_.positions[data_.indices[3 * tri]];
  const Point3f& b = data_.positions[data_.indices[3 * tri + 1]];
  const Point3f& c = data_.positions[data_.indices[3 * tri + 2]];
  Normal3f n = (b - a).cross(c - a);
  const float len = n.norm();
  if (!(len > 0) || !std::isfinite(len)) return Normal3f::UnitZ();
  n /= len;
  // The front side agrees with the vertex normals when there are any.
  if (!data_.normals.empty()) {
    const Normal3f avg = data_.normals[data_.indices[3 * tri]] +
                         data_.normals[data_.indices[3 * tri + 1]] +
                         data_.normals[data_.indices[3 * tri + 2]];
    if (avg.dot(n) < 0) n = -n;
  }
  return n;
}

void TriangleMesh::completeHit(const Ray&, const RTCHit& hit, float, SurfaceInteraction& si) const {
  const size_t tri = hit.primID;
  const uint32_t i0 = data_.indices[3 * tri], i1 = data_.indices[3 * tri + 1],
                 i2 = data_.indices[3 * tri + 2];
  const float b1 = hit.u, b2 = hit.v, b0 = 1 - b1 - b2;
  // Interpolating the vertices keeps the point's error relative to the triangle's size.
  si.p = b0 * data_.positions[i0] + b1 * data_.positions[i1] + b2 * data_.positions[i2];
  si.pError = pointError(tri);
  si.ng = faceNormals_[tri];
  si.uv = data_.uvs.empty() ? Point2f(b1, b2)
                            : Point2f(b0 * data_.uvs[i0] + b1 * data_.uvs[i1] + b2 * data_.uvs[i2]);
  Normal3f ns = si.ng;
  if (!data_.normals.empty()) {
    const Normal3f n = b0 * data_.normals[i0] + b1 * data_.normals[i1] + b2 * data_.normals[i2];
    const float len = n.norm();
    if (len > 0 && std::isfinite(len)) ns = n / len;
  }
  si.shading = Frame(ns);
}

Bounds3f TriangleMesh::bounds() const {
  Bounds3f b;
  for (const Point3f& p : data_.positions) b.expand(p);
  return b;
}

double TriangleMesh::solidAngleEstimate(const Point3f& ref) const {
  if (primitiveCount() > kTrianglesEstimated) return Shape::solidAngleEstimate(ref);
  double sum = 0;
  for (size_t tri = 0; tri < primitiveCount(); ++tri) {
    const Point3f& a = data_.positions[data_.indices[3 * tri]];
    const Point3f& b = data_.positions[data_.indices[3 * tri + 1]];
    const Point3f& c = data_.positions[data_.indices[3 * tri + 2]];
    const double area = areas_.pmf(tri) * areas_.total();
    if (area > 0) sum += planarSolidAngleEstimate(area, (a + b + c) / 3, faceNormals_[tri], ref);
  }
  return std::min(2 * double{kPi}, sum);
}

ShapeSample TriangleMesh::sampleArea(const Point2f& u) const {
  float remapped = 0;
  const size_t tri = areas_.sampleDiscrete(u.x(), nullptr, &remapped);
  const Point2f b = warp::squareToUniformTriangle(Point2f(remapped, u.y()));
  const Point3f& a = data_.positions[data_.indices[3 * tri]];
  const Point3f& p1 = data_.positions[data_.indices[3 * tri + 1]];
  const Point3f& p2 = data_.positions[data_.indices[3 * tri + 2]];
  return {b.x() * a + b.y() * p1 + (1 - b.x() - b.y()) * p2, faceNormals_[tri], pointError(tri),
          1.0f / area()};
}

}  // namespace verity

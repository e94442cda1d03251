// Triangles with optional per-vertex normals and uvs, in world space (Embree triangles).
#pragma once

#include <vector>

#include "sampling/distribution.h"
#include "shapes/shape.h"
#include "shapes/shape_type.h"

namespace verity {

struct MeshData {
  std::vector<Point3f> positions;
  std::vector<Normal3f> normals;  // empty, or one per position
  std::vector<Point2f> uvs;       // empty, or one per position
  std::vector<uint32_t> indices;  // three per triangle
};

class TriangleMesh : public Shape {
 public:
  // Degenerate (zero-area) triangles are kept for intersection but never sampled.
  explicit TriangleMesh(MeshData data);

  unsigned attach(RTCDevice device, RTCScene scene) const override;
  void completeHit(const Ray& ray, const RTCHit& hit, float t,
                   SurfaceInteraction& si) const override;
  Bounds3f bounds() const override;
  float area() const override { return static_cast<float>(areas_.total()); }
  ShapeSample sampleArea(const Point2f& u) const override;
  // Summed over the triangles up to kTrianglesEstimated of them; beyond, the default's.
  double solidAngleEstimate(const Point3f& ref) const override;
  size_t primitiveCount() const override { return data_.indices.size() / 3; }
  static constexpr size_t kTrianglesEstimated = 16;
  const MeshData& data() const { return data_; }

 private:
  // The unit geometric normal, on the side of the vertex normals where there are any.
  Normal3f computeFaceNormal(size_t tri) const;
  Vector3f pointError(size_t tri) const;

  MeshData data_;
  Distribution1D areas_;
  // computeFaceNormal of each triangle, computed once: every hit and every sampled point on an
  // emitting mesh reads it (12 bytes a triangle).
  std::vector<Normal3f> faceNormals_;
};

// The scene format's "mesh" (an OBJ file) and "triangle" (triangle_mesh_types.cpp).
ShapeType meshType();
ShapeType triangleType();

}  // namespace verity

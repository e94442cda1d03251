// The scene format's triangle surfaces: "mesh", read from an OBJ file, and "triangle", given
// inline. Both become a TriangleMesh in world space.
#include "params/key.h"
#include "shapes/obj_loader.h"
#include "shapes/triangle_mesh.h"

namespace verity {

namespace {

// A triangle's front side is the side its winding turns counter-clockwise around; a
// mirroring transform reverses the winding, so it is reversed back to keep the front on the
// same side of the surface (as quads do; pbrt flips such normals too).
MeshData keepFront(MeshData mesh, const Transform& toWorld) {
  if (toWorld.flipsHandedness())
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  return mesh;
}

const KeyDeclaration kPositions{"positions",      {},
                                ValueType::Array, "3 points, each a number or [x, y, z]",
                                "required",       "the corners, in local coordinates"};
const KeyDeclaration kNormals{"normals",
                              {},
                              ValueType::Array,
                              "3 non-zero vectors",
                              "the geometric normal",
                              "shading normals at the corners, interpolated across the triangle"};
const KeyDeclaration kUvs{"uvs",
                          {},
                          ValueType::Array,
                          "3 pairs [u, v]",
                          "barycentric (u, v)",
                          "texture coordinates at the corners"};
const Key<std::string> kMeshFile{.name = "filename",
                                 .allowed = "an OBJ file, relative to the scene file",
                                 .meaning = "the mesh to load"};

MeshData parseTriangle(const JsonNode& node, const Transform& toWorld) {
  MeshData mesh;
  const JsonNode positions = node[kPositions];
  if (!positions.isArray() || positions.size() != 3) positions.fail("expected 3 points");
  for (size_t i = 0; i < 3; ++i) mesh.positions.push_back(toWorld.point(positions[i].asVector3()));
  if (auto normals = node.find(kNormals)) {
    if (!normals->isArray() || normals->size() != 3) normals->fail("expected 3 normals");
    for (size_t i = 0; i < 3; ++i) {
      const Normal3f n = toWorld.normal((*normals)[i].asVector3());
      if (!(n.norm() > 0)) (*normals)[i].fail("a normal must not be zero");
      mesh.normals.push_back(n.normalized());
    }
  }
  if (auto uvs = node.find(kUvs)) {
    if (!uvs->isArray() || uvs->size() != 3) uvs->fail("expected 3 uv pairs");
    for (size_t i = 0; i < 3; ++i) {
      const JsonNode uv = (*uvs)[i];
      if (!uv.isArray() || uv.size() != 2) uv.fail("expected [u, v]");
      mesh.uvs.emplace_back(uv[0].asFloat(), uv[1].asFloat());
    }
  }
  mesh.indices = {0, 1, 2};
  return mesh;
}

}  // namespace

ShapeType meshType() {
  return {"mesh",
          {},
          "the triangles of a Wavefront OBJ file (polygons fan-triangulated), with its normals "
          "and uvs where it has them",
          declarations(kMeshFile),
          [](const JsonNode& node, const Transform& toWorld) -> std::unique_ptr<Shape> {
            const JsonNode file = node[kMeshFile];
            try {
              return std::make_unique<TriangleMesh>(
                  keepFront(loadObj(node.resolve(file.asString()), toWorld, file.path()), toWorld));
            } catch (const VerityError& e) {
              if (!e.file().empty()) throw;
              throw VerityError(node.file().string(), e.jsonPath(), e.problem());
            }
          }};
}

ShapeType triangleType() {
  return {"triangle",
          {},
          "one triangle given by its corners; its front side is the one they turn "
          "counter-clockwise around",
          declarations(kPositions, kNormals, kUvs),
          [](const JsonNode& node, const Transform& toWorld) -> std::unique_ptr<Shape> {
            return std::make_unique<TriangleMesh>(keepFront(parseTriangle(node, toWorld), toWorld));
          }};
}

}  // namespace verity

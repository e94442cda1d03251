#include "shapes/obj_loader.h"

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "core/error.h"

namespace verity {

MeshData loadObj(const std::filesystem::path& file, const Transform& toWorld,
                 const std::string& jsonPath) {
  const std::string name = file.string();
  if (std::filesystem::is_directory(file))
    throw VerityError("", jsonPath, "\"" + name + "\" is a directory, not a mesh file");
  if (!std::filesystem::is_regular_file(file))
    throw VerityError("", jsonPath, "mesh file \"" + name + "\" does not exist");
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) throw VerityError("", jsonPath, "cannot read mesh file \"" + name + "\"");
  return parseObj(text.str(), name, toWorld, jsonPath);
}

namespace {

// tinyobjloader reads a number it cannot parse, or a missing one, as 0. Checks every vertex
// position (v: x y z [w] or x y z r g b), normal (vn: x y z) and texture coordinate
// (vt: u [v [w]]) line first: each must hold that many finite numbers and nothing else.
void checkVertexLines(const std::string& text, const std::string& name,
                      const std::string& jsonPath) {
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const size_t comment = line.find('#');
    std::istringstream tokens(line.substr(0, comment));
    std::string keyword, token;
    if (!(tokens >> keyword) || (keyword != "v" && keyword != "vn" && keyword != "vt")) continue;
    const auto fail = [&](const std::string& problem) {
      throw VerityError("", jsonPath,
                        fmt::format("mesh \"{}\", line {}: {}", name, number, problem));
    };
    int count = 0;
    while (tokens >> token) {
      float value = 0;
      const char* end = token.data() + token.size();
      const auto [ptr, error] = std::from_chars(token.data(), end, value);
      if (error != std::errc() || ptr != end || !std::isfinite(value))
        fail("\"" + token + "\" is not a finite number");
      ++count;
    }
    const bool countOk = keyword == "v"    ? (count >= 3 && count <= 4) || count == 6
                         : keyword == "vn" ? count == 3
                                           : count >= 1 && count <= 3;
    if (!countOk) fail(fmt::format("\"{}\" with {} numbers", keyword, count));
  }
}

}  // namespace

MeshData parseObj(const std::string& text, const std::string& name, const Transform& toWorld,
                  const std::string& jsonPath) {
  checkVertexLines(text, name, jsonPath);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // Materials (.mtl) are not read: the scene assigns materials.
  if (!reader.ParseFromString(text, "", config)) {
    std::string message = reader.Error();
    while (!message.empty() && message.back() == '\n') message.pop_back();
    throw VerityError("", jsonPath, "cannot read mesh \"" + name + "\": " + message);
  }
  const auto& attrib = reader.GetAttrib();
  MeshData mesh;
  std::map<std::tuple<int, int, int>, uint32_t> corners;
  bool hasNormals = !attrib.normals.empty(), hasUvs = !attrib.texcoords.empty();
  const size_t nv = attrib.vertices.size() / 3, nn = attrib.normals.size() / 3,
               nt = attrib.texcoords.size() / 2;
  for (const auto& shape : reader.GetShapes()) {
    for (const auto& idx : shape.mesh.indices) {
      if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= nv)
        throw VerityError("", jsonPath,
                          "mesh \"" + name + "\" has a face with a vertex index out of range");
      // A corner without a normal or uv drops them for the whole mesh; a wrong index is an error.
      if (size_t(idx.normal_index) >= nn && idx.normal_index >= 0)
        throw VerityError("", jsonPath,
                          "mesh \"" + name + "\" has a face with a normal index out of range");
      if (size_t(idx.texcoord_index) >= nt && idx.texcoord_index >= 0)
        throw VerityError("", jsonPath,
                          "mesh \"" + name + "\" has a face with a uv index out of range");
      hasNormals = hasNormals && idx.normal_index >= 0;
      hasUvs = hasUvs && idx.texcoord_index >= 0;
    }
  }
  for (const auto& shape : reader.GetShapes()) {
    for (const auto& idx : shape.mesh.indices) {
      const auto key = std::make_tuple(idx.vertex_index, hasNormals ? idx.normal_index : -1,
                                       hasUvs ? idx.texcoord_index : -1);
      auto [it, inserted] = corners.emplace(key, static_cast<uint32_t>(mesh.positions.size()));
      if (inserted) {
        const float* v = &attrib.vertices[3 * idx.vertex_index];
        mesh.positions.push_back(toWorld.point(Point3f(v[0], v[1], v[2])));
        if (hasNormals) {
          const float* n = &attrib.normals[3 * idx.normal_index];
          Normal3f wn = toWorld.normal(Normal3f(n[0], n[1], n[2]));
          const float len = wn.norm();
          mesh.normals.push_back(len > 0 && std::isfinite(len) ? Normal3f(wn / len)
                                                               : Normal3f::UnitZ());
        }
        if (hasUvs) {
          const float* t = &attrib.texcoords[2 * idx.texcoord_index];
          mesh.uvs.emplace_back(t[0], t[1]);
        }
      }
      mesh.indices.push_back(it->second);
    }
  }
  if (mesh.indices.empty()) throw VerityError("", jsonPath, "mesh \"" + name + "\" has no faces");
  for (const Point3f& p : mesh.positions)
    if (!p.allFinite())
      throw VerityError("", jsonPath, "mesh \"" + name + "\" has a non-finite vertex position");
  return mesh;
}

}  // namespace verity

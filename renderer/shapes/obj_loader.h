// Reads a Wavefront OBJ file into a triangle mesh (polygons are fan-triangulated).
#pragma once

#include <filesystem>

#include "core/transform.h"
#include "shapes/triangle_mesh.h"

namespace verity {

// Throws VerityError with `jsonPath` when the file is missing or malformed.
MeshData loadObj(const std::filesystem::path& file, const Transform& toWorld,
                 const std::string& jsonPath);
// The same for OBJ text; `name` stands for the file in messages.
MeshData parseObj(const std::string& text, const std::string& name, const Transform& toWorld,
                  const std::string& jsonPath);

}  // namespace verity

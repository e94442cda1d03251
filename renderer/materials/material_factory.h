// Builds a material from its JSON object (every type and spelling of the scene format).
#pragma once

#include <memory>

#include "materials/material.h"
#include "scene/json_node.h"
#include "textures/texture_factory.h"

namespace verity {

// `node` is the material object itself; `named` resolves a material name (for `blend`).
class MaterialFactory {
 public:
  explicit MaterialFactory(TextureFactory& textures) : textures_(textures) {}
  std::shared_ptr<const Material> make(const JsonNode& node);
  // `nameNode` is the "name" member, for the error when the name is already taken.
  void addNamed(const JsonNode& nameNode, std::shared_ptr<const Material> material);
  // A material's name or an inline material object.
  std::shared_ptr<const Material> reference(const JsonNode& node);

 private:
  TextureFactory& textures_;
  std::map<std::string, std::shared_ptr<const Material>> named_;
};

}  // namespace verity

// Builds a material from its JSON object: looks its type up in the registry
// (material_registry.h) and serves the types' build functions with albedos, textures,
// named materials and warnings.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "materials/material.h"
#include "params/json_node.h"
#include "textures/texture_factory.h"

namespace verity {

// `node` is the material object itself; `named` resolves a material name (for `blend`).
class MaterialFactory {
 public:
  // Warnings (a material that would invent or lose energy) are appended to `warnings`.
  MaterialFactory(TextureFactory& textures, std::vector<VerityError>& warnings)
      : textures_(textures), warnings_(warnings) {}
  std::shared_ptr<const Material> make(const JsonNode& node);
  // `nameNode` is the "name" member, for the error when the name is already taken.
  void addNamed(const JsonNode& nameNode, std::shared_ptr<const Material> material);
  // Every name the scene's "materials" list gives, so that a reference to one not yet defined
  // (a blend naming itself or a later material) is told apart from an unknown name.
  void setListedNames(std::set<std::string> names) { listed_ = std::move(names); }
  // A material's name or an inline material object.
  std::shared_ptr<const Material> reference(const JsonNode& node);

  // For the types' build functions:
  // The "albedo" member (kAlbedo), with a warning when it can exceed 1.
  TexturedColor parseAlbedo(const JsonNode& node);
  TextureFactory& textures() { return textures_; }
  void warn(VerityError warning) { warnings_.push_back(std::move(warning)); }

 private:
  TextureFactory& textures_;
  std::vector<VerityError>& warnings_;
  std::map<std::string, std::shared_ptr<const Material>> named_;
  std::set<std::string> listed_;
};

}  // namespace verity

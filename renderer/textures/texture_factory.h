// Reads texture-valued JSON fields: a number or [r,g,b] is a constant, an object names a
// type of the texture registry (texture_registry.h). Image files are decoded once per path.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "params/json_node.h"
#include "textures/texture.h"

namespace verity {

class ImageTexture;

class TextureFactory {
 public:
  // `quantity` names the value in errors ("roughness must not be negative").
  TexturedColor parse(const JsonNode& node, const std::string& quantity = "a colour");
  // Reads member `keys` of `parent`, or `def` when absent.
  TexturedColor parse(const JsonNode& parent, Keys keys, const Color3& def,
                      const std::string& quantity = "a colour");
  // The image that the file name `fileNode` names (relative to the scene file), decoded on
  // its first use.
  std::shared_ptr<const ImageTexture> image(const JsonNode& fileNode);

 private:
  std::map<std::string, std::shared_ptr<const ImageTexture>> images_;
};

}  // namespace verity

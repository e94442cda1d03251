// Reads texture-valued JSON fields: a number or [r,g,b] is a constant, an object names a
// texture type. Image files are decoded once per path.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "scene/json_node.h"
#include "textures/texture.h"

namespace verity {

class ImageTexture;

class TextureFactory {
 public:
  TexturedColor parse(const JsonNode& node);
  // Reads member `keys` of `parent`, or `def` when absent.
  TexturedColor parse(const JsonNode& parent, Keys keys, const Color3& def);

 private:
  std::map<std::string, std::shared_ptr<const ImageTexture>> images_;
};

}  // namespace verity

// Reads texture-valued JSON fields: a number or [r,g,b] is a constant, an object names a
// type of the texture registry (texture_registry.h). Image files are decoded once per path.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "params/key.h"
#include "textures/texture.h"

namespace verity {

// A key whose value is a texture: a number, [r, g, b] or a texture object; its default is a
// constant colour. TextureFactory::parse reads it. `Allowed` says in words what the reader
// accepts (a constant is never negative).
template <>
struct KeyValue<TexturedColor> {
  using Allowed = std::string;
  static constexpr ValueType type = ValueType::Texture;
  static std::string allowedText(const std::string& words) { return words; }
  static std::string text(const TexturedColor& v) { return KeyValue<Color3>::text(v.constant()); }
};

class ImageTexture;

class TextureFactory {
 public:
  // `quantity` names the value in errors ("roughness must not be negative").
  TexturedColor parse(const JsonNode& node, const std::string& quantity = "a colour");
  // Reads the member `key` of `parent`, or its default when absent.
  TexturedColor parse(const JsonNode& parent, const Key<TexturedColor>& key,
                      const std::string& quantity = "a colour");
  // The image that the file name `fileNode` names (relative to the scene file), decoded on
  // its first use.
  std::shared_ptr<const ImageTexture> image(const JsonNode& fileNode);

 private:
  std::map<std::string, std::shared_ptr<const ImageTexture>> images_;
};

}  // namespace verity

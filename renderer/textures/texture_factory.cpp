#include "textures/texture_factory.h"

#include "textures/image_texture.h"
#include "textures/texture_registry.h"

namespace verity {

TexturedColor TextureFactory::parse(const JsonNode& node, const std::string& quantity) {
  if (node.isNumber() || node.isArray()) {
    const Vector3f v = node.asVector3();
    if ((v.array() < 0).any()) node.fail(quantity + " must not be negative");
    return TexturedColor(Color3(v.array()));
  }
  if (!node.isObject()) node.fail("expected a number, [r,g,b] or a texture object");
  const TextureType& entry = textureTypes().get(node[{"type"}]);
  node.declare({"texture " + entry.name, {&textureCommonKeys(), &entry.keys}});
  TexturedColor result = entry.build(node, *this, quantity);
  node.rejectUnknownKeys();
  return result;
}

TexturedColor TextureFactory::parse(const JsonNode& parent, const Key<TexturedColor>& key,
                                    const std::string& quantity) {
  auto node = parent.find(key);
  if (node) return parse(*node, quantity);
  if (!key.defaultValue) parent.fail("missing required key \"" + key.name + "\"");
  return *key.defaultValue;
}

std::shared_ptr<const ImageTexture> TextureFactory::image(const JsonNode& fileNode) {
  const std::string path = fileNode.resolve(fileNode.asString()).string();
  auto& image = images_[path];
  if (!image) {
    try {
      image = std::make_shared<ImageTexture>(path, fileNode.path());
    } catch (const VerityError& e) {
      throw VerityError(fileNode.file().string(), e.jsonPath(), e.problem());
    }
  }
  return image;
}

}  // namespace verity

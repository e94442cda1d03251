#include "textures/texture_registry.h"

#include "params/json_node.h"
#include "textures/checker.h"
#include "textures/image_texture.h"
#include "textures/marble.h"
#include "textures/texture_factory.h"

namespace verity {

namespace {

const Key<TexturedColor> kConstantColor{
    .name = "color",
    .aliases = {"value"},
    .allowed = "each channel >= 0",
    .meaning = "the colour (a number, [r, g, b], or another texture)"};

// A constant written as an object: it has no class of its own.
TextureType constantTextureType() {
  return {"constant",
          {},
          "one colour everywhere, written as an object",
          declarations(kConstantColor),
          [](const JsonNode& node, TextureFactory& factory, const std::string& quantity) {
            return factory.parse(node, kConstantColor, quantity);
          }};
}

}  // namespace

// An explicit list, as materials' (material_registry.cpp): the renderer is a static library,
// whose unreferenced object files the linker drops, self-registration and all.
const Registry<TextureType>& textureTypes() {
  static const Registry<TextureType> types(
      "texture type",
      {constantTextureType(), checkerTextureType(), marbleTextureType(), imageTextureType()});
  return types;
}

const KeyList& textureCommonKeys() {
  static const KeyList keys = {textureTypes().typeKey()};
  return keys;
}

}  // namespace verity

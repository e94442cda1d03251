#include "textures/texture_registry.h"

#include "params/json_node.h"
#include "textures/checker.h"
#include "textures/image_texture.h"
#include "textures/marble.h"
#include "textures/texture_factory.h"

namespace verity {

namespace {

// A constant written as an object: it has no class of its own.
TextureType constantTextureType() {
  return {"constant",
          "one colour everywhere, written as an object",
          {{"color",
            {"value"},
            ValueType::Texture,
            "each channel >= 0",
            "required",
            "the colour (a number, [r, g, b], or another texture)"}},
          [](const JsonNode& node, TextureFactory& factory, const std::string& quantity) {
            return factory.parse(node[{"color", "value"}], quantity);
          }};
}

}  // namespace

// An explicit list, as materials' (material_registry.cpp): the renderer is a static library,
// whose unreferenced object files the linker drops, self-registration and all.
const std::vector<TextureType>& textureTypes() {
  static const std::vector<TextureType> types = {constantTextureType(), checkerTextureType(),
                                                 marbleTextureType(), imageTextureType()};
  return types;
}

const TextureType* findTextureType(const std::string& name) {
  for (const TextureType& t : textureTypes())
    if (t.name == name) return &t;
  return nullptr;
}

std::string textureTypeList() {
  const auto& types = textureTypes();
  std::string list;
  for (size_t i = 0; i < types.size(); ++i)
    list += (i == 0 ? "" : i + 1 == types.size() ? " or " : ", ") + types[i].name;
  return list;
}

const KeyList& textureCommonKeys() {
  static const KeyList keys = {{"type",
                                {},
                                ValueType::String,
                                "a texture type's name (any letter case)",
                                "required",
                                "the texture type"}};
  return keys;
}

}  // namespace verity

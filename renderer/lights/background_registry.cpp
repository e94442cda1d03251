#include "lights/background_registry.h"

#include "params/json_node.h"

namespace verity {

namespace {

BackgroundType constantBackground() {
  return {"constant",
          "the same radiance from every direction",
          {{"color",
            {},
            ValueType::Rgb,
            "each channel >= 0",
            "required",
            "the radiance arriving from every direction"}},
          [](const JsonNode& node) {
            const JsonNode color = node[{"color"}];
            const Vector3f c = color.asVector3();
            if ((c.array() < 0).any()) color.fail("background radiance must not be negative");
            return std::make_unique<EnvironmentLight>(Color3(c.array()));
          }};
}

BackgroundType imageBackground() {
  return {"image",
          "a latitude-longitude image, importance-sampled by luminance",
          {{"filename",
            {},
            ValueType::String,
            "an image file, relative to the scene file",
            "required",
            "the radiance map: its top row is straight up (+y), its columns run once around y"}},
          [](const JsonNode& node) {
            const JsonNode file = node[{"filename"}];
            try {
              return std::make_unique<EnvironmentLight>(
                  std::make_shared<ImageTexture>(node.resolve(file.asString()), file.path()));
            } catch (const VerityError& e) {
              if (!e.file().empty()) throw;
              throw VerityError(node.file().string(), e.jsonPath(), e.problem());
            }
          }};
}

}  // namespace

const std::vector<BackgroundType>& backgroundTypes() {
  static const std::vector<BackgroundType> types = {constantBackground(), imageBackground()};
  return types;
}

const BackgroundType* findBackgroundType(const std::string& name) {
  for (const BackgroundType& t : backgroundTypes())
    if (t.name == name) return &t;
  return nullptr;
}

std::string backgroundTypeList() {
  const auto& types = backgroundTypes();
  std::string list;
  for (size_t i = 0; i < types.size(); ++i)
    list += (i == 0 ? "" : i + 1 == types.size() ? " or " : ", ") + types[i].name;
  return list;
}

const KeyList& backgroundCommonKeys() {
  static const KeyList keys = {{"type",
                                {},
                                ValueType::String,
                                "a background type's name (any letter case)",
                                "required",
                                "the background type"}};
  return keys;
}

}  // namespace verity

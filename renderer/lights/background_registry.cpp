#include "lights/background_registry.h"

#include "params/key.h"

namespace verity {

namespace {

const Key<Color3> kBackgroundColor{.name = "color",
                                   .allowed = Range::nonNegative(),
                                   .meaning = "the radiance arriving from every direction"};

BackgroundType constantBackground() {
  return {"constant",
          {},
          "the same radiance from every direction",
          declarations(kBackgroundColor),
          [](const JsonNode& node) {
            return std::make_unique<EnvironmentLight>(node.get(kBackgroundColor));
          }};
}

const Key<std::string> kBackgroundFile{
    .name = "filename",
    .allowed = "an image file, relative to the scene file",
    .meaning = "the radiance map: its top row is straight up (+y), its columns run once around y"};

BackgroundType imageBackground() {
  return {"image",
          {},
          "a latitude-longitude image, importance-sampled by luminance",
          declarations(kBackgroundFile),
          [](const JsonNode& node) {
            const JsonNode file = node[kBackgroundFile];
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

const Registry<BackgroundType>& backgroundTypes() {
  static const Registry<BackgroundType> types("background type",
                                              {constantBackground(), imageBackground()});
  return types;
}

const KeyList& backgroundCommonKeys() {
  static const KeyList keys = {backgroundTypes().typeKey()};
  return keys;
}

}  // namespace verity

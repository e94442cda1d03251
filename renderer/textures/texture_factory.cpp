#include "textures/texture_factory.h"

#include "scene/scene.h"
#include "scene/transform_parser.h"
#include "textures/checker.h"
#include "textures/image_texture.h"
#include "textures/marble.h"

namespace verity {

namespace {
// A solid texture's optional `transform`: its frame in the world.
SolidMapping parseMapping(const JsonNode& node) {
  return node.has({"transform"}) ? SolidMapping(parseOptionalTransform(node)) : SolidMapping();
}
}  // namespace

TexturedColor TextureFactory::parse(const JsonNode& node) {
  if (node.isNumber() || node.isArray()) {
    const Vector3f v = node.asVector3();
    if ((v.array() < 0).any()) node.fail("a colour must not be negative");
    return TexturedColor(Color3(v.array()));
  }
  if (!node.isObject()) node.fail("expected a number, [r,g,b] or a texture object");
  const std::string type = node.type();
  TexturedColor result;
  if (type == "constant") {
    result = parse(node[{"color", "value"}]);
  } else if (type == "checker") {
    TexturedColor even = parse(node, {"even"}, Color3::Ones());
    TexturedColor odd = parse(node, {"odd"}, Color3::Zero());
    const float scale = node.getFloat({"scale"}, 1.0f, Range::positive());
    result = TexturedColor(std::make_shared<CheckerTexture>(even, odd, scale, parseMapping(node)));
  } else if (type == "marble") {
    TexturedColor veins = parse(node, {"veins"}, Color3::Constant(0.1f));
    TexturedColor base = parse(node, {"base"}, Color3::Constant(0.9f));
    // Beyond this scale a point at the largest coordinate a scene may hold overflows to
    // infinity, and the veins' sine of it is NaN.
    constexpr float kMaxScale = std::numeric_limits<float>::max() / kMaxSceneCoordinate;
    const float scale = node.getFloat({"scale"}, 1.0f, Range{0.0f, kMaxScale, true, false});
    result = TexturedColor(std::make_shared<MarbleTexture>(veins, base, scale, parseMapping(node)));
  } else if (type == "image") {
    const JsonNode fileNode = node[{"filename"}];
    const std::string path = node.resolve(fileNode.asString()).string();
    auto& image = images_[path];
    if (!image) {
      try {
        image = std::make_shared<ImageTexture>(path, fileNode.path());
      } catch (const VerityError& e) {
        throw VerityError(node.file().string(), e.jsonPath(), e.problem());
      }
    }
    result = TexturedColor(image);
  } else {
    node[{"type"}].fail("unknown texture type \"" + type + "\"");
  }
  node.rejectUnknownKeys();
  return result;
}

TexturedColor TextureFactory::parse(const JsonNode& parent, Keys keys, const Color3& def) {
  auto node = parent.find(keys);
  return node ? parse(*node) : TexturedColor(def);
}

}  // namespace verity

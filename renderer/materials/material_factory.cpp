#include "materials/material_factory.h"

#include <fmt/format.h>

#include "materials/material_keys.h"
#include "materials/material_registry.h"

namespace verity {

TexturedColor MaterialFactory::parseAlbedo(const JsonNode& node) {
  TexturedColor albedo = textures_.parse(node, kAlbedo);
  const float bound = albedo.upperBound();
  if (bound > 1)
    warn(node[kAlbedo].warning(fmt::format(
        "{} {:g}, above 1: the surface reflects more light than reaches it (a white furnace "
        "would gain energy)",
        albedo.isConstant() ? "an albedo of" : "a texture that reaches", bound)));
  return albedo;
}

std::shared_ptr<const Material> MaterialFactory::make(const JsonNode& node) {
  node.find({"name"});  // the name is read by the scene loader
  const MaterialType& entry = materialTypes().get(node[{"type"}]);
  node.declare({"material " + entry.name, {&materialCommonKeys(), &entry.keys}});
  std::shared_ptr<const Material> material = entry.build(*this, node);
  node.rejectUnknownKeys();
  return material;
}

void MaterialFactory::addNamed(const JsonNode& nameNode, std::shared_ptr<const Material> material) {
  const std::string name = nameNode.asString();
  if (!named_.emplace(name, std::move(material)).second)
    nameNode.fail("a material named \"" + name + "\" is already defined");
}

std::shared_ptr<const Material> MaterialFactory::reference(const JsonNode& node) {
  if (node.isString()) {
    const std::string name = node.asString();
    auto it = named_.find(name);
    if (it == named_.end() && listed_.count(name))
      node.fail("\"" + name +
                "\" is this material or one defined after it: a blend may name only materials "
                "defined before it in \"materials\"");
    if (it == named_.end()) node.fail("no material is named \"" + name + "\"");
    return it->second;
  }
  if (!node.isObject()) node.fail("expected a material name or a material object");
  return make(node);
}

}  // namespace verity

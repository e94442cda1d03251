#include "materials/material_factory.h"

#include "materials/diffuse_light.h"
#include "materials/lambertian.h"

namespace verity {

std::shared_ptr<const Material> MaterialFactory::make(const JsonNode& node) {
  const std::string type = node.type();
  node.find({"name"});  // the name is read by the scene loader
  std::shared_ptr<const Material> material;
  if (type == "lambertian") {
    material = std::make_shared<Lambertian>(textures_.parse(node, {"albedo"}, Color3::Constant(0.8f)));
  } else if (type == "diffuse light" || type == "diffuse_light") {
    const Color3 emit = node.getVector3({"emit"}, Vector3f::Ones()).array();
    if (!(emit >= 0).all()) node[{"emit"}].fail("emitted radiance must not be negative");
    material = std::make_shared<DiffuseLight>(emit);
  } else {
    node[{"type"}].fail("unknown material type \"" + type + "\"");
  }
  node.rejectUnknownKeys();
  return material;
}

void MaterialFactory::addNamed(const std::string& name, std::shared_ptr<const Material> material) {
  named_[name] = std::move(material);
}

std::shared_ptr<const Material> MaterialFactory::reference(const JsonNode& node) {
  if (node.isString()) {
    const std::string name = node.asString();
    auto it = named_.find(name);
    if (it == named_.end()) node.fail("no material is named \"" + name + "\"");
    return it->second;
  }
  if (!node.isObject()) node.fail("expected a material name or a material object");
  return make(node);
}

}  // namespace verity

// The BSDF sweep must hold every material type of the registry: a type added to the scene
// format without chi-square cases fails here. The types it cannot test are a named list.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "chi2/suite/suite.h"
#include "materials/material_registry.h"
#include "params/json_node.h"

namespace verity::chi2 {
namespace {

// Types whose sampling a histogram of scattered directions cannot check, and where they
// are checked instead.
const std::map<std::string, std::string> kNotInBsdfSweep = {
    {"dielectric",
     "only delta lobes (no histogram sees them); its Fresnel choice and 1/eta² scaling are "
     "checked in renderer/materials/tests (Dielectric.FresnelChoiceAndScaling)"},
    {"diffuse_light", "scatters nothing; the emitters it makes are sampled by the light cases"},
};

// The canonical type of each BSDF case's top-level material.
std::set<std::string> sweptTypes() {
  std::set<std::string> types;
  for (const suite::BsdfCase& c : suite::bsdfCases()) {
    const std::string spelling = JsonNode::parse(c.json, c.name).type();
    const MaterialType* t = findMaterialType(spelling);
    EXPECT_NE(t, nullptr) << c.name << ": " << spelling;
    if (t) types.insert(t->name);
  }
  return types;
}

TEST(FrameworkCoverage, EveryMaterialTypeIsInTheBsdfSweep) {
  const std::set<std::string> swept = sweptTypes();
  for (const MaterialType& t : materialTypes()) {
    if (kNotInBsdfSweep.count(t.name)) {
      EXPECT_FALSE(swept.count(t.name)) << t.name << " is swept: remove it from kNotInBsdfSweep";
      continue;
    }
    EXPECT_TRUE(swept.count(t.name))
        << "material type \"" << t.name << "\" has no case in chi2/suite.cpp bsdfCases()";
  }
  for (const auto& [name, why] : kNotInBsdfSweep)
    EXPECT_NE(findMaterialType(name), nullptr) << name << " is no longer a material type";
}

}  // namespace
}  // namespace verity::chi2

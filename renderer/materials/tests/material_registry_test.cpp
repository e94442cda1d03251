// The material registry: every name and alias builds its type, no spelling belongs to two
// types, and the unknown-type error and the help list every type.
#include "materials/material_registry.h"

#include <gtest/gtest.h>

#include <set>

#include "materials/tests/material_test_util.h"

namespace verity::test {
namespace {

// Blend needs its two materials; every other type builds from its defaults.
std::string minimalJson(const std::string& spelling) {
  if (findMaterialType(spelling) && findMaterialType(spelling)->name == "blend")
    return R"({"type":")" + spelling + R"(","a":{"type":"lambertian"},"b":{"type":"lambertian"}})";
  return R"({"type":")" + spelling + R"("})";
}

TEST(MaterialRegistry, EverySpellingBuildsItsOwnType) {
  std::set<std::string> spellings;
  ASSERT_GE(materialTypes().size(), 11u);
  for (const MaterialType& t : materialTypes()) {
    EXPECT_FALSE(t.description.empty()) << t.name;
    ASSERT_NE(t.build, nullptr) << t.name;
    std::vector<std::string> all = t.aliases;
    all.push_back(t.name);
    for (const std::string& s : all) {
      EXPECT_TRUE(spellings.insert(s).second) << "\"" << s << "\" names two types";
      EXPECT_EQ(findMaterialType(s), &t) << s;
      EXPECT_NO_THROW(makeMaterial(minimalJson(s))) << s;
    }
  }
  // The scene format's type is case-insensitive (JsonNode::type() lower-cases it).
  EXPECT_NO_THROW(makeMaterial(R"({"type":"Blinn-Phong"})"));
  EXPECT_EQ(findMaterialType("velvet"), nullptr);
}

TEST(MaterialRegistry, UnknownTypeErrorAndHelpListEveryType) {
  std::string message;
  try {
    makeMaterial(R"({"type":"velvet"})");
  } catch (const VerityError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("type: unknown material type \"velvet\""), std::string::npos) << message;
  const std::string help = materialTypes().help();
  for (const MaterialType& t : materialTypes()) {
    EXPECT_NE(message.find(t.name), std::string::npos) << message;
    EXPECT_NE(help.find(t.name + (t.aliases.empty() ? ":" : " (")), std::string::npos) << help;
    for (const std::string& alias : t.aliases) EXPECT_NE(help.find(alias), std::string::npos);
  }
}

}  // namespace
}  // namespace verity::test

// The registry of a family's types: one rule for names (canonical name or other spelling,
// any letter case, a space read as an underscore), an unknown name an error that names the
// file and path (or the option) and lists every known name, and help from the entries.
#include "params/registry.h"

#include <gtest/gtest.h>

#include "testing/error_of.h"

namespace verity {
namespace {

struct Fruit {
  std::string name;
  std::vector<std::string> aliases;
  std::string description;
  KeyList keys;
};

const Registry<Fruit>& fruits() {
  static const Registry<Fruit> table(
      "fruit type",
      {{"apple", {}, "round", {{"size", {}, ValueType::Number, "> 0", "1", "its size"}}},
       {"blood_orange", {"moro"}, "red inside", {}}},
      {"basket"});
  return table;
}

TEST(Registry, FindsATypeByAnySpellingUnderOneRule) {
  const Fruit* orange = &*std::next(fruits().begin());
  EXPECT_EQ(fruits().find("apple"), &fruits().front());
  EXPECT_EQ(fruits().find("APPLE"), &fruits().front());
  EXPECT_EQ(fruits().find("blood_orange"), orange);
  EXPECT_EQ(fruits().find("Blood Orange"), orange);
  EXPECT_EQ(fruits().find("Moro"), orange);
  EXPECT_EQ(fruits().find("blood-orange"), nullptr);
  EXPECT_EQ(fruits().find("pear"), nullptr);
  EXPECT_EQ(fruits().find("basket"), nullptr);  // read by the family's reader, not the table
  EXPECT_EQ(typeNameKey("Path Tracer MIS"), "path_tracer_mis");
}

TEST(Registry, AnUnknownNameIsAnErrorListingTheKnownNames) {
  const JsonNode root = JsonNode::parse(R"({"fruit": {"type": "Pear"}})", "/tmp/fruit.json");
  EXPECT_EQ(errorOf([&] { fruits().get(root[{"fruit"}][{"type"}]); }),
            "/tmp/fruit.json: fruit.type: unknown fruit type \"Pear\" (expected one of apple, "
            "blood_orange, basket)");
  EXPECT_EQ(errorOf([] { fruits().get("pear", "--fruit"); }),
            "--fruit: unknown fruit type \"pear\" (expected one of apple, blood_orange, basket)");
  EXPECT_EQ(&fruits().get("MORO", "--fruit"), &*std::next(fruits().begin()));
}

TEST(Registry, HelpAndTypeKeyComeFromTheEntries) {
  EXPECT_EQ(fruits().help(), "  apple: round; size (1)\n  blood_orange (moro): red inside\n");
  EXPECT_EQ(fruits().names(), "apple, blood_orange, basket");
  const KeyDeclaration type = fruits().typeKey();
  EXPECT_EQ(type.name, "type");
  EXPECT_EQ(type.defaultValue, "required");
  EXPECT_EQ(type.meaning, "the fruit type");
}

}  // namespace
}  // namespace verity

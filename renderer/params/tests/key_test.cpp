// The typed key: one declaration gives the value read (its default when absent), the range
// check and the words of its error (naming the file and the JSON path), and the row of the
// scene-format tables.
#include "params/key.h"

#include <gtest/gtest.h>

#include "testing/error_of.h"

namespace verity {
namespace {

enum class Flavour { Sweet, Sour };

const Key<float> kPower{.name = "power",
                        .defaultValue = 1,
                        .allowed = {0, 16, true, false},
                        .meaning = "the heuristic's exponent"};
const Key<int> kDepth{.name = "rr_depth",
                      .aliases = {"rr depth"},
                      .defaultValue = 5,
                      .allowed = {1, std::numeric_limits<int>::max()},
                      .meaning = "the roulette's first event"};
const Key<std::string> kFile{.name = "filename", .allowed = "a file", .meaning = "the file"};
const Key<Flavour> kFlavour{.name = "flavour",
                            .defaultValue = Flavour::Sour,
                            .allowed = {{"sweet", Flavour::Sweet}, {"sour", Flavour::Sour}},
                            .meaning = "the taste"};

JsonNode object(const std::string& json) {
  return JsonNode::parse(R"({"thing": )" + json + "}", "/tmp/key.json")[{"thing"}];
}

TEST(TypedKey, ReadsTheValueGivenOrItsDefault) {
  EXPECT_EQ(object(R"({"power": 2.5})").get(kPower), 2.5f);
  EXPECT_EQ(object("{}").get(kPower), 1.0f);
  EXPECT_EQ(object(R"({"rr depth": 3})").get(kDepth), 3);
  EXPECT_EQ(object("{}").get(kDepth), 5);
  EXPECT_EQ(object(R"({"filename": "a.obj"})").get(kFile), "a.obj");
  EXPECT_EQ(object(R"({"flavour": "sweet"})").get(kFlavour), Flavour::Sweet);
  EXPECT_EQ(object("{}").get(kFlavour), Flavour::Sour);
}

TEST(TypedKey, AValueOutsideItsRangeIsAnErrorNamingThePathAndTheRange) {
  EXPECT_EQ(errorOf([] { object(R"({"power": 0})").get(kPower); }),
            "/tmp/key.json: thing.power: expected a number in (0, 16], found 0");
  EXPECT_EQ(errorOf([] { object(R"({"power": 16})").get(kPower); }), "");
  EXPECT_EQ(errorOf([] { object(R"({"rr_depth": 0})").get(kDepth); }),
            "/tmp/key.json: thing.rr_depth: expected an integer >= 1, found 0");
  EXPECT_EQ(errorOf([] { object(R"({"flavour": "bitter"})").get(kFlavour); }),
            "/tmp/key.json: thing.flavour: expected \"sweet\" or \"sour\", found \"bitter\"");
  EXPECT_EQ(errorOf([] { object("{}").get(kFile); }),
            "/tmp/key.json: thing: missing required key \"filename\"");
}

TEST(TypedKey, ItsDeclarationIsTheDocumentsRow) {
  const KeyDeclaration power = kPower.declaration();
  EXPECT_EQ(power.name, "power");
  EXPECT_EQ(power.type, ValueType::Number);
  EXPECT_EQ(power.range, "(0, 16]");
  EXPECT_EQ(power.defaultValue, "1");
  EXPECT_EQ(power.meaning, "the heuristic's exponent");
  const KeyDeclaration depth = kDepth.declaration();
  EXPECT_EQ(depth.aliases, std::vector<std::string>{"rr depth"});
  EXPECT_EQ(depth.type, ValueType::Integer);
  EXPECT_EQ(depth.range, ">= 1");
  EXPECT_EQ(depth.defaultValue, "5");
  EXPECT_EQ(kFile.declaration().defaultValue, "required");
  EXPECT_EQ(kFile.declaration().range, "a file");
  EXPECT_EQ(kFlavour.declaration().range, "\"sweet\" or \"sour\"");
  EXPECT_EQ(kFlavour.declaration().defaultValue, "\"sour\"");
  EXPECT_EQ(kPower.described("other words").declaration().meaning, "other words");
  const Key<float> far{.name = "fdist", .defaultValue = 1, .allowed = {0, 1e15f, true, false}};
  EXPECT_EQ(far.declaration().range, "(0, 1e15]");
}

TEST(TypedKey, AnObjectThatDeclaresItsKeysIsReadByTheDeclaration) {
  static const KeyList keys = declarations(kPower, kDepth);
  const JsonNode node = object(R"({"power": 2, "rr depth": 4})");
  node.declare({"thing", {&keys}});
  EXPECT_EQ(node.get(kPower), 2.0f);
  EXPECT_EQ(node.get(kDepth), 4);
  EXPECT_THROW(node.get(kFile), std::logic_error);
}

}  // namespace
}  // namespace verity

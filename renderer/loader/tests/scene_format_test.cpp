// docs/scene-format.md against the registries: its generated key tables are what the
// registries declare, every example in it loads through the real loader, and the examples of
// each type use every key the type declares. With JsonNode's refusal of undeclared reads, the
// document, the declarations and the readers agree.
#include "loader/scene_format.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "loader/scene_loader.h"
#include "params/json_node.h"
#include "params/key.h"
#include "testing/error_of.h"

namespace verity {
namespace {

const std::string kDocument = "docs/scene-format.md";

std::string readDocument() {
  std::ifstream in(std::string(VERITY_SOURCE_DIR) + "/" + kDocument, std::ios::binary);
  EXPECT_TRUE(in) << "cannot open " << kDocument;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The first difference of two texts, with a little of what surrounds it.
std::string firstDifference(const std::string& written, const std::string& generated) {
  const auto a = lines(written), b = lines(generated);
  size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  std::string report = "first difference at line " + std::to_string(i + 1) + ":\n";
  for (size_t j = i; j < std::min(a.size(), i + 4); ++j) report += "- " + a[j] + "\n";
  for (size_t j = i; j < std::min(b.size(), i + 4); ++j) report += "+ " + b[j] + "\n";
  return report;
}

TEST(SceneFormatDocument, GeneratedTablesMatchTheRegistries) {
  const std::string doc = readDocument();
  const std::string generated = regenerateSceneFormat(doc, kDocument);
  EXPECT_TRUE(doc == generated)
      << kDocument << ": the key tables differ from the registries' declarations; regenerate "
      << "them with `scene_format_tables " << kDocument << "` (build/bin/, from the source "
      << "folder) and review the change.\n"
      << firstDifference(doc, generated);
}

TEST(SceneFormatDocument, RegenerationRefusesAMissingOrUnknownBlock) {
  const std::string doc = readDocument();
  const std::string block = "<!-- keys material lambertian -->";
  ASSERT_NE(doc.find(block), std::string::npos);
  std::string renamed = doc;
  renamed.replace(renamed.find(block), block.size(), "<!-- keys material velvet -->");
  EXPECT_NE(errorOf([&] {
              regenerateSceneFormat(renamed, kDocument);
            }).find("the material family has no type named \"velvet\""),
            std::string::npos);
  std::string dropped = doc;
  dropped.replace(dropped.find(block), block.size(), "");
  EXPECT_NE(errorOf([&] {
              regenerateSceneFormat(dropped, kDocument);
            }).find("no block <!-- keys material lambertian -->"),
            std::string::npos);
}

// An example of the document: a ```json block whose info string names the family.
struct Example {
  std::string family;
  nlohmann::json value;
  size_t line;
};

std::vector<Example> examples(const std::string& doc) {
  std::vector<Example> out;
  const auto all = lines(doc);
  for (size_t i = 0; i < all.size(); ++i) {
    if (all[i].rfind("```json ", 0) != 0) continue;
    std::string text;
    size_t j = i + 1;
    for (; j < all.size() && all[j] != "```"; ++j) text += all[j] + "\n";
    out.push_back({all[i].substr(8), nlohmann::json::parse(text), i + 1});
    i = j;
  }
  return out;
}

// A scene that holds `e` where its family belongs. Material examples are listed with every
// material example before them, so that a blend can name an earlier one; surfaces may name
// any material example.
std::string sceneOf(const Example& e, const nlohmann::json& materialsBefore,
                    const nlohmann::json& allMaterials) {
  using nlohmann::json;
  const json camera = json::object();
  const json lambertian = {{"type", "lambertian"}};
  json scene = {{"camera", camera}};
  if (e.family == "scene") {
    scene = e.value;
  } else if (e.family == "camera") {
    scene["camera"] = e.value;
  } else if (e.family == "transform") {
    scene["surfaces"] = {{{"type", "quad"}, {"transform", e.value}, {"material", lambertian}}};
  } else if (e.family == "surface") {
    scene["materials"] = allMaterials;
    scene["surfaces"] = {e.value};
  } else if (e.family == "material") {
    scene["materials"] = materialsBefore;
    scene["materials"].push_back(e.value);
  } else if (e.family == "texture") {
    scene["surfaces"] = {
        {{"type", "sphere"}, {"material", {{"type", "lambertian"}, {"albedo", e.value}}}}};
  } else {
    // background, integrator, sampler: members of the top level.
    scene[e.family] = e.value;
  }
  return scene.dump(2);
}

std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

TEST(SceneFormatDocument, EveryExampleLoadsAndTheExamplesUseEveryDeclaredKey) {
  const std::string doc = readDocument();
  const auto all = examples(doc);
  ASSERT_FALSE(all.empty());
  nlohmann::json allMaterials = nlohmann::json::array();
  for (const Example& e : all)
    if (e.family == "material") allMaterials.push_back(e.value);

  // The keys the examples give, per family ("" for the family's own keys) and type.
  std::map<std::string, std::map<std::string, std::set<std::string>>> used;
  nlohmann::json materialsBefore = nlohmann::json::array();
  // Scene files beside the project's scenes, so that their meshes and textures resolve.
  const std::string file = std::string(VERITY_SOURCE_DIR) + "/scenes/scene-format-example.json";
  for (const Example& e : all) {
    SCOPED_TRACE(kDocument + ", the example at line " + std::to_string(e.line));
    const std::string scene = sceneOf(e, materialsBefore, allMaterials);
    EXPECT_EQ(errorOf([&] { loadSceneText(scene, file); }), "") << scene;
    if (e.family == "material") materialsBefore.push_back(e.value);

    // A surface is a group or a shape; both take the surface family's keys.
    std::vector<std::string> families = {e.family};
    std::string type;
    if (e.value.is_object() && e.value.contains("type")) type = lowerCase(e.value["type"]);
    if (e.family == "surface" && type != "group") families.push_back("shape");
    for (const std::string& familyName : families) {
      const FormatFamily* family = findFormatFamily(familyName);
      ASSERT_TRUE(family) << "no family \"" << familyName << "\"";
      // A transform example may be an array of transform objects.
      std::vector<nlohmann::json> objects = {e.value};
      if (e.value.is_array()) objects.assign(e.value.begin(), e.value.end());
      for (const nlohmann::json& object : objects)
        for (const auto& item : object.items()) used[familyName][""].insert(item.key());
      if (family->types.empty()) continue;
      std::string spelled = type;
      if (familyName == "integrator") std::replace(spelled.begin(), spelled.end(), ' ', '_');
      // A sampler without a type is the default (the first) one.
      if (spelled.empty() && familyName == "sampler") spelled = family->types.front().name;
      // A shape's type is not among the surface family's own types (group), nor the reverse.
      const FormatType* t = findFormatType(*family, spelled);
      if (!t) continue;
      for (const auto& item : e.value.items()) used[familyName][t->name].insert(item.key());
    }
  }

  auto covered = [&](const std::set<std::string>& keys, const KeyDeclaration& k) {
    if (keys.count(k.name)) return true;
    return std::any_of(k.aliases.begin(), k.aliases.end(),
                       [&](const std::string& a) { return keys.count(a) > 0; });
  };
  for (const FormatFamily& family : sceneFormatFamilies()) {
    for (const KeyDeclaration& k : *family.common)
      EXPECT_TRUE(covered(used[family.name][""], k))
          << "no " << family.name << " example in " << kDocument << " gives \"" << k.name << "\"";
    for (const FormatType& type : family.types) {
      EXPECT_TRUE(used[family.name].count(type.name))
          << "no " << family.name << " example in " << kDocument << " is a " << type.name;
      for (const KeyDeclaration& k : *type.keys)
        EXPECT_TRUE(covered(used[family.name][type.name], k))
            << "no example of " << family.name << " " << type.name << " in " << kDocument
            << " gives \"" << k.name << "\"";
    }
  }
}

TEST(SceneFormatDocument, UnknownKeyErrorPointsToTheDocument) {
  const std::string message = errorOf([] {
    loadSceneText(R"({"camera": {}, "surfaces": [{"type": "sphere",
                     "material": {"type": "lambertian", "albdo": 0.5}}]})",
                  "/tmp/typo.json");
  });
  EXPECT_NE(message.find("surfaces[0].material.albdo: unknown key \"albdo\" (the keys of "
                         "material lambertian are listed in docs/scene-format.md)"),
            std::string::npos)
      << message;
}

// Every kind of object declares its type's keys when the loader reads it, so that a typo in
// any of them is reported as a key of that type, with the pointer to the document.
TEST(SceneFormatDocument, EveryKindOfObjectNamesItsKeysInTheUnknownKeyError) {
  struct Case {
    std::string members;  // of the top level, besides the camera
    std::string where;    // the JSON path of the misspelt key
    std::string owner;    // how the error names the object
  };
  const std::vector<Case> cases = {
      {R"("colour": 1)", "colour", "the scene file"},
      {R"("surfaces": [{"type": "quad", "material": {"type": "lambertian"}, "sise": 1}])",
       "surfaces[0].sise", "surface quad"},
      {R"("surfaces": [{"type": "group", "children": [], "child": []}])", "surfaces[0].child",
       "surface group"},
      {R"("surfaces": [{"type": "quad", "transform": {"translate": [0, 1, 0], "rotate": 30},
           "material": {"type": "lambertian"}}])",
       "surfaces[0].transform.rotate", "a transform"},
      {R"("surfaces": [{"type": "quad", "material": {"type": "lambertian",
           "albedo": {"type": "checker", "scales": 2}}}])",
       "surfaces[0].material.albedo.scales", "texture checker"},
      {R"("background": {"type": "constant", "color": 1, "colour": 1})", "background.colour",
       "background constant"},
      {R"("integrator": {"type": "path tracer mis", "rr_dept": 3})", "integrator.rr_dept",
       "integrator path_tracer_mis"},
      {R"("integrator": {"type": "ao", "max_bounces": 3})", "integrator.max_bounces",
       "integrator ao"},
      {R"("sampler": {"type": "stratified", "sample": 4})", "sampler.sample", "sampler stratified"},
      {R"("sampler": {"sample": 4})", "sampler.sample", "sampler independent"},
  };
  for (const Case& c : cases) {
    const std::string message =
        errorOf([&] { loadSceneText(R"({"camera": {}, )" + c.members + "}", "/tmp/typo.json"); });
    const std::string key = c.where.substr(c.where.rfind('.') + 1);
    EXPECT_NE(message.find(c.where + ": unknown key \"" + key + "\" (the keys of " + c.owner +
                           " are listed in docs/scene-format.md)"),
              std::string::npos)
        << message;
  }
  const std::string camera =
      errorOf([] { loadSceneText(R"({"camera": {"fov": 40}})", "/tmp/typo.json"); });
  EXPECT_NE(camera.find("camera.fov: unknown key \"fov\" (the keys of the camera are listed in "
                        "docs/scene-format.md)"),
            std::string::npos)
      << camera;
}

TEST(DeclaredKeys, AReadOfAnUndeclaredKeyOrSpellingIsADefectOfTheReader) {
  static const KeyList keys = {{"alpha", {"ab"}, ValueType::Number, "", "0.1", "roughness"}};
  const auto object = [] {
    JsonNode root = JsonNode::parse(R"({"m": {"alpha": 0.2}})", "/tmp/declared.json");
    JsonNode m = root[{"m"}];
    m.declare({"material test", {&keys}});
    return m;
  };
  const auto key = [](std::string name, std::vector<std::string> aliases) {
    return Key<float>{.name = std::move(name), .aliases = std::move(aliases), .defaultValue = 0.1f};
  };
  EXPECT_EQ(object().get(key("alpha", {"ab"})), 0.2f);
  EXPECT_EQ(object().get(key("ab", {"alpha"})), 0.2f);
  // An undeclared key, absent from the file as well: the read itself is refused.
  EXPECT_THROW(object().get(key("ior", {})), std::logic_error);
  // A declared key by fewer spellings than declared, or by one more.
  EXPECT_THROW(object().get(key("alpha", {})), std::logic_error);
  EXPECT_THROW(object().get(key("alpha", {"ab", "roughness"})), std::logic_error);
  // A key read before the declaration must be among the declared ones.
  JsonNode root = JsonNode::parse(R"({"m": {"alpha": 0.2, "ior": 1.5}})", "/tmp/declared.json");
  JsonNode m = root[{"m"}];
  m.has({"ior"});
  EXPECT_THROW(m.declare({"material test", {&keys}}), std::logic_error);
}

}  // namespace
}  // namespace verity

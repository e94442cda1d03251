#include "loader/scene_format.h"

#include <fmt/format.h>

#include <regex>
#include <set>
#include <sstream>

#include "core/error.h"
#include "integrators/integrator_registry.h"
#include "lights/background_registry.h"
#include "loader/scene_keys.h"
#include "materials/material_registry.h"
#include "params/transform_parser.h"
#include "sampling/sampler_registry.h"
#include "shapes/shape_registry.h"
#include "textures/texture_registry.h"

namespace verity {

namespace {

std::vector<FormatFamily> makeFamilies() {
  std::vector<FormatFamily> families;
  families.push_back({"scene", &sceneKeys(), {}});
  families.push_back({"camera", &cameraKeys(), {}});
  families.push_back({"transform", &transformKeys(), {}});
  families.push_back({"surface",
                      &surfaceCommonKeys(),
                      {{"group", {}, "surfaces placed together by one transform", &groupKeys()}}});
  FormatFamily shapes{"shape", &shapeCommonKeys(), {}};
  for (const ShapeType& t : shapeTypes())
    shapes.types.push_back({t.name, t.aliases, t.description, &t.keys});
  families.push_back(std::move(shapes));
  FormatFamily materials{"material", &materialCommonKeys(), {}};
  for (const MaterialType& t : materialTypes())
    materials.types.push_back({t.name, t.aliases, t.description, &t.keys});
  families.push_back(std::move(materials));
  FormatFamily textures{"texture", &textureCommonKeys(), {}};
  for (const TextureType& t : textureTypes())
    textures.types.push_back({t.name, t.aliases, t.description, &t.keys});
  families.push_back(std::move(textures));
  FormatFamily backgrounds{"background", &backgroundCommonKeys(), {}};
  for (const BackgroundType& t : backgroundTypes())
    backgrounds.types.push_back({t.name, t.aliases, t.description, &t.keys});
  families.push_back(std::move(backgrounds));
  FormatFamily integrators{"integrator", &integratorCommonKeys(), {}};
  for (const IntegratorType& t : integratorTypes())
    integrators.types.push_back({t.name, t.aliases, t.description, &t.keys});
  families.push_back(std::move(integrators));
  FormatFamily samplers{"sampler", &samplerCommonKeys(), {}};
  for (const SamplerType& t : samplerTypes())
    samplers.types.push_back({t.name, t.aliases, t.description, &t.keys});
  families.push_back(std::move(samplers));
  return families;
}

// A table cell: a '|' would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out.empty() ? "—" : out;
}

std::string spellings(const std::string& name, const std::vector<std::string>& aliases) {
  std::string text = "`" + name + "`";
  if (aliases.empty()) return text;
  text += " (or ";
  for (size_t i = 0; i < aliases.size(); ++i) text += (i ? ", `" : "`") + aliases[i] + "`";
  return text + ")";
}

std::string keyTable(const KeyList& keys) {
  std::string table = "| key | value | allowed | default | meaning |\n|---|---|---|---|---|\n";
  for (const KeyDeclaration& k : keys)
    table += fmt::format("| {} | {} | {} | {} | {} |\n", cell(spellings(k.name, k.aliases)),
                         cell(valueTypeText(k.type)), cell(k.range), cell(k.defaultValue),
                         cell(k.meaning));
  return table;
}

std::string typeBlock(const FormatType& type) {
  std::string text = "**" + spellings(type.name, type.aliases) + "**: " + type.description + ".\n";
  if (type.keys->empty()) return text + "\nNo keys of its own.\n";
  return text + "\n" + keyTable(*type.keys);
}

}  // namespace

const std::vector<FormatFamily>& sceneFormatFamilies() {
  static const std::vector<FormatFamily> families = makeFamilies();
  return families;
}

const FormatFamily* findFormatFamily(const std::string& name) {
  for (const FormatFamily& f : sceneFormatFamilies())
    if (f.name == name) return &f;
  return nullptr;
}

const FormatType* findFormatType(const FormatFamily& family, const std::string& spelling) {
  for (const FormatType& t : family.types) {
    if (t.name == spelling) return &t;
    for (const std::string& alias : t.aliases)
      if (alias == spelling) return &t;
  }
  return nullptr;
}

std::string regenerateSceneFormat(const std::string& doc, const std::string& docName) {
  static const std::regex begin(R"(<!-- keys ([a-z_]+)(?: ([^ ]+))? -->)");
  static const std::string end = "<!-- end keys -->";
  std::istringstream in(doc);
  std::string out, line;
  std::set<std::string> seen;
  size_t number = 0;
  auto fail = [&](const std::string& problem) {
    throw VerityError(docName, fmt::format("line {}", number), problem);
  };
  while (std::getline(in, line)) {
    ++number;
    out += line + "\n";
    std::smatch m;
    if (!std::regex_match(line, m, begin)) continue;
    const FormatFamily* family = findFormatFamily(m[1]);
    if (!family) fail("no family of the scene format is named \"" + m[1].str() + "\"");
    std::string generated;
    if (m[2].matched) {
      const FormatType* type = findFormatType(*family, m[2]);
      if (!type || type->name != m[2])
        fail(fmt::format("the {} family has no type named \"{}\"", family->name, m[2].str()));
      generated = typeBlock(*type);
    } else {
      generated = keyTable(*family->common);
    }
    if (!seen.insert(line).second) fail("a second block for the same keys");
    const size_t opened = number;
    bool closed = false;
    while (!closed && std::getline(in, line)) {
      ++number;
      closed = line == end;
    }
    if (!closed)
      throw VerityError(docName, fmt::format("line {}", opened),
                        "the block is not closed by \"" + end + "\"");
    out += generated + end + "\n";
  }
  for (const FormatFamily& family : sceneFormatFamilies()) {
    if (!family.common->empty() && !seen.count("<!-- keys " + family.name + " -->"))
      throw VerityError(docName, "",
                        "no block <!-- keys " + family.name + " --> for the family's keys");
    for (const FormatType& type : family.types)
      if (!seen.count("<!-- keys " + family.name + " " + type.name + " -->"))
        throw VerityError(docName, "",
                          "no block <!-- keys " + family.name + " " + type.name +
                              " --> for a "
                              "registered type");
  }
  return out;
}

}  // namespace verity

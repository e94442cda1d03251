// The scene format as its registries declare it: every family of objects (materials,
// surfaces, integrators, ...), its types and their keys; and the key tables of
// docs/scene-format.md generated from them. Between the document's markers
//   <!-- keys FAMILY -->        the keys every object of the family takes
//   <!-- keys FAMILY TYPE -->   a type's name, other spellings, description and keys
//   <!-- end keys -->
// the text is generated; everything else in the document is written by hand.
#pragma once

#include <string>
#include <vector>

#include "params/key_declaration.h"

namespace verity {

struct FormatType {
  std::string name;
  std::vector<std::string> aliases;
  std::string description;
  const KeyList* keys;
};

struct FormatFamily {
  std::string name;       // as the markers spell it: "material", "surface", ...
  const KeyList* common;  // the keys every object of the family takes (may be empty)
  std::vector<FormatType> types;
};

// Every family, in the document's order.
const std::vector<FormatFamily>& sceneFormatFamilies();
// The family named `name`, or null.
const FormatFamily* findFormatFamily(const std::string& name);
// The type of `family` spelled `spelling` (a name or another spelling), or null.
const FormatType* findFormatType(const FormatFamily& family, const std::string& spelling);

// `doc` with every generated block rewritten from the registries. Throws VerityError naming
// `docName` and the line when a marker names no family or type, a block is not closed or
// repeats another, or a family or type of the registries has no block.
std::string regenerateSceneFormat(const std::string& doc, const std::string& docName);

}  // namespace verity

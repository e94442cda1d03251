// The declaration of one key of a scene-file object: its spellings, the kind of value it
// takes, the values allowed, its default and what it means. Each type of the scene format
// lists its keys beside its definition (a material's in its registry entry, the camera's
// beside its reader); docs/scene-format.md prints these lists as its key tables, and
// JsonNode refuses to read a key that the object's declaration does not list.
#pragma once

#include <string>
#include <vector>

namespace verity {

enum class ValueType {
  Number,
  Integer,
  Boolean,
  String,     // free text or one of the names the range lists
  Rgb,        // a number (grey) or [r, g, b]
  Vector3,    // a number (all three components) or [x, y, z]
  Size2,      // a number (both) or [width, height]
  Texture,    // a number, [r, g, b] or a texture object
  Material,   // a material's name or a material object
  Transform,  // a transform object, or an array of them
  Object,
  Array,
  Any,
};

// How the document names a value type.
const char* valueTypeText(ValueType type);

struct KeyDeclaration {
  std::string name;                  // the canonical spelling
  std::vector<std::string> aliases;  // other accepted spellings of the same key
  ValueType type = ValueType::Number;
  std::string range;         // the values allowed; empty when the value type says it all
  std::string defaultValue;  // "required" when the key must be given
  std::string meaning;
  // The canonical spelling, then the aliases.
  std::vector<std::string> spellings() const;
};

using KeyList = std::vector<KeyDeclaration>;

// The declared keys of one object: the keys common to its family (a material's "type" and
// "name") and its own type's.
struct DeclaredKeys {
  std::string what;  // "material lambertian", "camera": how messages name the object
  std::vector<const KeyList*> lists;
  // The declaration spelled `spelling`, or null.
  const KeyDeclaration* find(const std::string& spelling) const;
};

}  // namespace verity

#include "params/key_declaration.h"

#include <algorithm>

namespace verity {

const char* valueTypeText(ValueType type) {
  switch (type) {
    case ValueType::Number:
      return "number";
    case ValueType::Integer:
      return "integer";
    case ValueType::Boolean:
      return "true or false";
    case ValueType::String:
      return "string";
    case ValueType::Rgb:
      return "number or [r, g, b]";
    case ValueType::Vector3:
      return "number or [x, y, z]";
    case ValueType::Size2:
      return "number or [width, height]";
    case ValueType::Texture:
      return "texture";
    case ValueType::Material:
      return "material";
    case ValueType::Transform:
      return "transform";
    case ValueType::Object:
      return "object";
    case ValueType::Array:
      return "array";
    case ValueType::Any:
      return "any";
  }
  return "";
}

std::vector<std::string> KeyDeclaration::spellings() const {
  std::vector<std::string> all{name};
  all.insert(all.end(), aliases.begin(), aliases.end());
  return all;
}

const KeyDeclaration* DeclaredKeys::find(const std::string& spelling) const {
  for (const KeyList* list : lists)
    for (const KeyDeclaration& key : *list)
      if (key.name == spelling ||
          std::find(key.aliases.begin(), key.aliases.end(), spelling) != key.aliases.end())
        return &key;
  return nullptr;
}

}  // namespace verity

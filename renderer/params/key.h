// A typed key of the scene format, declared once per parameter: its spellings, its default
// (or that it is required), the values allowed and what it means. The one declaration drives
// the reading (JsonNode::get returns a T, checked against the values allowed, an error naming
// the file and the JSON path), the error's words for the values allowed, and the row of the
// generated tables of docs/scene-format.md (declaration()), which JsonNode also uses to refuse
// undeclared keys.
//
//   inline const Key<float> kRadius{.name = "radius", .defaultValue = 1,
//                                   .allowed = Range::positive(), .meaning = "the radius"};
//   const float r = node.get(kRadius);
#pragma once

#include <fmt/format.h>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "params/json_node.h"
#include "params/key_declaration.h"

namespace verity {

// One value of a key whose values are names: "ggx" reads as MicrofacetType::GGX.
template <class E>
struct Choice {
  const char* name;
  E value;
};

// How a value of type T is read, checked and written in the documents. `Allowed` is what a
// key states about its values: a Range for numbers, the names for a choice.
template <class T, class = void>
struct KeyValue;

template <>
struct KeyValue<float> {
  using Allowed = Range;
  static constexpr ValueType type = ValueType::Number;
  static float read(const JsonNode& node, const Range& r) { return node.asFloat(r); }
  static std::string allowedText(const Range& r);
  static std::string text(float v);
};

template <>
struct KeyValue<int> {
  using Allowed = IntRange;
  static constexpr ValueType type = ValueType::Integer;
  static int read(const JsonNode& node, const IntRange& r) { return node.asInt(r.lo, r.hi); }
  static std::string allowedText(const IntRange& r) { return r.interval(); }
  static std::string text(int v) { return std::to_string(v); }
};

template <>
struct KeyValue<std::string> {
  using Allowed = std::string;  // in words: "an image file, relative to the scene file"
  static constexpr ValueType type = ValueType::String;
  static std::string read(const JsonNode& node, const std::string&) { return node.asString(); }
  static std::string allowedText(const std::string& words) { return words; }
  static std::string text(const std::string& v) { return "\"" + v + "\""; }
};

// A number (all three components) or [x, y, z], each component in the range.
template <>
struct KeyValue<Vector3f> {
  using Allowed = Range;
  static constexpr ValueType type = ValueType::Vector3;
  static Vector3f read(const JsonNode& node, const Range& r) { return node.asVector3(r); }
  static std::string allowedText(const Range& r);
  static std::string text(const Vector3f& v);
};

// A number (grey) or [r, g, b], each channel in the range.
template <>
struct KeyValue<Color3> {
  using Allowed = Range;
  static constexpr ValueType type = ValueType::Rgb;
  static Color3 read(const JsonNode& node, const Range& r) { return node.asVector3(r).array(); }
  static std::string allowedText(const Range& r);
  static std::string text(const Color3& v);
};

// A number (both sides) or [width, height], each in the range.
template <>
struct KeyValue<Vector2f> {
  using Allowed = Range;
  static constexpr ValueType type = ValueType::Size2;
  static Vector2f read(const JsonNode& node, const Range& r);
  static std::string allowedText(const Range& r) { return "each " + r.interval(); }
  static std::string text(const Vector2f& v);
};

// [width, height]: two integers, each in the range.
template <>
struct KeyValue<Vector2i> {
  using Allowed = IntRange;
  static constexpr ValueType type = ValueType::Array;
  static Vector2i read(const JsonNode& node, const IntRange& r) {
    return node.asVector2i(r.lo, r.hi);
  }
  static std::string allowedText(const IntRange& r) {
    return "[width, height], each " + r.describe();
  }
  static std::string text(const Vector2i& v) { return fmt::format("[{}, {}]", v.x(), v.y()); }
};

template <class E>
struct KeyValue<E, std::enable_if_t<std::is_enum_v<E>>> {
  using Allowed = std::vector<Choice<E>>;
  static constexpr ValueType type = ValueType::String;
  static E read(const JsonNode& node, const Allowed& choices) {
    const std::string name = node.asString();
    for (const Choice<E>& c : choices)
      if (name == c.name) return c.value;
    node.fail(fmt::format("expected {}, found \"{}\"", allowedText(choices), name));
  }
  // "\"ggx\" or \"beckmann\"".
  static std::string allowedText(const Allowed& choices) {
    std::string text;
    for (size_t i = 0; i < choices.size(); ++i)
      text += std::string(i == 0                    ? ""
                          : i + 1 == choices.size() ? " or "
                                                    : ", ") +
              "\"" + choices[i].name + "\"";
    return text;
  }
  static std::string text(E v, const Allowed& choices) {
    for (const Choice<E>& c : choices)
      if (c.value == v) return std::string("\"") + c.name + "\"";
    return "";
  }
};

template <class T>
struct Key {
  std::string name;                    // the canonical spelling
  std::vector<std::string> aliases{};  // other accepted spellings of the same key
  std::optional<T> defaultValue{};     // none: the key is required
  typename KeyValue<T>::Allowed allowed{};
  std::string meaning{};
  // For the documents, where the value alone does not say it all: the default in words
  // ("\"image_samples\", else 1"), and what the reader checks besides `allowed`.
  std::string defaultText{};
  std::string alsoAllowed{};

  // This key as a type lists it, with its own words for what it means there (a shared
  // "albedo" scales a different quantity in each material).
  Key described(std::string typeMeaning) const {
    Key k = *this;
    k.meaning = std::move(typeMeaning);
    return k;
  }

  // This key as a type lists it, with its own default.
  Key withDefault(T value) const {
    Key k = *this;
    k.defaultValue = value;
    return k;
  }

  std::vector<std::string> spellings() const {
    std::vector<std::string> all{name};
    all.insert(all.end(), aliases.begin(), aliases.end());
    return all;
  }

  KeyDeclaration declaration() const {
    std::string range = KeyValue<T>::allowedText(allowed);
    if (!alsoAllowed.empty()) range += (range.empty() ? "" : "; ") + alsoAllowed;
    std::string def = defaultText;
    if (def.empty()) {
      if (!defaultValue)
        def = "required";
      else if constexpr (std::is_enum_v<T>)
        def = KeyValue<T>::text(*defaultValue, allowed);
      else
        def = KeyValue<T>::text(*defaultValue);
    }
    return {name, aliases, KeyValue<T>::type, range, def, meaning};
  }
};

// A key's declaration: a typed key's, or a KeyDeclaration itself (a key whose value another
// reader reads: an object, a transform, a material).
inline const KeyDeclaration& declarationOf(const KeyDeclaration& key) {
  return key;
}
template <class T>
KeyDeclaration declarationOf(const Key<T>& key) {
  return key.declaration();
}

// The declarations of `keys`, typed or not, for a type's KeyList.
template <class... K>
KeyList declarations(const K&... keys) {
  return {declarationOf(keys)...};
}

template <class T>
T JsonNode::get(const Key<T>& key) const {
  const std::optional<JsonNode> node = find(key.spellings());
  if (node) return KeyValue<T>::read(*node, key.allowed);
  if (!key.defaultValue) fail(fmt::format("missing required key \"{}\"", key.name));
  return *key.defaultValue;
}

}  // namespace verity

// The table of the types of one scene-format family (materials, samplers, shapes, textures,
// backgrounds, integrators): each type's entry is defined beside the class it builds, and
// the family's table lists the entries in a fixed order. The table finds a type by any of its
// spellings, names the known types in errors and prints help.
//
// One rule for names, in every family: a spelling names a type when, with letter case
// ignored and spaces read as underscores, it equals the type's name or one of its aliases
// ("Path Tracer MIS" is path_tracer_mis).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "params/json_node.h"
#include "params/key_declaration.h"

namespace verity {

// `spelling` as type names compare: lower case, spaces as underscores.
std::string typeNameKey(std::string_view spelling);

// Entry is an aggregate with `name`, `aliases`, `description` and `keys` (a KeyList).
template <class Entry>
class Registry {
 public:
  // `noun` names a type in errors ("material type"); `otherNames` are names the family's
  // reader handles outside the table (a surface "group"), listed among the known ones.
  Registry(std::string noun, std::vector<Entry> entries, std::vector<std::string> otherNames = {})
      : noun_(std::move(noun)), entries_(std::move(entries)), otherNames_(std::move(otherNames)) {}

  auto begin() const { return entries_.begin(); }
  auto end() const { return entries_.end(); }
  size_t size() const { return entries_.size(); }
  const Entry& front() const { return entries_.front(); }

  // The type spelled `spelling` (see the rule above), or null.
  const Entry* find(std::string_view spelling) const {
    const std::string key = typeNameKey(spelling);
    for (const Entry& e : entries_) {
      if (typeNameKey(e.name) == key) return &e;
      for (const std::string& alias : e.aliases)
        if (typeNameKey(alias) == key) return &e;
    }
    return nullptr;
  }
  // The type that the string `typeNode` names; an unknown name is an error naming the node's
  // file and path and listing the known names.
  const Entry& get(const JsonNode& typeNode) const {
    const std::string spelling = typeNode.asString();
    const Entry* e = find(spelling);
    if (!e) typeNode.fail(unknown(spelling));
    return *e;
  }
  // The type `spelling` names, as a command-line option gives it; an unknown name is an error
  // naming `option` and listing the known names.
  const Entry& get(const std::string& spelling, const std::string& option) const {
    const Entry* e = find(spelling);
    if (!e) throw VerityError("", option, unknown(spelling));
    return *e;
  }
  // The declaration of the family's "type" key, whose values are this table's names.
  KeyDeclaration typeKey(std::string defaultText = "required") const {
    return {"type",
            {},
            ValueType::String,
            "one of the " + noun_ +
                "s below, by name or other spelling (any letter case; a "
                "space reads as _)",
            std::move(defaultText),
            "the " + noun_};
  }
  // "unknown material type "velvet" (expected one of lambertian, ...)".
  std::string unknown(const std::string& spelling) const {
    return "unknown " + noun_ + " \"" + spelling + "\" (expected one of " + names() + ")";
  }
  // The canonical names, then the other names, in table order: "lambertian, diffuse_light".
  std::string names() const {
    std::string list;
    for (const Entry& e : entries_) list += (list.empty() ? "" : ", ") + e.name;
    for (const std::string& n : otherNames_) list += (list.empty() ? "" : ", ") + n;
    return list;
  }
  // One line per type: its names (aliases in parentheses), its description, and its keys
  // with their defaults.
  std::string help() const {
    std::string help;
    for (const Entry& e : entries_) {
      std::string names = e.name;
      for (size_t i = 0; i < e.aliases.size(); ++i)
        names += (i ? ", " : " (") + e.aliases[i] + (i + 1 == e.aliases.size() ? ")" : "");
      std::string keys;
      for (const KeyDeclaration& k : e.keys)
        keys += (keys.empty() ? "; " : ", ") + k.name + " (" + k.defaultValue + ")";
      help += "  " + names + ": " + e.description + keys + "\n";
    }
    return help;
  }

 private:
  std::string noun_;
  std::vector<Entry> entries_;
  std::vector<std::string> otherNames_;
};

}  // namespace verity

// A view of one JSON value that knows its file and JSON path, so that every error it
// raises names both, and that remembers which keys were read so that unknown keys are
// rejected instead of silently ignored. An object whose type declares its keys
// (key_declaration.h) can be read only by the spellings declared.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "params/key_declaration.h"

namespace verity {

// Accepted spellings of one key; the first is the canonical one used in messages.
using Keys = std::initializer_list<const char*>;

template <class T>
struct Key;

// A number as errors and the documents write it: its shortest exact form, with large powers
// as "1e15"; "infinite" for infinity.
std::string numberText(float v);

struct Range {
  float lo = -kInfinity, hi = kInfinity;
  bool loOpen = false, hiOpen = false;

  static Range any() { return {}; }
  static Range positive() { return {0.0f, kInfinity, true, false}; }
  static Range nonNegative() { return {0.0f, kInfinity, false, false}; }
  bool contains(float v) const;
  std::string describe() const;  // "a number in (0, 100]"
  std::string interval() const;  // "(0, 100]", "> 0", "finite": for key declarations
  bool operator==(const Range&) const = default;
};

// The integers allowed: [lo, hi].
struct IntRange {
  int lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
  std::string describe() const;  // "an integer in [0, 16]", "an integer >= 1"
  std::string interval() const;  // "[0, 16]", ">= 1": for key declarations
};

class JsonNode {
 public:
  // Parses a file; syntax errors name the line and column.
  static JsonNode load(const std::filesystem::path& file);
  // Parses text as if it were the file `file` (tests and inline scenes).
  static JsonNode parse(const std::string& text, const std::filesystem::path& file);

  const nlohmann::json& value() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::filesystem::path& file() const { return source_->file; }
  // The error fail() would throw, as a value: a loader warning naming this value.
  VerityError warning(const std::string& problem) const;
  // Resolves a file name relative to the scene file's folder.
  std::filesystem::path resolve(const std::string& name) const;

  bool isObject() const { return value_->is_object(); }
  bool isArray() const { return value_->is_array(); }
  bool isNumber() const { return value_->is_number(); }
  bool isString() const { return value_->is_string(); }
  size_t size() const { return value_->size(); }

  bool has(Keys keys) const;
  JsonNode operator[](Keys keys) const;  // required member
  std::optional<JsonNode> find(Keys keys) const;
  JsonNode operator[](size_t index) const;
  // The member spelled one of `spellings` (the canonical spelling first), or the key declared:
  // a key whose value another reader reads (an object, a texture, a material).
  std::optional<JsonNode> find(const std::vector<std::string>& spellings) const;
  std::optional<JsonNode> find(const KeyDeclaration& key) const { return find(key.spellings()); }
  JsonNode operator[](const KeyDeclaration& key) const;  // required member
  template <class T>
  std::optional<JsonNode> find(const Key<T>& key) const {
    return find(key.spellings());
  }
  template <class T>
  JsonNode operator[](const Key<T>& key) const {
    return (*this)[key.declaration()];
  }
  // The value of a typed key (params/key.h defines it): its default when absent; an error
  // naming the path when it is missing and required, or outside the values allowed.
  template <class T>
  T get(const Key<T>& key) const;

  // Typed reads of this value.
  float asFloat(Range range = Range::any()) const;
  int asInt(int lo, int hi) const;
  std::string asString() const;
  // A number fills all three components; each component must lie in `range`.
  Vector3f asVector3(Range range = Range::any()) const;
  Vector2i asVector2i(int lo, int hi) const;

  // The object's "type", lower-cased, with spaces, hyphens and underscores kept as given.
  std::string type() const;
  // States the keys this object's type declares. Every key read before or after must be
  // declared, by exactly its declared spellings: a read that is not is a defect of the
  // reader, thrown as std::logic_error. `keys` must outlive the document.
  void declare(DeclaredKeys keys) const;
  // Raises an error for the first member that no read asked for.
  void rejectUnknownKeys() const;
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  struct Source {
    std::filesystem::path file;
    // Keys read so far, per JSON object, shared by every view of the document.
    mutable std::map<const nlohmann::json*, std::set<std::string>> used;
    // The declared keys of the objects whose type declares them.
    mutable std::map<const nlohmann::json*, DeclaredKeys> declared;
  };
  void checkDeclared(const std::vector<std::string>& spellings) const;
  JsonNode(std::shared_ptr<const nlohmann::json> root, const nlohmann::json* value,
           std::string path, std::shared_ptr<const Source> source);
  // The spelling among `spellings` that the object gives, or null.
  const std::string* resolveKey(const std::vector<std::string>& spellings) const;

  std::shared_ptr<const nlohmann::json> root_;
  const nlohmann::json* value_;
  std::string path_;
  std::shared_ptr<const Source> source_;
};

}  // namespace verity

#include "params/json_node.h"

#include <fmt/format.h>

#include <cctype>
#include <fstream>
#include <functional>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

namespace verity {

namespace {
std::string typeName(const nlohmann::json& j) {
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  if (j.is_boolean()) return "a boolean";
  return "null";
}

// Line and column (both from 1) of a byte offset.
std::pair<size_t, size_t> lineColumn(const std::string& text, size_t offset) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}
// Scenes nest a few levels (groups, blends, textures); the readers recurse once per level.
constexpr int kMaxNesting = 64;

// The path of a value nested deeper than kMaxNesting (searched without recursion), or
// nullopt when there is none.
std::optional<std::string> tooDeeplyNested(const nlohmann::json& root) {
  struct Entry {
    const nlohmann::json* value;
    std::string path;
    int depth;
  };
  std::vector<Entry> stack{{&root, "", 0}};
  while (!stack.empty()) {
    Entry e = std::move(stack.back());
    stack.pop_back();
    if (e.depth > kMaxNesting) return e.path;
    if (e.value->is_object()) {
      for (const auto& item : e.value->items())
        stack.push_back(
            {&item.value(), e.path.empty() ? item.key() : e.path + "." + item.key(), e.depth + 1});
    } else if (e.value->is_array()) {
      for (size_t i = 0; i < e.value->size(); ++i)
        stack.push_back({&(*e.value)[i], fmt::format("{}[{}]", e.path, i), e.depth + 1});
    }
  }
  return std::nullopt;
}

// Records the first key repeated within one object. nlohmann keeps the last value of a
// repeated key, other readers the first: a scene that says two things must say one.
class DuplicateKeyFinder {
 public:
  bool operator()(int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        frames_.push_back({event == Event::object_start, childSegment(), {}, {}, 0});
        break;
      case Event::object_end:
      case Event::array_end:
        frames_.pop_back();
        break;
      case Event::key: {
        Frame& object = frames_.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second && !duplicate_) duplicate_ = currentPath();
        break;
      }
      case Event::value:
        if (!frames_.empty() && !frames_.back().isObject) ++frames_.back().index;
        break;
    }
    return true;
  }
  const std::optional<std::string>& duplicate() const { return duplicate_; }

 private:
  // Each frame keeps only its own step of the path (".key" or "[i]"), so that deep nesting
  // costs memory in proportion to its depth.
  struct Frame {
    bool isObject;
    std::string segment, key;
    std::set<std::string> keys;
    size_t index;
  };
  // The step from the current container to a container starting now.
  std::string childSegment() {
    if (frames_.empty()) return "";
    Frame& parent = frames_.back();
    if (parent.isObject) return "." + parent.key;
    return fmt::format("[{}]", parent.index++);
  }
  // The path of the current key.
  std::string currentPath() const {
    std::string path;
    for (const Frame& f : frames_) path += f.segment;
    path += "." + frames_.back().key;
    return path.substr(1);
  }

  std::vector<Frame> frames_;
  std::optional<std::string> duplicate_;
};

}  // namespace

std::string numberText(float v) {
  if (std::isinf(v)) return v > 0 ? "infinite" : "-infinite";
  if (std::abs(v) < 1e7f) return fmt::format("{}", v);
  std::string text = fmt::format("{:g}", v);
  if (const size_t e = text.find("e+"); e != std::string::npos) text.erase(e + 1, 1);
  return text;
}

bool Range::contains(float v) const {
  if (!std::isfinite(v)) return false;
  if (loOpen ? v <= lo : v < lo) return false;
  if (hiOpen ? v >= hi : v > hi) return false;
  return true;
}

std::string Range::describe() const {
  if (lo == -kInfinity && hi == kInfinity) return "a finite number";
  if (hi == kInfinity || lo == -kInfinity) return "a number " + interval();
  return "a number in " + interval();
}

std::string Range::interval() const {
  if (lo == -kInfinity && hi == kInfinity) return "finite";
  if (hi == kInfinity) return fmt::format("{} {}", loOpen ? ">" : ">=", numberText(lo));
  if (lo == -kInfinity) return fmt::format("{} {}", hiOpen ? "<" : "<=", numberText(hi));
  return fmt::format("{}{}, {}{}", loOpen ? "(" : "[", numberText(lo), numberText(hi),
                     hiOpen ? ")" : "]");
}

std::string IntRange::describe() const {
  return "an integer " + std::string(hi == std::numeric_limits<int>::max() ? "" : "in ") +
         interval();
}

std::string IntRange::interval() const {
  if (hi == std::numeric_limits<int>::max()) return fmt::format(">= {}", lo);
  return fmt::format("[{}, {}]", lo, hi);
}

JsonNode::JsonNode(std::shared_ptr<const nlohmann::json> root, const nlohmann::json* value,
                   std::string path, std::shared_ptr<const Source> source)
    : root_(std::move(root)), value_(value), path_(std::move(path)), source_(std::move(source)) {}

JsonNode JsonNode::load(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw VerityError(file.string(), "", "cannot open the scene file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse(buffer.str(), file);
}

JsonNode JsonNode::parse(const std::string& text, const std::filesystem::path& file) {
  auto source = std::make_shared<Source>();
  source->file = file;
  // nlohmann's reader takes a NUL byte for the end of the input and ignores what follows.
  if (const size_t nul = text.find('\0'); nul != std::string::npos) {
    const auto [line, column] = lineColumn(text, nul);
    throw VerityError(file.string(), "",
                      fmt::format("JSON syntax error at line {}, column {}: a NUL byte (JSON "
                                  "text cannot contain one; is this a binary file?)",
                                  line, column));
  }
  std::shared_ptr<nlohmann::json> root;
  DuplicateKeyFinder duplicates;
  try {
    root = std::make_shared<nlohmann::json>(nlohmann::json::parse(text, std::ref(duplicates)));
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is one past the offending character.
    const auto [line, column] = lineColumn(text, e.byte > 0 ? e.byte - 1 : 0);
    // nlohmann's message repeats its own position before the description: keep the latter.
    std::string what = e.what();
    const auto cut = what.find(": ", what.find("parse error"));
    if (cut != std::string::npos) what = what.substr(cut + 2);
    throw VerityError(
        file.string(), "",
        fmt::format("JSON syntax error at line {}, column {}: {}", line, column, what));
  } catch (const nlohmann::json::exception& e) {
    // Valid syntax the parser still refuses, such as a number too large for a double.
    std::string what = e.what();
    const auto cut = what.find("] ");
    if (cut != std::string::npos) what = what.substr(cut + 2);
    throw VerityError(file.string(), "", "JSON error: " + what);
  }
  if (!root->is_object())
    throw VerityError(file.string(), "", "the scene must be a JSON object, not " + typeName(*root));
  if (const auto path = tooDeeplyNested(*root))
    throw VerityError(file.string(), *path,
                      fmt::format("nested deeper than {} levels", kMaxNesting));
  if (duplicates.duplicate())
    throw VerityError(file.string(), *duplicates.duplicate(),
                      "the key appears twice in one object; keep one");
  return JsonNode(root, root.get(), "", source);
}

std::filesystem::path JsonNode::resolve(const std::string& name) const {
  const std::filesystem::path p(name);
  if (p.is_absolute()) return p;
  return source_->file.parent_path() / p;
}

void JsonNode::checkDeclared(const std::vector<std::string>& spellings) const {
  const auto it = source_->declared.find(value_);
  if (it == source_->declared.end()) return;
  const KeyDeclaration* key = it->second.find(spellings.front());
  bool same = key && spellings.size() == 1 + key->aliases.size();
  for (const std::string& spelling : spellings) same = same && it->second.find(spelling) == key;
  if (!same)
    throw std::logic_error(fmt::format(
        "{}: {}: the reader of {} asks for \"{}\" ({} spellings), which its key declaration "
        "does not list as one key with exactly these spellings",
        source_->file.string(), path_.empty() ? "(top level)" : path_, it->second.what,
        spellings.front(), spellings.size()));
}

void JsonNode::declare(DeclaredKeys keys) const {
  if (!value_->is_object()) return;
  DeclaredKeys& declared = source_->declared[value_] = std::move(keys);
  for (const std::string& read : source_->used[value_])
    if (!declared.find(read))
      throw std::logic_error(
          fmt::format("{}: {}: \"{}\" was read before {} declared its keys, "
                      "and is not among them",
                      source_->file.string(), path_, read, declared.what));
}

const std::string* JsonNode::resolveKey(const std::vector<std::string>& spellings) const {
  if (!value_->is_object()) fail("expected an object, found " + typeName(*value_));
  checkDeclared(spellings);
  const std::string* found = nullptr;
  for (const std::string& key : spellings) {
    if (value_->contains(key)) {
      if (found)
        fail(fmt::format("both \"{}\" and \"{}\" are given; they are spellings of one key", *found,
                         key));
      found = &key;
    }
  }
  if (found) source_->used[value_].insert(*found);
  return found;
}

namespace {
std::vector<std::string> spelled(Keys keys) {
  return {keys.begin(), keys.end()};
}
}  // namespace

bool JsonNode::has(Keys keys) const {
  return resolveKey(spelled(keys)) != nullptr;
}

std::optional<JsonNode> JsonNode::find(Keys keys) const {
  return find(spelled(keys));
}

std::optional<JsonNode> JsonNode::find(const std::vector<std::string>& spellings) const {
  const std::string* key = resolveKey(spellings);
  if (!key) return std::nullopt;
  return JsonNode(root_, &(*value_)[*key], path_.empty() ? *key : path_ + "." + *key, source_);
}

JsonNode JsonNode::operator[](Keys keys) const {
  auto node = find(keys);
  if (!node) fail(fmt::format("missing required key \"{}\"", *keys.begin()));
  return *node;
}

JsonNode JsonNode::operator[](const KeyDeclaration& key) const {
  auto node = find(key);
  if (!node) fail(fmt::format("missing required key \"{}\"", key.name));
  return *node;
}

JsonNode JsonNode::operator[](size_t index) const {
  if (!value_->is_array()) fail("expected an array, found " + typeName(*value_));
  if (index >= value_->size())
    fail(fmt::format("expected at least {} entries, found {}", index + 1, value_->size()));
  return JsonNode(root_, &(*value_)[index], fmt::format("{}[{}]", path_, index), source_);
}

float JsonNode::asFloat(Range range) const {
  if (!value_->is_number()) fail("expected a number, found " + typeName(*value_));
  const double v = value_->get<double>();
  if (!range.contains(static_cast<float>(v)))
    fail(fmt::format("expected {}, found {}", range.describe(), value_->dump()));
  return static_cast<float>(v);
}

int JsonNode::asInt(int lo, int hi) const {
  if (!value_->is_number()) fail("expected an integer, found " + typeName(*value_));
  const double v = value_->get<double>();
  if (v != std::floor(v)) fail(fmt::format("expected an integer, found {}", value_->dump()));
  if (v < lo || v > hi)
    fail(fmt::format("expected {}, found {}", IntRange{lo, hi}.describe(), value_->dump()));
  return static_cast<int>(v);
}

std::string JsonNode::asString() const {
  if (!value_->is_string()) fail("expected a string, found " + typeName(*value_));
  return value_->get<std::string>();
}

Vector3f JsonNode::asVector3(Range range) const {
  if (value_->is_number()) return Vector3f::Constant(asFloat(range));
  if (!value_->is_array() || value_->size() != 3)
    fail("expected a number or an array of 3 numbers, found " +
         (value_->is_array() ? fmt::format("an array of {}", value_->size()) : typeName(*value_)));
  return {(*this)[0].asFloat(range), (*this)[1].asFloat(range), (*this)[2].asFloat(range)};
}

Vector2i JsonNode::asVector2i(int lo, int hi) const {
  if (!value_->is_array() || value_->size() != 2)
    fail("expected an array of 2 integers, found " +
         (value_->is_array() ? fmt::format("an array of {}", value_->size()) : typeName(*value_)));
  return {(*this)[0].asInt(lo, hi), (*this)[1].asInt(lo, hi)};
}

std::string JsonNode::type() const {
  std::string t = (*this)[{"type"}].asString();
  for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return t;
}

void JsonNode::rejectUnknownKeys() const {
  if (!value_->is_object()) return;
  const auto& used = source_->used[value_];
  const auto declared = source_->declared.find(value_);
  const std::string owner = declared == source_->declared.end()
                                ? "the scene format's keys are"
                                : "the keys of " + declared->second.what + " are";
  for (const auto& item : value_->items()) {
    if (!used.count(item.key())) {
      const std::string where = path_.empty() ? item.key() : path_ + "." + item.key();
      throw VerityError(
          source_->file.string(), where,
          fmt::format("unknown key \"{}\" ({} listed in docs/scene-format.md)", item.key(), owner));
    }
  }
}

VerityError JsonNode::warning(const std::string& problem) const {
  return VerityError(source_->file.string(), path_.empty() ? "(top level)" : path_, problem);
}

void JsonNode::fail(const std::string& problem) const {
  throw warning(problem);
}

}  // namespace verity

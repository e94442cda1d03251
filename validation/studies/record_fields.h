// Typed reads of a study record's fields: a missing key or a value of the wrong type is an
// error naming the file, the record and the key, never a default that would pass as 0 or "".
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace verity::studies {

class FieldReader {
 public:
  // `where` names the object in errors, e.g. "record 3".
  FieldReader(const nlohmann::json& object, const std::string& file, std::string where)
      : object_(object), file_(file), where_(std::move(where)) {}

  const nlohmann::json& field(const char* key) const;
  std::string text(const char* key) const;
  double number(const char* key) const;
  int integer(const char* key) const;
  const nlohmann::json& array(const char* key) const;
  const nlohmann::json& object(const char* key) const;
  const nlohmann::json& object() const { return object_; }
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  [[noreturn]] void fail(const char* key, const std::string& problem) const;

 private:
  const nlohmann::json& object_;
  const std::string& file_;
  std::string where_;
};

}  // namespace verity::studies

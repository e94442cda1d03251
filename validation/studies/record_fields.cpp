#include "validation/studies/record_fields.h"

#include <fmt/format.h>

#include "core/error.h"

namespace verity::studies {

const nlohmann::json& FieldReader::field(const char* key) const {
  const auto it = object_.find(key);
  if (it == object_.end()) fail(key, "missing key");
  return *it;
}

std::string FieldReader::text(const char* key) const {
  const nlohmann::json& v = field(key);
  if (!v.is_string()) fail(key, "expected a string, found " + v.dump());
  return v.get<std::string>();
}

double FieldReader::number(const char* key) const {
  const nlohmann::json& v = field(key);
  if (!v.is_number()) fail(key, "expected a number, found " + v.dump());
  return v.get<double>();
}

int FieldReader::integer(const char* key) const {
  const nlohmann::json& v = field(key);
  if (!v.is_number_integer()) fail(key, "expected an integer, found " + v.dump());
  return v.get<int>();
}

const nlohmann::json& FieldReader::array(const char* key) const {
  const nlohmann::json& v = field(key);
  if (!v.is_array()) fail(key, "expected an array, found " + v.dump());
  return v;
}

const nlohmann::json& FieldReader::object(const char* key) const {
  const nlohmann::json& v = field(key);
  if (!v.is_object()) fail(key, "expected an object, found " + v.dump());
  return v;
}

void FieldReader::fail(const char* key, const std::string& problem) const {
  throw VerityError(file_, fmt::format("{}, \"{}\"", where_, key), problem);
}

}  // namespace verity::studies

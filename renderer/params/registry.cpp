#include "params/registry.h"

#include <cctype>

namespace verity {

std::string typeNameKey(std::string_view spelling) {
  std::string key(spelling);
  for (char& c : key)
    c = c == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return key;
}

}  // namespace verity

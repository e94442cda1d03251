#include "validation/referee/command_template.h"

#include <fmt/format.h>

#include "core/error.h"

namespace verity::validation {

namespace {

// Single quotes keep every character but the single quote, written '\''.
std::string shellQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Calls `placeholder(name)` for each {name}, `text(piece)` for the text between.
template <class Text, class Placeholder>
void scan(const std::string& s, const std::string& option, Text text, Placeholder placeholder) {
  size_t i = 0;
  while (i < s.size()) {
    const size_t open = s.find('{', i);
    if (open == std::string::npos) {
      text(s.substr(i));
      return;
    }
    const size_t close = s.find('}', open);
    if (close == std::string::npos)
      throw VerityError("", option, fmt::format("\"{}\" has a '{{' with no '}}'", s));
    text(s.substr(i, open - i));
    placeholder(s.substr(open + 1, close - open - 1));
    i = close + 1;
  }
}

}  // namespace

bool hasPlaceholder(const std::string& text, const std::string& name) {
  return text.find("{" + name + "}") != std::string::npos;
}

void checkCommandTemplate(const std::string& text, const std::string& option,
                          std::optional<int> spp) {
  if (text.empty()) throw VerityError("", option, "the render command is empty");
  scan(
      text, option, [](const std::string&) {},
      [&](const std::string& name) {
        if (name != "seed" && name != "out" && name != "spp")
          throw VerityError("", option,
                            fmt::format("\"{}\" has the placeholder {{{}}}; a render command "
                                        "knows {{seed}}, {{out}} and {{spp}}",
                                        text, name));
      });
  for (const char* needed : {"seed", "out"})
    if (!hasPlaceholder(text, needed))
      throw VerityError("", option,
                        fmt::format("\"{}\" has no {{{}}}: each render needs its own seed and "
                                    "output file",
                                    text, needed));
  if (hasPlaceholder(text, "spp") && !spp)
    throw VerityError("", option, fmt::format("\"{}\" has {{spp}} but no --spp is given", text));
}

std::string expandCommand(const std::string& text, uint64_t seed, const std::string& out,
                          std::optional<int> spp) {
  std::string command;
  scan(
      text, "", [&](const std::string& piece) { command += piece; },
      [&](const std::string& name) {
        if (name == "seed") command += std::to_string(seed);
        if (name == "out") command += shellQuoted(out);
        if (name == "spp") command += std::to_string(spp.value_or(0));
      });
  return command;
}

}  // namespace verity::validation

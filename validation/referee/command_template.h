// A render command as a template: `{seed}` and `{out}` are replaced by a render's seed and the
// EXR file it must write, `{spp}` (optional) by the samples per pixel given to the referee. The
// command runs under /bin/sh, so the placeholders' values are inserted shell-quoted.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace verity::validation {

// Throws VerityError naming `option` when the template lacks {seed} or {out}, has {spp} but no
// spp is given, or has a brace that is no placeholder.
void checkCommandTemplate(const std::string& text, const std::string& option,
                          std::optional<int> spp);

// The command with its placeholders replaced.
std::string expandCommand(const std::string& text, uint64_t seed, const std::string& out,
                          std::optional<int> spp);

bool hasPlaceholder(const std::string& text, const std::string& name);

}  // namespace verity::validation

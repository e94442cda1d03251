#include "cli/seed_option.h"

#include <charconv>

namespace verity {

CLI::Option* addSeedOption(CLI::App* cmd, uint64_t& seed, const std::string& help) {
  return cmd->add_option_function<std::string>(
      "--seed",
      [&seed](const std::string& text) {
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, seed);
        if (error != std::errc() || stop != end || text.empty())
          throw CLI::ValidationError(
              "--seed", "\"" + text + "\" is not a whole number from 0 to 18446744073709551615");
      },
      help);
}

}  // namespace verity

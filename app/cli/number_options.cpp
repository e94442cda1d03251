#include "cli/number_options.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string>

namespace verity {

namespace {

std::string wholeRange(long long min, long long max) {
  if (max == INT_MAX || max == LLONG_MAX) return fmt::format("a whole number of at least {}", min);
  return fmt::format("a whole number from {} to {}", min, max);
}

std::string realRange(double lo, bool loIncluded, double hi, bool hiIncluded) {
  const std::string from = fmt::format("{} {}", loIncluded ? "at least" : "above", lo);
  if (std::isinf(hi)) return "a number " + from;
  return fmt::format("a number {} and {} {}", from, hiIncluded ? "at most" : "below", hi);
}

}  // namespace

CLI::Validator wholeNumber(long long min, long long max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (error == std::errc() && stop == end && !text.empty() && value >= min && value <= max)
          return "";
        return fmt::format("must be {}, not {}", wholeRange(min, max), text);
      },
      "");
}

CLI::Validator realNumber(double lo, bool loIncluded, double hi, bool hiIncluded) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        const bool inRange =
            (loIncluded ? value >= lo : value > lo) && (hiIncluded ? value <= hi : value < hi);
        if (error == std::errc() && stop == end && !text.empty() && std::isfinite(value) && inRange)
          return "";
        return fmt::format("must be {}, not {}", realRange(lo, loIncluded, hi, hiIncluded), text);
      },
      "");
}

CLI::Validator wholeNumber(const IntRange& allowed) {
  return wholeNumber(allowed.lo, allowed.hi);
}

CLI::Validator realNumber(const Range& allowed) {
  return realNumber(allowed.lo, !allowed.loOpen, allowed.hi, !allowed.hiOpen);
}

}  // namespace verity

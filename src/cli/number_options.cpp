#include "cli/number_options.hpp"

#include <cmath>
#include <cstdlib>

namespace sl {
namespace {

// The number `text` holds, if it is all of it and finite.
bool finiteValue(const std::string& text, double& value) {
  const char* begin = text.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  return end != begin && *end == '\0' && std::isfinite(value);
}

CLI::Validator finiteNumber(bool allowZero) {
  return CLI::Validator(
      [allowZero](std::string& text) -> std::string {
        double value = 0;
        if (finiteValue(text, value) && (value > 0 || (allowZero && value == 0))) return "";
        return "found " + text + "; expected a finite number " + (allowZero ? ">= 0" : "> 0");
      },
      allowZero ? "NONNEGATIVE" : "POSITIVE");
}

}  // namespace

CLI::Validator finitePositive() { return finiteNumber(false); }
CLI::Validator finiteNonNegative() { return finiteNumber(true); }

CLI::Validator finiteRange(double min, double max) {
  const std::string range = CLI::detail::to_string(min) + " to " + CLI::detail::to_string(max);
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        double value = 0;
        if (finiteValue(text, value) && value >= min && value <= max) return "";
        return "found " + text + "; expected a finite number from " + range;
      },
      "FLOAT in [" + range + "]");
}

}  // namespace sl

#include "cli/number_options.hpp"

#include <cmath>
#include <cstdlib>

namespace sl {
namespace {

CLI::Validator finiteNumber(bool allowZero) {
  return CLI::Validator(
      [allowZero](std::string& text) -> std::string {
        const char* begin = text.c_str();
        char* end = nullptr;
        const double value = std::strtod(begin, &end);
        const bool number = end != begin && *end == '\0' && std::isfinite(value);
        if (number && (value > 0 || (allowZero && value == 0))) return "";
        return "found " + text + "; expected a finite number " + (allowZero ? ">= 0" : "> 0");
      },
      allowZero ? "NONNEGATIVE" : "POSITIVE");
}

}  // namespace

CLI::Validator finitePositive() { return finiteNumber(false); }
CLI::Validator finiteNonNegative() { return finiteNumber(true); }

}  // namespace sl

#include "cli/environment.hpp"

#include <cmath>
#include <cstdlib>

#include "cli/exit_codes.hpp"
#include "contracts/limits.hpp"

namespace sl {
namespace {

// A number of seconds from `name`, or `fallback` when it is unset or empty.
double secondsFrom(const char* name, double fallback) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(seconds) || seconds < 0)
    throw CommandExit(kExitBadInput, std::string(name) + ": found \"" + text + "\"; expected seconds, a number >= 0");
  return seconds;
}

Environment readEnvironment() {
  const char* shaders = std::getenv("SL_SHADER_DIR");
  return {secondsFrom("LINKAGE_LOCK_WAIT", limits::kMaxLockWaitSeconds),
          secondsFrom("LINKAGE_ENCODER_WAIT", limits::kMaxEncoderStallSeconds), shaders ? shaders : ""};
}

}  // namespace

const Environment& environment() {
  static const Environment read = readEnvironment();
  return read;
}

}  // namespace sl

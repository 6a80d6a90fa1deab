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
  if (end == text || *end != '\0' || !std::isfinite(seconds) || seconds < 0 ||
      seconds > limits::kMaxEnvironmentWaitSeconds)
    throw CommandExit(kExitBadInput, std::string(name) + ": found \"" + text + "\"; expected seconds, a number from 0 to " +
                                         std::to_string(static_cast<long>(limits::kMaxEnvironmentWaitSeconds)));
  return seconds;
}

std::string textOf(const char* name) {
  const char* text = std::getenv(name);
  return text ? text : "";
}

bool progressJsonFrom(const char* name) {
  const std::string text = textOf(name);
  if (text.empty() || text == "text") return false;
  if (text == "json") return true;
  throw CommandExit(kExitBadInput, std::string(name) + ": found \"" + text + "\"; expected json or text");
}

Environment readEnvironment() {
  std::string switches;
  for (const char* name : {"GALLIUM_OVERRIDE_CPU_CAPS", "GALLIUM_NOSSE", "LP_NATIVE_VECTOR_WIDTH"})
    if (const std::string value = textOf(name); !value.empty())
      switches += (switches.empty() ? "" : " ") + std::string(name) + "=" + value;
  return {secondsFrom("LINKAGE_LOCK_WAIT", limits::kMaxLockWaitSeconds),
          secondsFrom("LINKAGE_ENCODER_WAIT", limits::kMaxEncoderStallSeconds),
          textOf("SL_SHADER_DIR"),
          textOf("LINKAGE_GL"),
          switches,
          progressJsonFrom("LINKAGE_PROGRESS")};
}

}  // namespace

const Environment& environment() {
  static const Environment read = readEnvironment();
  return read;
}

}  // namespace sl

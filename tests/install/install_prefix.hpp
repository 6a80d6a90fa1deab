#pragma once
// The build's own `cmake --install` into a prefix, as the install tests need it.

#include <filesystem>
#include <string>

#include "support/child_process.hpp"

namespace sl::testing {

// Installs the build tree into `prefix`, run from `folder`.
inline ProcessResult installInto(const std::filesystem::path& prefix, const std::filesystem::path& folder) {
  return runShell(std::string(SL_CMAKE_COMMAND) + " --install " + shellQuoted(SL_BUILD_DIR) + " --prefix " +
                      shellQuoted(prefix.string()),
                  folder, 300);
}

}  // namespace sl::testing

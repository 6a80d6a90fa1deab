#pragma once
// The `linkage` binary under test. Its path is a compile definition of each test target that runs it
// (LINKAGE_BINARY="$<TARGET_FILE:linkage>", with add_dependencies on linkage), so this header is for those
// targets only and is not part of sl_test_support's sources.

#ifndef LINKAGE_BINARY
#error "support/linkage_binary.hpp: the test target needs target_compile_definitions(... LINKAGE_BINARY=...)"
#endif

#include <filesystem>
#include <string>
#include <vector>

#include "support/child_process.hpp"

namespace sl::testing {

inline std::string linkageBinary() { return LINKAGE_BINARY; }

// `linkage args...` run in folder to completion (at most timeoutSeconds).
inline ProcessResult runLinkage(const std::vector<std::string>& args, const std::filesystem::path& folder,
                                double timeoutSeconds = kDefaultTimeoutSeconds) {
  return runProcess(linkageBinary(), args, folder, timeoutSeconds);
}

}  // namespace sl::testing

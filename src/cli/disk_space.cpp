#include "cli/disk_space.hpp"

#include <cstdio>
#include <filesystem>

#include "cli/exit_codes.hpp"

namespace sl {

std::string formatBytes(std::uintmax_t bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
  double value = double(bytes);
  int unit = 0;
  while (value >= 1000 && unit < 5) value /= 1000, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
  return text;
}

namespace {

// The folder, or its nearest existing ancestor when it is yet to be created: the file system it will be on.
std::filesystem::path existingAncestor(std::filesystem::path folder) {
  std::error_code error;
  while (!folder.empty() && !std::filesystem::exists(folder, error) && folder.has_parent_path() &&
         folder.parent_path() != folder)
    folder = folder.parent_path();
  return folder.empty() || !std::filesystem::exists(folder, error) ? std::filesystem::path(".") : folder;
}

}  // namespace

void refuseIfFramesCannotFit(const FrameSpaceNeed& need) {
  std::error_code error;
  const std::filesystem::space_info space = std::filesystem::space(existingAncestor(need.folder), error);
  if (error) return;  // unknown (an exotic file system): writing reports a full disk if it happens
  const std::uintmax_t required = std::uintmax_t(need.framesToWrite) * need.bytesPerFrame;
  if (required <= space.available) return;
  throw CommandExit(kExitBadInput,
                    need.folder + ": " + std::to_string(need.framesToWrite) + " frames of " +
                        std::to_string(need.width) + "x" + std::to_string(need.height) + " need about " +
                        formatBytes(required) + " (frame " + std::to_string(need.measuredFrame) + " encodes to " +
                        formatBytes(need.bytesPerFrame) + "), but only " + formatBytes(space.available) +
                        " are free there; free space, choose a smaller --size, or render part with --frames A:B");
}

}  // namespace sl

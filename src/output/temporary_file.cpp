#include "output/temporary_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sl {
namespace {

constexpr const char* kMarker = ".tmp.";

// The pid namespace's inode ("pid:[4026531836]" -> "4026531836"): containers that share a host name still have
// pid namespaces of their own, and a pid means something only within its namespace.
std::string pidNamespace() {
  char link[64] = {};
  const ssize_t size = ::readlink("/proc/self/ns/pid", link, sizeof link - 1);
  std::string digits;
  for (ssize_t i = 0; i < size; ++i)
    if (std::isdigit(static_cast<unsigned char>(link[i]))) digits += link[i];
  return digits.empty() ? "0" : digits;
}

// Who can tell whether a pid is alive: this host (its full name, each character outside [A-Za-z0-9] as '-', so
// it never adds a '.' to the name's fields) and this pid namespace.
const std::string& hostTag() {
  static const std::string tag = [] {
    char name[256] = {};
    std::string host;
    if (::gethostname(name, sizeof name - 1) == 0)
      for (const char* c = name; *c; ++c) host += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '-';
    return (host.empty() ? std::string("host") : host) + "-" + pidNamespace();
  }();
  return tag;
}

bool isNumber(const std::string& text) {
  return !text.empty() && text.size() < 12 && text.find_first_not_of("0123456789") == std::string::npos;
}

// A process that has ended but was not yet reaped (a zombie: its parent died first and nobody waits for it, as
// happens to a render's worker processes killed with it under an init that does not reap) writes nothing any more.
bool processExists(pid_t pid) {
  if (::kill(pid, 0) != 0 && errno != EPERM) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;  // no /proc: alive, as kill said
  const auto name = line.rfind(')');          // "pid (command) state ...": the command may hold spaces
  return name == std::string::npos || name + 2 >= line.size() || (line[name + 2] != 'Z' && line[name + 2] != 'X');
}

// The writer's pid if `name` is a temporary written on this host, else 0.
pid_t localWriter(const std::string& name) {
  const auto marker = name.rfind(kMarker);
  if (marker == std::string::npos || marker == 0) return 0;
  std::istringstream fields(name.substr(marker + std::char_traits<char>::length(kMarker)));
  std::string host, pid, serial;
  if (!std::getline(fields, host, '.') || !std::getline(fields, pid, '.') || !std::getline(fields, serial, '.'))
    return 0;
  if (host != hostTag() || !isNumber(pid) || !isNumber(serial)) return 0;
  return static_cast<pid_t>(std::stol(pid));
}

}  // namespace

std::string temporaryPathFor(const std::string& finalPath) {
  static std::atomic<unsigned long> serial{0};
  return finalPath + kMarker + hostTag() + "." + std::to_string(::getpid()) + "." + std::to_string(serial++);
}

std::vector<std::string> removeStaleTemporaries(const std::string& folder) {
  std::vector<std::string> removed;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    const pid_t writer = localWriter(name);
    if (writer <= 0 || processExists(writer)) continue;
    if (std::filesystem::remove(entry.path(), error)) removed.push_back(name);
  }
  return removed;
}

}  // namespace sl

#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "output/temporary_file.hpp"

namespace sl::output {
namespace {

// Removes the temporary (keeping errno for the message) and throws.
[[noreturn]] void failAndRemove(const std::string& what, const std::string& path, const std::string& temporary) {
  const int saved = errno;
  ::unlink(temporary.c_str());
  throw std::runtime_error(what + " " + path + ": " + std::strerror(saved));
}

void writeAll(int fd, const std::uint8_t* data, std::size_t size, const std::string& temporary) {
  for (std::size_t written = 0; written < size;) {
    const ssize_t n = ::write(fd, data + written, size - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int saved = errno;
      ::close(fd);
      errno = saved;
      failAndRemove("cannot write", temporary, temporary);
    }
    written += static_cast<std::size_t>(n);
  }
}

// After the rename, the folder's entry must reach the disk as well.
void syncFolderOf(const std::string& path) {
  const std::string folder = std::filesystem::path(path).parent_path().string();
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // the file is in place; only its durability across a power loss is weaker
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::uint8_t* data, std::size_t size, Sync sync) {
  const std::string temporary = temporaryPathFor(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot create " + temporary + ": " + std::strerror(errno));
  writeAll(fd, data, size, temporary);
  if (sync == Sync::data && ::fsync(fd) != 0) {
    const int saved = errno;
    ::close(fd);
    errno = saved;
    failAndRemove("cannot sync", temporary, temporary);
  }
  // close() reports deferred write errors (NFS, quota): the temporary may be incomplete.
  if (::close(fd) != 0) failAndRemove("cannot close", temporary, temporary);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) failAndRemove("cannot rename into", path, temporary);
  if (sync == Sync::data) syncFolderOf(path);
}

void writeFileAtomically(const std::string& path, const std::string& text, Sync sync) {
  writeFileAtomically(path, reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), sync);
}

}  // namespace sl::output

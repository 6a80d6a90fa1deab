#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "output/temporary_file.hpp"

namespace sl {
namespace {

// Removes the temporary (keeping errno for the message) and throws.
[[noreturn]] void failAndRemove(const std::string& what, const std::string& path, const std::string& temporary) {
  const int saved = errno;
  ::unlink(temporary.c_str());
  const std::string message = what + " " + path + ": " + std::strerror(saved);
  if (saved == ENOSPC || saved == EDQUOT) throw FileSystemFull(message);
  throw std::runtime_error(message);
}

[[noreturn]] void failToCreate(const std::string& temporary) {
  const int saved = errno;
  const std::string message = "cannot create " + temporary + ": " + std::strerror(saved) +
                              (saved == ENOSPC ? " (no space, or no free inodes)" : "");
  if (saved == ENOSPC || saved == EDQUOT) throw FileSystemFull(message);
  throw std::runtime_error(message);
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

std::string outputTarget(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::path target = path;
  // Follow a chain of links (bounded, as the kernel bounds it) to the file they name.
  for (int hops = 0; fs::is_symlink(fs::symlink_status(target, error)); ++hops) {
    if (hops == 40) throw std::invalid_argument(path + ": too many levels of symbolic links");
    const fs::path next = fs::read_symlink(target, error);
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  const fs::file_status status = fs::status(target, error);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw std::invalid_argument(path + (target != fs::path(path) ? " (a link to " + target.string() + ")" : "") +
                                " exists and is not a regular file (" +
                                (fs::is_directory(status) ? "a folder" : "a device, pipe or socket") +
                                "); refusing to replace it");
  return target.string();
}

AtomicFileWriter::AtomicFileWriter(const std::string& path) : path_(outputTarget(path)) {
  temporary_ = temporaryPathFor(path_);
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) failToCreate(temporary_);
}

AtomicFileWriter::~AtomicFileWriter() {
  if (fd_ >= 0) ::close(fd_);
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void AtomicFileWriter::write(const std::string& text) {
  if (fd_ < 0) throw std::logic_error("AtomicFileWriter: write after commit");
  const int fd = fd_;
  fd_ = -1;  // writeAll closes it on failure
  writeAll(fd, reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), temporary_);
  fd_ = fd;
}

void AtomicFileWriter::commit() {
  if (fd_ < 0) throw std::logic_error("AtomicFileWriter: commit twice");
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) failAndRemove("cannot close", temporary_, temporary_);
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) failAndRemove("cannot rename into", path_, temporary_);
  temporary_.clear();
}

void writeFileAtomically(const std::string& requested, const std::uint8_t* data, std::size_t size, Sync sync) {
  const std::string path = outputTarget(requested);
  const std::string temporary = temporaryPathFor(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) failToCreate(temporary);
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

}  // namespace sl

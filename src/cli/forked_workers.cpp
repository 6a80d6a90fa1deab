#include "cli/forked_workers.hpp"

#include "cli/exit_codes.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <system_error>

namespace sl {

namespace {

// A message on the pipe: its kind, the text's length (4 bytes, this machine's order: both ends are one program on
// one machine) and the text.
constexpr std::size_t kHeader = 1 + sizeof(std::uint32_t);

void writeAll(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return;  // the other end is gone: its process has ended, which the reader notices
    data += written;
    size -= static_cast<std::size_t>(written);
  }
}

// Writing to a pipe whose reader has ended raises SIGPIPE, which would end the parent: ignored while the parent
// writes the go.
class SigpipeIgnored {
 public:
  SigpipeIgnored() {
    struct sigaction ignore = {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, &previous_);
  }
  ~SigpipeIgnored() { ::sigaction(SIGPIPE, &previous_, nullptr); }
  SigpipeIgnored(const SigpipeIgnored&) = delete;
  SigpipeIgnored& operator=(const SigpipeIgnored&) = delete;

 private:
  struct sigaction previous_ = {};
};

void closeIfOpen(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

}  // namespace

void WorkerChannel::send(char kind, const std::string& text) const {
  std::string message(kHeader, '\0');
  message[0] = kind;
  const auto length = static_cast<std::uint32_t>(text.size());
  std::memcpy(message.data() + 1, &length, sizeof length);
  message += text;
  writeAll(up_, message.data(), message.size());
}

bool WorkerChannel::waitForGo(const std::function<bool()>& cancelled) const {
  char go = 0;
  while (true) {
    const ssize_t got = ::read(down_, &go, 1);
    if (got < 0 && errno == EINTR && !cancelled()) continue;
    return got == 1 && go == 'g';
  }
}

ForkedWorkers::ForkedWorkers(int count, const std::function<int(int, const WorkerChannel&)>& body) {
  std::cout.flush();  // buffered output would otherwise be written by every worker too
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  for (int i = 0; i < count; ++i) {
    int up[2], down[2];
    if (::pipe2(up, O_CLOEXEC) != 0) break;
    if (::pipe2(down, O_CLOEXEC) != 0) {
      ::close(up[0]), ::close(up[1]);
      break;
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
      // The worker: none of the parent's ends of any pipe, and it dies with its parent, as a thread would (a
      // SIGTERM or SIGINT the parent gets is sent on by next(), and the workers finish their frames in flight).
      for (Worker& earlier : workers_) closeIfOpen(earlier.up), closeIfOpen(earlier.down);
      ::close(up[0]), ::close(down[1]);
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      int status = kExitFailure;
      if (::getppid() == parent) {
        try {
          status = body(i, WorkerChannel(up[1], down[0]));
        } catch (...) {  // the body reports its own errors; this is the last resort
        }
      }
      std::cout.flush();
      std::fflush(nullptr);
      ::_exit(status);
    }
    ::close(up[1]), ::close(down[0]);
    if (pid < 0) {
      ::close(up[0]), ::close(down[1]);
      break;
    }
    Worker started;
    started.pid = pid, started.up = up[0], started.down = down[1];
    workers_.push_back(std::move(started));
  }
  if (static_cast<int>(workers_.size()) < count) {
    const int error = errno;
    stopAll();  // the workers that did start wait for the go: told to stop, waited for
    throw std::system_error(error, std::generic_category(), "cannot start the processes that draw frames");
  }
}

ForkedWorkers::~ForkedWorkers() { stopAll(); }

void ForkedWorkers::stopAll() {
  bool running = false;
  for (const Worker& worker : workers_) running = running || (worker.open && worker.status < 0);
  refuse();
  if (running) signalAll(SIGTERM);  // one drawing stops after the frames in flight
  exitStatuses();
  for (Worker& worker : workers_) closeIfOpen(worker.up);
}

void ForkedWorkers::refuse() {
  for (Worker& worker : workers_) closeIfOpen(worker.down);  // its read of the go ends without one
}

void ForkedWorkers::go() {
  const SigpipeIgnored ignored;
  for (Worker& worker : workers_) {
    writeAll(worker.down, "g", 1);
    closeIfOpen(worker.down);
  }
}

std::optional<ForkedWorkers::Message> ForkedWorkers::takeMessage(Worker& worker, int index) {
  if (worker.received.size() < kHeader) return std::nullopt;
  std::uint32_t length = 0;
  std::memcpy(&length, worker.received.data() + 1, sizeof length);
  if (worker.received.size() < kHeader + length) return std::nullopt;
  Message message{index, worker.received[0], worker.received.substr(kHeader, length)};
  worker.received.erase(0, kHeader + length);
  return message;
}

std::optional<ForkedWorkers::Message> ForkedWorkers::next(const std::function<bool()>& signalled) {
  while (true) {
    for (std::size_t i = 0; i < workers_.size(); ++i)
      if (auto message = takeMessage(workers_[i], static_cast<int>(i))) return message;
    if (!ended_.empty()) {  // after the worker's last messages
      const int worker = ended_.front();
      ended_.pop_front();
      return Message{worker, kEnded, ""};
    }
    std::vector<pollfd> fds;
    std::vector<std::size_t> owners;
    for (std::size_t i = 0; i < workers_.size(); ++i)
      if (workers_[i].open) fds.push_back({workers_[i].up, POLLIN, 0}), owners.push_back(i);
    if (fds.empty()) return std::nullopt;
    // SIGINT and SIGTERM are blocked except inside ppoll, so one that arrives between the check and the wait still
    // ends the wait (no lost wake-up).
    sigset_t interrupts, previous;
    sigemptyset(&interrupts);
    sigaddset(&interrupts, SIGINT);
    sigaddset(&interrupts, SIGTERM);
    ::sigprocmask(SIG_BLOCK, &interrupts, &previous);
    if (signalled() && !forwarded_) {
      signalAll(SIGTERM);
      forwarded_ = true;
    }
    // Woken each second to look for workers that were stopped (SIGSTOP, a debugger, a batch system's suspend):
    // the render then says what it waits for instead of hanging without a word.
    const timespec second{1, 0};
    const int ready = ::ppoll(fds.data(), fds.size(), &second, &previous);
    const int error = errno;
    ::sigprocmask(SIG_SETMASK, &previous, nullptr);
    if (ready < 0) {
      if (error == EINTR) continue;
      throw std::system_error(error, std::generic_category(), "waiting for the processes that draw frames");
    }
    if (ready == 0) {
      noticeStops();
      continue;
    }
    for (std::size_t k = 0; k < fds.size(); ++k) {
      if (fds[k].revents == 0) continue;
      Worker& worker = workers_[owners[k]];
      char buffer[4096];
      const ssize_t got = ::read(worker.up, buffer, sizeof buffer);
      if (got > 0) {
        worker.received.append(buffer, static_cast<std::size_t>(got));
      } else if (got == 0 || errno != EINTR) {
        worker.open = false;  // ended (or its pipe failed, which ends it as far as messages go)
        ended_.push_back(static_cast<int>(owners[k]));
      }
    }
  }
}

void ForkedWorkers::signalAll(int signal) const {
  for (const Worker& worker : workers_)
    if (worker.status < 0) {
      ::kill(worker.pid, signal);
      ::kill(worker.pid, SIGCONT);  // a stopped worker acts on the signal only once it runs again
    }
}

void ForkedWorkers::noticeStops() {
  for (Worker& worker : workers_) {
    if (worker.status >= 0) continue;
    int raw = 0;
    const pid_t changed = ::waitpid(worker.pid, &raw, WNOHANG | WUNTRACED | WCONTINUED);
    if (changed != worker.pid) continue;
    if (WIFSTOPPED(raw)) {
      std::cerr << "linkage: a process drawing frames (pid " << worker.pid << ") is stopped ("
                << ::strsignal(WSTOPSIG(raw)) << "); the render waits for it: continue it (kill -CONT " << worker.pid
                << ") or stop the render (SIGINT, SIGTERM)\n";
    } else if (WIFEXITED(raw) || WIFSIGNALED(raw)) {
      worker.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);  // reaped here: exitStatuses knows
    }
  }
}

std::vector<int> ForkedWorkers::exitStatuses() {
  std::vector<int> statuses;
  for (Worker& worker : workers_) {
    while (worker.status < 0) {
      int raw = 0;
      if (::waitpid(worker.pid, &raw, 0) < 0) {
        if (errno == EINTR) continue;
        worker.status = kExitFailure;  // not ours to wait for any more: count it as failed
        break;
      }
      worker.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    }
    statuses.push_back(worker.status);
  }
  return statuses;
}

}  // namespace sl

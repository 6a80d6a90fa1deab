#include "support/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <chrono>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "support/files.hpp"

extern char** environ;

namespace sl::testing {

namespace {

// Spawn attributes that undo what the test process may have changed (gtest death tests, a handler it
// installed): the child starts as a shell would start it.
class DefaultSignals {
 public:
  DefaultSignals() {
    posix_spawnattr_init(&attributes_);
    sigset_t all, none;
    sigfillset(&all);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attributes_, &all);
    posix_spawnattr_setsigmask(&attributes_, &none);
    posix_spawnattr_setflags(&attributes_, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  }
  ~DefaultSignals() { posix_spawnattr_destroy(&attributes_); }
  const posix_spawnattr_t* get() const { return &attributes_; }

 private:
  posix_spawnattr_t attributes_;
};

}  // namespace

ChildProcess::ChildProcess(const std::string& program, const std::vector<std::string>& args,
                           const std::filesystem::path& folder) {
  std::vector<std::string> words{program};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string outPath = logs_ / "out", errPath = logs_ / "err";
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  const DefaultSignals signals;
  const int error = posix_spawn(&pid_, program.c_str(), &actions, signals.get(), argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("cannot start " + program + ": errno " + std::to_string(error));
}

ChildProcess::~ChildProcess() {
  if (!reaped_ && pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
}

bool ChildProcess::running() {
  if (reaped_) return false;
  int raw = 0;
  if (::waitpid(pid_, &raw, WNOHANG) != pid_) return true;
  reaped_ = true;
  result_.code = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  result_.signal = WIFSIGNALED(raw) ? WTERMSIG(raw) : 0;
  return false;
}

void ChildProcess::sendSignal(int signal) {
  if (!reaped_) ::kill(pid_, signal);
}

ProcessResult ChildProcess::wait(double timeoutSeconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  while (running()) {
    if (std::chrono::steady_clock::now() > deadline) {
      sendSignal(SIGKILL);
      while (running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      result_.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  result_.out = readFile(logs_ / "out");
  result_.err = readFile(logs_ / "err");
  return result_;
}

ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args,
                         const std::filesystem::path& folder, double timeoutSeconds) {
  return ChildProcess(program, args, folder).wait(timeoutSeconds);
}

ProcessResult runShell(const std::string& commandLine, const std::filesystem::path& folder, double timeoutSeconds) {
  return runProcess("/bin/sh", {"-c", commandLine}, folder, timeoutSeconds);
}

std::string shellQuoted(const std::string& word) {
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string ChildProcess::errSoFar() const { return readFile(logs_ / "err"); }

bool catchesSignal(pid_t pid, int signal) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (signal - 1)) & 1;
  return false;
}

std::string awaitSignalHandlers() {
  // SIGINT is bit 1 and SIGTERM bit 14 of the mask (signal number - 1): 0x4002.
  return "for i in $(seq 600); do m=$(awk '/^SigCgt/{print $2}' /proc/$pid/status 2>/dev/null); "
         "[ -n \"$m\" ] && [ $(( 0x$m & 0x4002 )) -eq $(( 0x4002 )) ] && break; sleep 0.1; done";
}

}  // namespace sl::testing

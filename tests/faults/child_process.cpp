#include "child_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace sl::faults {

ChildProcess::ChildProcess(const std::string& program, const std::vector<std::string>& args, const std::string& folder,
                           const std::string& logName)
    : errPath_(folder + "/" + logName + ".err") {
  std::vector<std::string> words{program};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string outPath = folder + "/" + logName + ".out";
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  const int error = posix_spawn(&pid_, program.c_str(), &actions, nullptr, argv.data(), environ);
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
  const pid_t done = ::waitpid(pid_, &raw, WNOHANG);
  if (done != pid_) return true;
  reaped_ = true;
  status_.code = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  status_.signal = WIFSIGNALED(raw) ? WTERMSIG(raw) : 0;
  return false;
}

void ChildProcess::sendSignal(int signal) {
  if (!reaped_) ::kill(pid_, signal);
}

ExitStatus ChildProcess::wait(double timeoutSeconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  while (running()) {
    if (std::chrono::steady_clock::now() > deadline) {
      sendSignal(SIGKILL);
      while (running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      status_.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status_;
}

std::string ChildProcess::standardError() const {
  std::ifstream stream(errPath_);
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

std::string linkageBinary() { return LINKAGE_BINARY; }

ExitStatus runLinkage(const std::vector<std::string>& args, const std::string& folder, double timeoutSeconds,
                      std::string* standardError) {
  ChildProcess child(linkageBinary(), args, folder);
  const ExitStatus status = child.wait(timeoutSeconds);
  if (standardError != nullptr) *standardError = child.standardError();
  return status;
}

}  // namespace sl::faults

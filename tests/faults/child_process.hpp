#pragma once
// The `linkage` binary as a child process the fault tests can watch and kill: started with
// posix_spawn (no shell), output streams to files, waited for with a time limit so that a hang fails
// the test instead of blocking the suite.

#include <sys/types.h>
#include <string>
#include <vector>

namespace sl::faults {

struct ExitStatus {
  int code = -1;   // exit status, or -1 if killed by a signal
  int signal = 0;  // the signal that ended it, or 0
  bool timedOut = false;
};

class ChildProcess {
 public:
  // Runs `program args...` in folder with stdout and stderr going to folder/<logName>.out/.err.
  ChildProcess(const std::string& program, const std::vector<std::string>& args, const std::string& folder,
               const std::string& logName = "child");
  ~ChildProcess();  // kills and reaps a child still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool running();
  pid_t pid() const { return pid_; }
  void sendSignal(int signal);
  // Waits at most timeoutSeconds; on timeout the child is killed and timedOut is set.
  ExitStatus wait(double timeoutSeconds);
  std::string standardError() const;

 private:
  pid_t pid_ = -1;
  std::string errPath_;
  bool reaped_ = false;
  ExitStatus status_;
};

// The path of the `linkage` binary under test (a compile definition set by tests/faults/CMakeLists.txt).
std::string linkageBinary();

// Runs `linkage args...` to completion (at most timeoutSeconds) in folder.
ExitStatus runLinkage(const std::vector<std::string>& args, const std::string& folder, double timeoutSeconds = 120,
                      std::string* standardError = nullptr);

}  // namespace sl::faults

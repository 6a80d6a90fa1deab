#pragma once
// Programs run from tests as child processes: started with posix_spawn (no shell unless asked for), in a
// given working folder, both output streams captured, waited for with a time limit so that a hang fails the
// test instead of blocking the suite, and open to signals while they run.

#include <sys/types.h>
#include <filesystem>
#include <string>
#include <vector>

#include "support/temp_folder.hpp"

namespace sl::testing {

// Long enough for the slowest render a test starts (600 small frames under the sanitizers).
inline constexpr double kDefaultTimeoutSeconds = 300;

struct ProcessResult {
  int code = -1;          // the exit status, or -1 if the process did not exit by itself
  int signal = 0;         // the signal that ended it, or 0
  bool timedOut = false;  // it outlived the time limit and was killed (SIGKILL)
  std::string out, err;   // everything it wrote to stdout and stderr
};

class ChildProcess {
 public:
  // Starts `program args...` (program is a path: no PATH search) in `folder`, stdin from /dev/null, with the
  // default signal dispositions and no blocked signals. stdout and stderr go to files of the child's own
  // outside `folder`, so the folder holds only what the program writes.
  ChildProcess(const std::string& program, const std::vector<std::string>& args, const std::filesystem::path& folder);
  ~ChildProcess();  // kills and reaps a child still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool running();
  pid_t pid() const { return pid_; }
  void sendSignal(int signal);  // nothing once the child has been reaped
  // What it has written to stderr so far (its progress lines: events to wait for).
  std::string errSoFar() const;
  // Waits at most timeoutSeconds; on timeout the child is killed and timedOut is set.
  ProcessResult wait(double timeoutSeconds = kDefaultTimeoutSeconds);

 private:
  TempFolder logs_;
  pid_t pid_ = -1;
  bool reaped_ = false;
  ProcessResult result_;
};

// Runs `program args...` in folder to completion (at most timeoutSeconds).
ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args,
                         const std::filesystem::path& folder, double timeoutSeconds = kDefaultTimeoutSeconds);
// Runs a /bin/sh command line in folder (for recipes written as shell lines, such as a README's).
ProcessResult runShell(const std::string& commandLine, const std::filesystem::path& folder,
                       double timeoutSeconds = kDefaultTimeoutSeconds);
// `word` as one word of a shell command line, whatever it holds.
std::string shellQuoted(const std::string& word);
// Whether `pid` has a handler for `signal` (the kernel's SigCgt mask in /proc/PID/status): an event to wait for
// before signalling a command, so that the signal finds the handler installed.
bool catchesSignal(pid_t pid, int signal);
// The same as a shell snippet that waits (at most 60 s) until the process `$pid` has handlers for SIGTERM and
// SIGINT: a signal sent after it tests the program's answer, never its start-up, however loaded the machine.
std::string awaitSignalHandlers();

}  // namespace sl::testing

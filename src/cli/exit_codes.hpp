#pragma once
// Exit statuses of `linkage` (also listed in `linkage --help`), and the exception commands throw to
// end with one of them.

#include <stdexcept>
#include <string>

namespace sl {

enum ExitCode : int {
  kExitOk = 0,
  kExitMismatch = 1,      // diff: the two sides differ beyond the tolerance
  kExitBadInput = 2,      // a bad scene, bad options or unreadable input files; nothing was written
  kExitFailure = 3,       // the work failed: cannot write, ffmpeg failed, a manifest is inconsistent
  kExitInterrupted = 130  // SIGINT or SIGTERM: stopped cleanly between frames (128 + SIGINT)
};

// Thrown by a command to stop with an exit status; what() is printed to stderr unless empty.
class CommandExit : public std::runtime_error {
 public:
  CommandExit(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// The footer of `linkage --help`.
inline const char* exitCodeHelp() {
  return "Exit status: 0 ok; 1 diff found differences; 2 bad scene, options or input files (nothing written);\n"
         "3 the work failed (cannot write, ffmpeg failed); 130 interrupted by SIGINT/SIGTERM (rerun with --resume).\n"
         "A run that stops (a method failing at a pole, say) is a result, not an error: it is reported and the\n"
         "frames show where and why it stopped.";
}

}  // namespace sl

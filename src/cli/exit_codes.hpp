#pragma once
// Exit statuses of `linkage` (also listed in `linkage --help`), and the exception commands throw to
// end with one of them.

#include <new>
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

// What ends a command with `error`: its exit status and the line printed (empty: nothing). A CommandExit says both;
// std::invalid_argument is bad input (2), any other exception a failure of the work (3).
struct ExitReport {
  int code = kExitFailure;
  std::string message;
};
inline ExitReport exitReportOf(const std::exception& error) {
  if (const auto* exit = dynamic_cast<const CommandExit*>(&error)) return {exit->code(), exit->what()};
  if (dynamic_cast<const std::bad_alloc*>(&error))
    return {kExitFailure, "linkage: out of memory (a smaller frame size or fewer runs need less; a batch system's "
                          "memory request or ulimit -v may be too small)"};
  if (dynamic_cast<const std::invalid_argument*>(&error)) return {kExitBadInput, std::string("linkage: ") + error.what()};
  return {kExitFailure, std::string("linkage: ") + error.what()};
}

// What each exit status means, in words: the footer of `linkage --help` and the man page's EXIT STATUS.
struct ExitStatusWords {
  ExitCode code;
  const char* meaning;
};
inline constexpr ExitStatusWords kExitStatusWords[] = {
    {kExitOk, "ok"},
    {kExitMismatch, "diff found differences beyond its tolerances"},
    {kExitBadInput, "bad scene, options or input files; nothing was written"},
    {kExitFailure, "the work failed (cannot write, ffmpeg failed, none of a search's results confirmed)"},
    {kExitInterrupted, "interrupted by SIGINT or SIGTERM (rerun with --resume to finish PNG frames)"},
};
// Why a stopped run is not an error.
inline constexpr const char* kStoppedRunWords =
    "A run that stops (a method failing at a pole, say) is a result, not an error: it is reported and the frames "
    "show where and why it stopped.";

// The footer of `linkage --help`.
inline std::string exitCodeHelp() {
  std::string text = "Exit status:";
  for (const ExitStatusWords& status : kExitStatusWords)
    text += std::string(status.code == kExitOk ? " " : "; ") + std::to_string(status.code) + " " + status.meaning;
  return text + ".\n" + kStoppedRunWords;
}

}  // namespace sl

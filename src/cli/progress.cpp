#include "cli/progress.hpp"

#include <unistd.h>
#include <algorithm>
#include <cstdio>

#include "cli/environment.hpp"

namespace sl {

namespace {

constexpr auto kTerminalInterval = std::chrono::milliseconds(200);
constexpr auto kLogHeartbeat = std::chrono::seconds(30);

}  // namespace

Progress::Progress(long total, bool quiet, std::string command, std::string unit)
    : total_(total),
      quiet_(quiet),
      terminal_(::isatty(STDERR_FILENO) != 0 && !environment().progressJson),
      json_(environment().progressJson),
      command_(std::move(command)),
      unit_(std::move(unit)),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

Progress::~Progress() {
  if (drawn_ && terminal_) std::fputc('\n', stderr);
}

void Progress::update(long done, long total) {
  total_ = total;
  update(done);
}

SearchProgress searchProgress(const std::string& command, bool quiet) {
  struct Passes {
    std::shared_ptr<Progress> line;
    long offset = 0, lastDone = 0, lastTotal = 0;
  };
  auto passes = std::make_shared<Passes>();
  passes->line = std::make_shared<Progress>(0, quiet, command, "search step");
  return [passes](long done, long total) {
    if (done < passes->lastDone) passes->offset += passes->lastTotal;  // a new pass
    passes->lastDone = done;
    passes->lastTotal = total;
    passes->line->update(passes->offset + done, passes->offset + total);
  };
}

void Progress::update(long done) {
  if (quiet_ || total_ <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  const long tenth = done * 10 / total_;
  if (terminal_) {
    if (drawn_ && done < total_ && now - lastDraw_ < kTerminalInterval) return;
  } else if (tenth <= lastTenth_ && now - lastDraw_ < kLogHeartbeat) {
    return;
  }
  lastDraw_ = now;
  lastTenth_ = std::max(lastTenth_, tenth);
  drawn_ = true;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const double rate = seconds > 0 ? done / seconds : 0;
  const long eta = rate > 0 ? static_cast<long>((total_ - done) / rate) : 0;
  if (json_)  // the command and the unit are the program's own words (no quoting needed)
    std::fprintf(stderr,
                 "{\"command\": \"%s\", \"unit\": \"%s\", \"done\": %ld, \"total\": %ld, \"rate\": %.4g, "
                 "\"eta_seconds\": %ld}\n",
                 command_.c_str(), unit_.c_str(), done, total_, rate, eta);
  else if (terminal_)
    std::fprintf(stderr, "\r%s %ld/%ld  %.1f %ss/s  ETA %ld:%02ld   ", unit_.c_str(), done, total_, rate,
                 unit_.c_str(), eta / 60, eta % 60);
  else
    std::fprintf(stderr, "linkage %s: %s %ld/%ld (%ld%%), %.1f %ss/s, ETA %ld:%02ld\n", command_.c_str(),
                 unit_.c_str(), done, total_, done * 100 / total_, rate, unit_.c_str(), eta / 60, eta % 60);
  std::fflush(stderr);
}

}  // namespace sl

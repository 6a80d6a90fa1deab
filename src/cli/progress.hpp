#pragma once
// Progress of long work on stderr ("frame 120/601  31.5 fps  ETA 0:15"), only when stderr is a terminal
// and not --quiet, redrawn at most five times a second. Never written into files or pipes.

#include <chrono>

namespace sl {

class Progress {
 public:
  Progress(long total, bool quiet);
  ~Progress();  // ends the line if something was drawn
  void update(long done);

 private:
  long total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace sl

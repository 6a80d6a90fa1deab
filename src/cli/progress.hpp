#pragma once
// Progress of long work on stderr, the one rule for every command (frames, sweep cells, bench points, grid rows):
// - stderr a terminal: one line redrawn in place ("frame 120/601  31.5 frames/s  ETA 0:15"), at most five
//   times a second;
// - stderr a file or pipe (a cluster job's log): a whole line each time another tenth of the work is done
//   ("linkage render: frame 121/601 (20%), 31.5 frames/s, ETA 0:15"), and between tenths one at most every
//   30 s when a tenth takes longer, so a log shows the job is alive without filling up;
// - LINKAGE_PROGRESS=json (cli/environment.hpp): whatever stderr is, one JSON object per line at each tenth and
//   at the end, {"command": "render", "unit": "frame", "done": 121, "total": 601, "rate": 31.5, "eta_seconds": 15},
//   for a script or a scheduler to read;
// - --quiet: nothing.

#include <chrono>
#include <memory>
#include <string>

#include "contracts/run_control.hpp"

namespace sl {

class Progress {
 public:
  // `command` names the log lines ("render"); `unit` is what is counted, singular ("frame", "cell", "point").
  Progress(long total, bool quiet, std::string command = "render", std::string unit = "frame");
  ~Progress();  // ends the terminal line if something was drawn
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void update(long done);
  // For work whose size is learnt on the way (a search plans its shots after its rays).
  void update(long done, long total);

 private:
  long total_;
  bool quiet_, terminal_, json_;
  std::string command_, unit_;
  bool drawn_ = false;
  long lastTenth_ = 0;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

// A search's progress on one line ("linkage periodic: search step 40/260 ..."): its passes (each counted from 0)
// follow one another, so the count only grows.
SearchProgress searchProgress(const std::string& command, bool quiet);

}  // namespace sl

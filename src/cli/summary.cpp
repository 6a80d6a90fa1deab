#include "cli/summary.hpp"

#include <cstdio>
#include <iostream>

namespace sl {

CommandSummary::CommandSummary(std::string command, bool quiet)
    : command_(std::move(command)), quiet_(quiet), start_(std::chrono::steady_clock::now()) {}

double CommandSummary::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void CommandSummary::print(const std::string& what, const std::string& after) const {
  if (quiet_) return;
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.3g", seconds());
  std::cerr << "linkage " << command_ << ": " << what << " in " << elapsed << " s" << after << "\n";
}

std::string runOutcomes(const Scene& scene, const std::vector<Trajectory>& runs, double until) {
  std::string text;
  char time[32];
  for (size_t i = 0; i < runs.size(); ++i) {
    const std::optional<StopInfo>& stop = runs[i].stop();
    const bool stopped = stop && stop->time <= until;
    std::snprintf(time, sizeof time, "%.4g", stopped ? stop->time : until);
    text += (text.empty() ? "" : "; ") + ("\"" + scene.runs[i].name + "\" ") +
            (stopped ? "stopped at t = " + std::string(time) + " (" + nameOf(stop->reason) + ")"
                  : "ran to t = " + std::string(time));
  }
  return text;
}

}  // namespace sl

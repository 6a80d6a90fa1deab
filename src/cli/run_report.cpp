#include "cli/run_report.hpp"

#include <iostream>
#include <sstream>

namespace sl {

std::string stopReports(const Scene& scene, const std::vector<Trajectory>& runs) {
  std::ostringstream lines;
  for (size_t i = 0; i < runs.size(); ++i) {
    const std::optional<StopInfo>& stop = runs[i].stop();
    if (!stop) continue;
    lines << "run \"" << scene.runs[i].name << "\" stopped at t = " << stop->time << ": " << nameOf(stop->reason)
          << (stop->detail().empty() ? "" : " (" + stop->detail() + ")") << '\n';
  }
  return lines.str();
}

void reportStops(const Scene& scene, const std::vector<Trajectory>& runs, bool quiet) {
  if (!quiet) std::cerr << stopReports(scene, runs);
}

}  // namespace sl

#include "cli/run_report.hpp"

#include <iostream>

namespace sl {

void reportStops(const Scene& scene, const std::vector<Trajectory>& runs, bool quiet) {
  if (quiet) return;
  for (size_t i = 0; i < runs.size(); ++i) {
    const std::optional<StopInfo>& stop = runs[i].stop();
    if (!stop) continue;
    std::cerr << "run \"" << scene.runs[i].name << "\" stopped at t = " << stop->time << ": " << nameOf(stop->reason)
              << (stop->detail().empty() ? "" : " (" + stop->detail() + ")") << '\n';
  }
}

}  // namespace sl

#pragma once
// The one line every command ends with ("linkage render: 601 frames ... in 12.3 s"), on stderr whether or not
// it is a terminal (a cluster job's log shows it too); --quiet leaves it out, like everything but errors.

#include <chrono>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

class CommandSummary {
 public:
  CommandSummary(std::string command, bool quiet);
  double seconds() const;
  // Prints "linkage <command>: <what> in <seconds> s<after>".
  void print(const std::string& what, const std::string& after = "") const;
  bool quiet() const { return quiet_; }

 private:
  std::string command_;
  bool quiet_;
  std::chrono::steady_clock::time_point start_;
};

// "\"geodesic\" ran to t = 20; \"published\" stopped at t = 3.41 (pole-fold-back)": each run's outcome up to
// time `until` (the last time the command needed), for summaries.
std::string runOutcomes(const Scene& scene, const std::vector<Trajectory>& runs, double until);

}  // namespace sl

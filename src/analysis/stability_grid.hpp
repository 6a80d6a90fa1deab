#pragma once
// The initial conditions of a stability sweep: a grid x by y of starts chosen to stress the chart
// (phi, t) of the spec (4 rods). Each kind names what its two axes vary:
//   launch     x = t0 in [-pi, pi), y = phi0 in (-pi/2, pi/2), heading fixed: the launch point over the sphere
//   direction  x = heading in [0, 2pi), y = phi0, t0 = 0.2: the launch direction at every latitude
//   pole       x = log10 of the closest approach to the pole phi = pi/2 (-11 .. -1; the leftmost column passes
//              exactly through it), y = the azimuth of that approach; reached at half the duration
//   seam       x = log10(t0 - pi/2) (-13 .. -1; the leftmost column starts exactly on the seam t0 = pi/2),
//              y = heading, phi0 = 0.3
//   length     x = u in [-1, 1] with L = 3 + sign(u)(1 - 10^(-6|u|)), from 2 + 1e-6 to 4 - 1e-6, y = heading
//   drift      like launch, for long spans (default T = 1000): energy and rod-length drift
// Headings are angles in the tangent plane (0 = increasing t, pi/2 = increasing phi) at round-sphere
// speed 1/2.

#include <string>
#include <vector>

#include "contracts/run_config.hpp"
#include "linkage/chain.hpp"

namespace sl {

struct StabilityCell {
  int i = 0, j = 0;  // column (x) and row (y)
  double x = 0, y = 0;
  Chain chain;
  InitialState start;
};

std::vector<std::string> stabilityKindNames();
bool isStabilityKind(const std::string& kind);

// Axis labels for charts: {x label, y label}.
std::pair<std::string, std::string> stabilityAxisLabels(const std::string& kind);

// The default span of time for a kind (20, or 1000 for drift).
double defaultStabilityDuration(const std::string& kind);

// Cell (i, j) of a grid x grid sweep. For `pole`, the start is found by running the reference backwards
// from the closest approach (stateArrivingAt), over duration / 2.
StabilityCell stabilityCell(const std::string& kind, int grid, int i, int j, double duration);

}  // namespace sl

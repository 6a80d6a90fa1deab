#pragma once
// Shared fixtures for the simulation tests: the reference trajectories and the standard starts.

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "linkage/chain.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"

namespace sl::testing {

// One row of tests/data/reference/*.csv: time, phi, t, phidot, tdot, speed2, p1..p3.
struct ReferenceRow {
  double time, phi, t, phidot, tdot, speed2;
  Eigen::Matrix<double, 2, 3> hinges;
};

inline std::vector<ReferenceRow> loadReference(const std::string& name) {
  const std::string path = std::string(SL_SOURCE_DIR) + "/tests/data/reference/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  std::getline(in, line);
  std::vector<ReferenceRow> rows;
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    ReferenceRow r;
    fields >> r.time >> r.phi >> r.t >> r.phidot >> r.tdot >> r.speed2;
    for (int k = 0; k < 3; ++k) fields >> r.hinges(0, k) >> r.hinges(1, k);
    rows.push_back(r);
  }
  return rows;
}

// The reference starts (tests/data/reference/README.md): L = 3, chart-0 coordinates and rates.
inline InitialState genericStart(const Chain& chain) {
  return initialStateFromChart(chain, Eigen::Vector2d(0.3, 0.2), Eigen::Vector2d(0.5, 0.7));
}
inline InitialState seamStart(const Chain& chain) {
  return initialStateFromChart(chain, Eigen::Vector2d(-0.2, 1.0), Eigen::Vector2d(0.1, 1.0));
}

// A run configuration by the names a scene uses (parsed through the registry, as the scene loader does);
// unknown names throw std::invalid_argument.
inline RunConfig config(const std::string& method, const std::string& integrator = "dopri5", double tolerance = 1e-12) {
  RunConfig c;
  const auto m = parseKind(kMethods, method);
  const auto i = parseKind(kIntegrators, integrator);
  if (!m) throw std::invalid_argument("unknown method '" + method + "'");
  if (!i) throw std::invalid_argument("unknown integrator '" + integrator + "'");
  c.method = *m;
  c.integrator = *i;
  c.tolerance = tolerance;
  return c;
}

// Max hinge distance between two runs at the given times (both must reach them).
inline double maxHingeDistance(Trajectory& a, Trajectory& b, const std::vector<double>& times) {
  double worst = 0;
  for (double t : times) {
    const auto sa = a.sampleAt(t), sb = b.sampleAt(t);
    if (!sa || !sb) throw std::runtime_error("a run stopped before t = " + std::to_string(t));
    worst = std::max(worst, (sa->hinges - sb->hinges).cwiseAbs().maxCoeff());
  }
  return worst;
}

inline std::vector<double> evenTimes(double end, int count) {
  std::vector<double> times;
  for (int i = 0; i <= count; ++i) times.push_back(end * i / count);
  return times;
}

// A start whose motion passes straight through the north pole of chart 0 at time `arrival`: begin at the
// pole, run the ambient method backwards (negated velocity) at tolerance 1e-13, and turn around.
InitialState poleCrossingStart(const Chain& chain, double arrival, const Eigen::VectorXd& poleVelocity);

}  // namespace sl::testing

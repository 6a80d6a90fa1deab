#pragma once
// Two-point motions: the geodesics from one configuration to another (issue: inverse problems), by two
// independent routes.
//   Route 1, shooting: the geodesic from the start with initial velocity v over time 1 (so |v|_M is its
//   length); Gauss-Newton on the end point q(1; v) - target, the derivative dq(1)/dv from the linearised
//   flow (GeodesicFlow's variations: Jacobi fields through the start). Seeds: a fan of unit-speed directions
//   from the start, each followed up to the length bound, its closest approaches to the target kept.
//   Route 2, the discrete action (inverse/discrete_action.hpp): the discrete Lagrangian made stationary on nodes
//   between the end points, the nodes doubled until the extrapolated length and path stop changing. No ODE is
//   integrated.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contracts/registry.hpp"
#include "contracts/run_control.hpp"
#include "inverse/constrained_model.hpp"
#include "inverse/discrete_action.hpp"
#include "linkage/chain.hpp"

namespace sl {

constexpr int kPathSamples = 8;  // paths are compared at t = j / 8, j = 0..8
// Up to this many degrees of freedom (12 rods) shooting takes the exact derivative dq(1)/dv at every Newton
// step; beyond, once, then Broyden's updates (docs/geometry.md, "Long chains").
constexpr int kExactShootingFreedom = 10;
constexpr int kMaxExactShots = 6;  // beyond it, per Newton solve (each costs d bare shots)
// Beyond it, the fan's closest approaches shot as seeds (60 below).
constexpr std::size_t kLongChainSeeds = 8;

struct Connection {
  double length = 0;         // route 1: |v|_M
  Eigen::VectorXd velocity;  // initial velocity over time 1 (stacked hinges for a chain)
  double endError = 0;       // max |q(1) - target| over the coordinates
  int newtonIterations = 0;
  std::vector<Eigen::VectorXd> path;  // route 1 at t = j / kPathSamples
  int morseIndex = -1;                // conjugate points passed (chains: from the Jacobi fields of the ambient run)
  std::optional<DiscreteGeodesic> discrete;  // route 2, when it found this geodesic
  double lengthDifference = 0;               // |route 1 - route 2|
  double pathDifference = 0;                 // max over the samples and coordinates
};

struct ConnectOptions {
  double maxLength = 0;       // <= 0: 2.5 times the shortest found from the direct seed
  int directions = 48;        // the fan (for a 2-dimensional configuration space)
  double tolerance = 1e-12;   // the integrator's
  bool discreteRoute = true;  // run route 2 and compare
  // Asked between rays and shots: when it answers true the search ends with RunCancelled (SIGINT, SIGTERM).
  bool (*cancelled)() = nullptr;
  SearchProgress progress;  // told after each ray and shot, when given
};

// Route 1 from one initial velocity (over time 1): the converged connection, or nothing.
std::optional<Connection> shootConnection(const ConstrainedModel& model, const Eigen::VectorXd& from,
                                          const Eigen::VectorXd& to, Eigen::VectorXd velocity,
                                          double tolerance = 1e-12);

// Shapes closer than this (the mass-weighted norm of their hinge difference) are one shape: a motion between them
// would leave in a direction made of rounding noise. A motion back to the start is a closed geodesic (periodic).
inline constexpr double kSameShapeDistance = 1e-9;
bool sameShape(const ConstrainedModel& model, const Eigen::VectorXd& from, const Eigen::VectorXd& to);

// Both routes. For a chain (`chain` given) route 2 is also seeded from the great-circle arcs between the two
// sphere points (independent of route 1), and the Morse index is counted. Sorted by length.
std::vector<Connection> findConnections(const ConstrainedModel& model, const Chain* chain, const Eigen::VectorXd& from,
                                        const Eigen::VectorXd& to, const ConnectOptions& options);

// The shortest motion only, shot from the direct seed (the great-circle arc for a chain): what the benchmark
// times.
std::optional<Connection> directConnection(const ConstrainedModel& model, const Chain* chain,
                                           const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                           double tolerance = 1e-12);

// Seed paths along the great-circle arcs from the start's sphere point to the target's (short and long way).
std::vector<std::vector<Eigen::VectorXd>> sphereArcPaths(const Chain& chain, const Eigen::VectorXd& from,
                                                         const Eigen::VectorXd& to, int intervals);

// Conjugate points along the geodesic from `from` with velocity v over time 1, strictly inside (chains).
int morseIndexOnChain(const Chain& chain, const Eigen::VectorXd& from, const Eigen::VectorXd& velocity);

// The path of route 1 sampled at t = j / intervals, j = 0..intervals.
std::vector<Eigen::VectorXd> shootingPath(const ConstrainedModel& model, const Eigen::VectorXd& from,
                                          const Eigen::VectorXd& velocity, int intervals, double tolerance = 1e-12);

}  // namespace sl

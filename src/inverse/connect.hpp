#pragma once
// Two-point motions: the geodesics from one configuration to another (issue: inverse problems), by two
// independent routes.
//   Route 1, shooting: the geodesic from the start with initial velocity v over time 1 (so |v|_M is its
//   length); Gauss-Newton on the end point q(1; v) - target, the derivative dq(1)/dv from the linearised
//   flow (GeodesicFlow's variations: Jacobi fields through the start). Seeds: a fan of unit-speed directions
//   from the start, each followed up to the length bound, its closest approaches to the target kept.
//   Route 2, the discrete action: nodes q_0 = start, ..., q_K = target, the discrete Lagrangian
//   sum_i |q_(i+1) - q_i|_M^2 / (2h) made stationary under c(q_i) = 0 with multipliers,
//     M (q_(i+1) - 2 q_i + q_(i-1)) + G(q_i)^T mu_i = 0,  c(q_i) = 0,
//   solved by Newton's method on the block-tridiagonal system (sparse LU, one block per node), the nodes
//   doubled until the Richardson-extrapolated length and path stop changing. No ODE is integrated.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contracts/registry.hpp"
#include "contracts/run_control.hpp"
#include "inverse/constrained_model.hpp"
#include "linkage/chain.hpp"

namespace sl {

constexpr int kPathSamples = 8;  // paths are compared at t = j / 8, j = 0..8
// Up to this many degrees of freedom (12 rods) shooting takes the exact derivative dq(1)/dv at every Newton
// step; beyond, once, then Broyden's updates (docs/geometry.md, "Long chains").
constexpr int kExactShootingFreedom = 10;
constexpr int kMaxExactShots = 6;  // beyond it, per Newton solve (each costs d bare shots)
// Beyond it, the fan's closest approaches shot as seeds (60 below).
constexpr std::size_t kLongChainSeeds = 8;

struct DiscreteGeodesic {
  double length = 0;                  // Richardson-extrapolated
  double lengthChange = 0;            // between the last two extrapolants: the error estimate
  std::vector<Eigen::VectorXd> path;  // extrapolated, at t = j / kPathSamples
  int nodes = 0;                      // the finest K
  DiscreteSeed seed = DiscreteSeed::SphereArc;  // where the discrete path started
  Eigen::VectorXd startVelocity;      // the first chord over its time step at the finest K: a shooting seed
};

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

// Route 2 from a seed path (K + 1 nodes, K a multiple of kPathSamples, end points the fixed ones). `descend`:
// where Newton's method fails from the seed, descend on the action first (long chains; docs/geometry.md, "Long
// chains").
std::optional<DiscreteGeodesic> discreteGeodesic(const ConstrainedModel& model, std::vector<Eigen::VectorXd> seed,
                                                 DiscreteSeed seedKind, bool descend = false);

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

// The same from the discrete action (any model): route 2's equations solved on route 1's path sampled at
// `intervals` segments, the negative eigenvalues of their second variation on the constraints counted. O(n^3)
// per node by dense blocks, no determinant: what long chains use (docs/geometry.md, "Morse index"). -1 when
// route 2 does not converge there.
int discreteMorseIndex(const ConstrainedModel& model, const Eigen::VectorXd& from, const Eigen::VectorXd& velocity,
                       int intervals = 40);

// The path of route 1 sampled at t = j / intervals, j = 0..intervals.
std::vector<Eigen::VectorXd> shootingPath(const ConstrainedModel& model, const Eigen::VectorXd& from,
                                          const Eigen::VectorXd& velocity, int intervals, double tolerance = 1e-12);

}  // namespace sl

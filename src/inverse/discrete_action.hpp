#pragma once
// Route 2 of the two-point and closed-geodesic searches (inverse/connect.hpp, inverse/periodic.hpp): the discrete
// action. Nodes q_0 = start, ..., q_K = target, the discrete Lagrangian sum_i |q_(i+1) - q_i|_M^2 / (2h) made
// stationary under c(q_i) = 0 with multipliers,
//   M (q_(i+1) - 2 q_i + q_(i-1)) + G(q_i)^T mu_i = 0,  c(q_i) = 0,
// solved by Newton's method on the block-tridiagonal system (sparse LU, one block per node), the nodes doubled until
// the Richardson-extrapolated length and path stop changing. No ODE is integrated: independent of route 1's
// shooting. docs/geometry.md gives the derivation and the checks.

#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "contracts/registry.hpp"
#include "inverse/constrained_model.hpp"

namespace sl {

struct DiscreteGeodesic {
  double length = 0;                            // Richardson-extrapolated
  double lengthChange = 0;                      // between the last two extrapolants: the error estimate
  std::vector<Eigen::VectorXd> path;            // extrapolated, at t = j / kPathSamples
  int nodes = 0;                                // the finest K
  DiscreteSeed seed = DiscreteSeed::SphereArc;  // where the discrete path started
  Eigen::VectorXd startVelocity;                // the first chord over its time step at the finest K: a shooting seed
};

// Newton's method on the discrete Euler-Lagrange equations with multipliers; nodes 0 and K fixed.
bool solveDiscrete(const ConstrainedModel& model, std::vector<Eigen::VectorXd>& nodes, bool periodic = false);
// Descent on the discrete action from a seed far from any geodesic (long chains, docs/geometry.md, "Long
// chains"): Newton's steps on the stationarity equations with shift * M added to the action's second variation
// (Levenberg-Marquardt), the nodes projected back onto the constraints after each step, a step kept only when
// it lowers the action; the shift shrinks after a kept step and grows after a refused one. It ends near a
// local minimum (a geodesic without conjugate points inside), where plain Newton (solveDiscrete) takes over.
bool descendDiscrete(const ConstrainedModel& model, std::vector<Eigen::VectorXd>& nodes);
// The nodes doubled: the midpoint of each pair, projected onto the constraints, between them.
std::vector<Eigen::VectorXd> refine(const ConstrainedModel& model, const std::vector<Eigen::VectorXd>& nodes);

// Route 2 from a seed path (K + 1 nodes, K a multiple of kPathSamples, end points the fixed ones). `descend`:
// where Newton's method fails from the seed, descend on the action first (long chains; docs/geometry.md, "Long
// chains").
std::optional<DiscreteGeodesic> discreteGeodesic(const ConstrainedModel& model, std::vector<Eigen::VectorXd> seed,
                                                 DiscreteSeed seedKind, bool descend = false);

// The Morse index of the geodesic from `from` with velocity v over time 1 (morseIndexOnChain in connect.hpp by the
// Jacobi fields) from the discrete action (any model): route 2's equations solved on route 1's path sampled at
// `intervals` segments, the negative eigenvalues of their second variation on the constraints counted. O(n^3)
// per node by dense blocks, no determinant: what long chains use (docs/geometry.md, "Morse index"). -1 when
// route 2 does not converge there.
int discreteMorseIndex(const ConstrainedModel& model, const Eigen::VectorXd& from, const Eigen::VectorXd& velocity,
                       int intervals = 40);

}  // namespace sl

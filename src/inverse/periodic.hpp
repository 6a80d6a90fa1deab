#pragma once
// Closed geodesics (periodic force-free motions) of a 2-dimensional ConstrainedModel (the 4-rod chain's
// configuration sphere, a triaxial ellipsoid) and of a 1-dimensional one (the 3-rod chain's circle).
//   Route 1, shooting on the return map: unknowns the start's offset s across the motion, the turn theta of
//   its unit velocity and the period T; Gauss-Newton on (q(T) - q0, v(T) - v0), the derivative from the
//   flow's variations (the monodromy) and (v(T), a(T)) for T. Seeds: fans of unit-speed geodesics from a
//   few points, their near-returns in position and velocity.
//   Route 2 (independent lengths, no integration): the fixed set of an isometry reflecting the chain end for
//   end (a closed geodesic when the masses are symmetric), as a closed curve whose polygons are
//   Richardson-extrapolated; a closed geodesic through the two fixed points of the half-turn isometry is
//   twice a geodesic between them, found by the discrete action (connect.hpp); the ellipsoid's principal
//   ellipses by complete elliptic integrals; the 3-rod circle as a closed curve.
// Stability: the linearised return map on the Jacobi field across the motion, P = [[J1, J2], [J1', J2']] at
// T for J1 = 1, J1' = 0 and J2 = 0, J2' = 1 (det P = 1): elliptic for |tr P| < 2 with rotation number
// acos(tr P / 2) / (2 pi), hyperbolic for |tr P| > 2.
#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "contracts/registry.hpp"
#include "contracts/run_control.hpp"
#include "inverse/constrained_model.hpp"
#include "linkage/chain.hpp"

namespace sl {

// A closed geodesic's size against a great circle of the unit sphere, min(1, length / 2 pi). Near L = n the
// configuration sphere shrinks like sqrt(n - L) while the hinge coordinates stay of size 1: digits are lost in
// proportion, and the velocity turns 1 / size times faster. The search's thresholds and the closure are measured
// in the orbit's own units with it.
double orbitScale(double length);

// A chain symmetry a closed geodesic is invariant under: as a curve (mapped onto itself), or point by point (fixed).
struct ChainSymmetryOf {
  ChainSymmetry kind = ChainSymmetry::Mirror;
  bool fixed = false;
  bool operator==(const ChainSymmetryOf&) const = default;
};

struct ClosedGeodesic {
  double length = 0;                                // route 1: the period at unit speed
  Eigen::VectorXd point, velocity;                  // a unit-speed start on it (stacked hinges for a chain)
  double positionClosure = 0, velocityClosure = 0;  // max |q(T) - q0|, max |v(T) - v0|
  // max(position closure, orbitScale x velocity closure): the closure in the orbit's own units (the check's).
  double closure() const { return std::max(positionClosure, orbitScale(length) * velocityClosure); }
  bool simple = true;
  Eigen::Matrix2d monodromy = Eigen::Matrix2d::Identity();
  std::optional<Stability> stability;  // none on a circle (the 3-rod chain's: no return map)
  double rotationNumber = 0;  // elliptic: acos(tr / 2) / (2 pi), in (0, 1/2)
  Eigen::Vector2cd eigenvalues;
  std::vector<ChainSymmetryOf> symmetries;  // the chain symmetries it is invariant under (none / not a chain)
  bool invariantUnder(ChainSymmetry kind) const {
    return std::any_of(symmetries.begin(), symmetries.end(), [&](const ChainSymmetryOf& s) { return s.kind == kind; });
  }
  bool fixedBy(ChainSymmetry kind) const {
    return std::any_of(symmetries.begin(), symmetries.end(),
                       [&](const ChainSymmetryOf& s) { return s.kind == kind && s.fixed; });
  }
  std::optional<double> independentLength;  // route 2
  std::string independentRoute;
};

// Route 1 from a start (q0, v0 of unit speed) and a period guess. With a twist S (a linear isometry of the
// model that is an involution, e.g. the chain's mirror), the guess is for half a period and Newton solves
// (q, v)(T) = S (q0, v0): the closed geodesics invariant under S, found from half their length.
std::optional<ClosedGeodesic> shootClosedGeodesic(const ConstrainedModel& model, Eigen::VectorXd q0, Eigen::VectorXd v0,
                                                  double period, const Eigen::MatrixXd* twist = nullptr);

struct PeriodicOptions {
  double maxLength = 0;   // <= 0: 3 times the shortest one found (chains), 30 otherwise
  int directions = 36;    // per seed point, over a half turn
  Eigen::MatrixXd twist;  // if given: also seek returns to the twisted start (see shootClosedGeodesic)
  // Asked between rays and shots: when it answers true the search ends with RunCancelled (SIGINT, SIGTERM).
  bool (*cancelled)() = nullptr;
  SearchProgress progress;  // told after each ray and shot, when given
};

// A start (point, unit velocity) and period to shoot from directly.
struct ClosedGeodesicGuess {
  Eigen::VectorXd point, velocity;
  double period = 0;
};

// Closed geodesics of a 2-dimensional model up to the length bound, from fans at the given points (and from
// the given starts: point and direction), simple ones first then by length. For a chain (`chain` given) symmetries are
// named and route 2 run where it applies.
std::vector<ClosedGeodesic> findClosedGeodesics(
    const ConstrainedModel& model, const Chain* chain, const std::vector<Eigen::VectorXd>& seedPoints,
    const PeriodicOptions& options, const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>>& starts = {},
    const std::vector<ClosedGeodesicGuess>& guesses = {});

// The 4-rod chain: its seed points and its closed geodesics with both routes.
std::vector<ClosedGeodesic> chainClosedGeodesics(const Chain& chain, const PeriodicOptions& options);
// The 3-rod chain's configuration space is a circle: itself a closed geodesic.
ClosedGeodesic circleClosedGeodesic(const Chain& chain);
// The closed geodesics of a 3- or 4-rod chain, in the order `linkage periodic` lists them (the circle for 3 rods).
// `cancelled`: as PeriodicOptions::cancelled.
// Why the search would not end in useful time for this chain (its masses too far apart:
// limits::kMaxPeriodicMassRatio), or nothing. closedGeodesicsOf throws std::invalid_argument with it.
std::optional<std::string> periodicSearchRefusal(const Chain& chain);
// `progress`: as PeriodicOptions::progress.
std::vector<ClosedGeodesic> closedGeodesicsOf(const Chain& chain, double maxLength, bool (*cancelled)() = nullptr,
                                              const SearchProgress& progress = {});

// Route 2 pieces, exposed for the tests.
// The length of a closed curve from its polygons on 2^k points, Richardson-extrapolated (periodic, smooth).
double closedCurveLength(const ConstrainedModel& model, const std::function<Eigen::VectorXd(double)>& curve);
// The fixed set of the end-for-end reflection of a 4-rod chain (p_k -> (L - x, y) of p_(4-k)), at parameter w.
Eigen::VectorXd endSwapFixedPoint(const Chain& chain, double w);
// The two fixed points of the half turn p_k -> (L, 0) - p_(4-k) (p2 at (L/2, 0)).
std::vector<Eigen::VectorXd> halfTurnFixedPoints(const Chain& chain);
// Perimeter of the ellipse with semi-axes a, b (complete elliptic integral of the second kind).
double ellipsePerimeter(double a, double b);
// One of the chain's three symmetries (contracts/registry.hpp) applied to stacked hinges.
Eigen::VectorXd applyChainSymmetry(const Chain& chain, ChainSymmetry symmetry, const Eigen::VectorXd& q);

}  // namespace sl

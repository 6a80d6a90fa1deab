#pragma once
// Results that check themselves (docs/hardening.md, principle 22). A closed geodesic, a connection, a distance
// map and a holonomy each carry the numbers of their own check (a closure, an end error, a second route); a result is reported as
// found, or used as a scene's start, only when those numbers are within the bounds written here, once. What fails
// is listed as unconfirmed with the check that failed, typed: the command line puts it into words.

#include "inverse/connect.hpp"
#include "inverse/distance_map.hpp"
#include "inverse/holonomy.hpp"
#include "inverse/periodic.hpp"

namespace sl {

// A closed geodesic at unit speed: its closure in its own units, ClosedGeodesic::closure() (route 1 reaches about
// 1e-11; near L = n, where digits are lost with the sphere's size, about 1e-11 still in those units).
inline constexpr double kClosureBound = 1e-8;
// A connection: max |q(1) - target| over the coordinates (Newton stops at 1e-12).
inline constexpr double kEndErrorBound = 1e-8;
// Two routes to one length, relative (they agree to about 1e-11 where both converge).
inline constexpr double kRouteAgreement = 1e-8;
// A holonomy: its two transport routes' angles (they agree to about 1e-13), and the angle against Gauss-Bonnet, the
// enclosed curvature and the corners' angle excess (about 1e-12; the quadrature of the enclosed curvature is the
// weaker side, so its bound is looser).
inline constexpr double kHolonomyRouteBound = 1e-8;
inline constexpr double kGaussBonnetBound = 1e-6;
// The distance map's injectivity radius (nearest cut point on the grid) against Klingenberg's lemma, in grid cells.
inline constexpr double kInjectivityAgreementCells = 6;

enum class SelfCheck {
  confirmed,
  notFinite,       // a length or an error is NaN or infinite
  openClosure,     // the closed geodesic does not close within kClosureBound
  missedTarget,    // the connection ends farther than kEndErrorBound from its target
  routesDisagree,  // the independent route's length differs by more than kRouteAgreement
  radiiDisagree,   // the two injectivity radii differ by more than kInjectivityAgreementCells grid cells
  turningDisagrees,   // the two routes' holonomy angles differ by more than kHolonomyRouteBound
  gaussBonnetFails,   // the holonomy differs from the enclosed curvature or the angle excess by more than kGaussBonnetBound
};

SelfCheck selfCheck(const ClosedGeodesic& geodesic);
SelfCheck selfCheck(const Connection& connection);
SelfCheck selfCheck(const DistanceMap& map);
SelfCheck selfCheck(const Holonomy& holonomy);

}  // namespace sl

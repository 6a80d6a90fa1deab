#pragma once
// Coordinates on the unit sphere S^k in R^(k+1), k = n-2 (spec: "the sphere point").
//
// The spec's chart uses nested spherical coordinates, outermost first:
//   x = (cos c1 * y, sin c1),  y = the same construction on c2..,  innermost y = (cos t, sin t),
// so for 4 rods x = (cos phi cos t, cos phi sin t, sin phi). These coordinates are singular where the
// innermost pair vanishes (x1 = x2 = 0: the poles phi = +-pi/2 for 4 rods).
//
// An atlas: chart j is the same construction after a fixed permutation of the axes, so that its
// innermost pair is another pair of axes. Chart 0 is the spec's chart. Every point of the sphere has a
// chart whose innermost pair has norm >= 1/sqrt(number of charts); that norm is the chart's regularity.

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace sl {

template <class S>
using VectorX = Eigen::Matrix<S, Eigen::Dynamic, 1>;

// x = S(c) for chart 0.
template <class S>
VectorX<S> spherePointFromCoordinates(const VectorX<S>& c) {
  using std::cos;
  using std::sin;
  const Eigen::Index k = c.size();
  VectorX<S> x(k + 1);
  x(0) = cos(c(k - 1));
  x(1) = sin(c(k - 1));
  for (Eigen::Index level = k - 2; level >= 0; --level) {
    const Eigen::Index inner = k - level;  // size of y
    const S cosine = cos(c(level));
    for (Eigen::Index i = 0; i < inner; ++i) x(i) = x(i) * cosine;
    x(inner) = sin(c(level));
  }
  return x;
}

// Chart 0 coordinates of x (any positive multiple of a sphere point). The last coordinate t is
// unwrapped to lie within pi of previousT. At the chart's singular set the result is a valid
// preimage (the undetermined angles are set to 0).
Eigen::VectorXd coordinatesFromSpherePoint(const Eigen::VectorXd& x, double previousT = 0.0);

// Rates of chart 0 coordinates from a tangent vector xdot at x: solves dS(c) cdot = xdot. Up to
// kMaxQrCoordinates coordinates (chains of up to 64 rods) by QR on the whole Jacobian, O(k^3), the numbers
// every shipped scene was checked with; beyond, level by level (coordinateRatesByLevels), O(k^2).
inline constexpr Eigen::Index kMaxQrCoordinates = 62;
Eigen::VectorXd coordinateRatesFromSphereVelocity(const Eigen::VectorXd& coords, const Eigen::VectorXd& xdot);
// The same rates by the nested circles of S(c), O(k^2) (exposed for tests: equal to the QR route to rounding).
Eigen::VectorXd coordinateRatesByLevels(const Eigen::VectorXd& coords, const Eigen::VectorXd& xdot);

// Tangent vector dS(c) cdot (chart 0).
Eigen::VectorXd sphereVelocityFromCoordinateRates(const Eigen::VectorXd& coords, const Eigen::VectorXd& rates);

// === The atlas
int sphereChartCount(int ambientDimension);  // ambientDimension = k + 1 = n - 1
// perm[i] = the axis of x that receives component i of S(c) in chart j.
std::vector<int> sphereChartAxes(int ambientDimension, int chart);
// Norm of the chart's innermost pair at x: 0 on its singular set, larger is better conditioned.
double sphereChartRegularity(const Eigen::VectorXd& x, int chart);
// The chart with the largest regularity at x.
int bestSphereChart(const Eigen::VectorXd& x);

// x = P_j S(c) and its inverse for chart j.
template <class S>
VectorX<S> spherePointInChart(const std::vector<int>& axes, const VectorX<S>& c) {
  const VectorX<S> s = spherePointFromCoordinates<S>(c);
  VectorX<S> x(s.size());
  for (Eigen::Index i = 0; i < s.size(); ++i) x(axes[static_cast<size_t>(i)]) = s(i);
  return x;
}
Eigen::VectorXd coordinatesInChart(const std::vector<int>& axes, const Eigen::VectorXd& x, double previousT = 0.0);
// Sphere velocity xdot = d/dt x(c) in chart j, and chart j's rates from (x, xdot): tangent vectors between the
// sphere's R^(k+1) and a chart.
Eigen::VectorXd sphereVelocityInChart(const std::vector<int>& axes, const Eigen::VectorXd& coords,
                                      const Eigen::VectorXd& rates);
Eigen::VectorXd ratesInChart(const std::vector<int>& axes, const Eigen::VectorXd& coords, const Eigen::VectorXd& xdot);

}  // namespace sl

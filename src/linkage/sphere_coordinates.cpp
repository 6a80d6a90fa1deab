#include "linkage/sphere_coordinates.hpp"

#include <numeric>

#include <unsupported/Eigen/AutoDiff>

namespace sl {

Eigen::VectorXd coordinatesFromSpherePoint(const Eigen::VectorXd& x, double previousT) {
  const Eigen::Index k = x.size() - 1;
  Eigen::VectorXd c(k);
  // c_level = atan2(last component, norm of the rest): well conditioned at every latitude.
  for (Eigen::Index level = 0; level + 1 < k; ++level) {
    const Eigen::Index last = k - level;
    c(level) = std::atan2(x(last), x.head(last).norm());
  }
  const double t = std::atan2(x(1), x(0));
  c(k - 1) = previousT + std::remainder(t - previousT, 2.0 * M_PI);
  return c;
}

Eigen::VectorXd sphereVelocityFromCoordinateRates(const Eigen::VectorXd& coords, const Eigen::VectorXd& rates) {
  // Forward-mode derivative along the rates, exact to rounding.
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  VectorX<Dual> c(coords.size());
  for (Eigen::Index i = 0; i < coords.size(); ++i) c(i) = Dual(coords(i), Eigen::Matrix<double, 1, 1>(rates(i)));
  const VectorX<Dual> x = spherePointFromCoordinates<Dual>(c);
  Eigen::VectorXd xdot(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) xdot(i) = x(i).derivatives()(0);
  return xdot;
}

// S(c) nests circles: x = (cos c_0 y, sin c_0) with y = S(c_1, ...) one dimension down. The column of c_0 is
// (-sin c_0 y, cos c_0), of size 1; the others are cos c_0 times y's own columns, orthogonal to it. So
// cdot_0 = -sin c_0 (y . xdot_head) + cos c_0 xdot_last, and the rest are y's rates for xdot_head / cos c_0
// (all 0 where cos c_0 = 0: their columns vanish there, as least squares would give them). O(k^2).
Eigen::VectorXd coordinateRatesByLevels(const Eigen::VectorXd& coords, const Eigen::VectorXd& xdot) {
  const Eigen::Index k = coords.size();
  // The points of every level, innermost first built: level L is S(c_L, ..., c_(k-1)), k - L + 1 components.
  std::vector<Eigen::VectorXd> levels(static_cast<std::size_t>(k));
  levels[static_cast<std::size_t>(k - 1)] = Eigen::Vector2d(std::cos(coords(k - 1)), std::sin(coords(k - 1)));
  for (Eigen::Index level = k - 2; level >= 0; --level) {
    const Eigen::VectorXd& inner = levels[static_cast<std::size_t>(level + 1)];
    Eigen::VectorXd point(inner.size() + 1);
    point.head(inner.size()) = std::cos(coords(level)) * inner;
    point(inner.size()) = std::sin(coords(level));
    levels[static_cast<std::size_t>(level)] = std::move(point);
  }
  Eigen::VectorXd rates = Eigen::VectorXd::Zero(k);
  Eigen::VectorXd w = xdot;
  for (Eigen::Index level = 0; level < k - 1; ++level) {
    const Eigen::VectorXd& inner = levels[static_cast<std::size_t>(level + 1)];
    const double cosine = std::cos(coords(level)), sine = std::sin(coords(level));
    const Eigen::Index size = inner.size();
    rates(level) = -sine * inner.dot(w.head(size)) + cosine * w(size);
    if (cosine == 0) return rates;
    w = Eigen::VectorXd(w.head(size) / cosine);
  }
  rates(k - 1) = -std::sin(coords(k - 1)) * w(0) + std::cos(coords(k - 1)) * w(1);
  return rates;
}

Eigen::VectorXd coordinateRatesFromSphereVelocity(const Eigen::VectorXd& coords, const Eigen::VectorXd& xdot) {
  const Eigen::Index k = coords.size();
  if (k > kMaxQrCoordinates) return coordinateRatesByLevels(coords, xdot);
  Eigen::MatrixXd jacobian(k + 1, k);
  for (Eigen::Index j = 0; j < k; ++j)
    jacobian.col(j) = sphereVelocityFromCoordinateRates(coords, Eigen::VectorXd::Unit(k, j));
  // The columns are orthogonal (a product of circles); least squares is exact for tangent xdot.
  return jacobian.colPivHouseholderQr().solve(xdot);
}

int sphereChartCount(int ambientDimension) {
  if (ambientDimension <= 2) return 1;  // the circle needs one periodic chart
  if (ambientDimension == 3) return 2;
  return (ambientDimension + 1) / 2;  // pairs (0,1), (2,3), ..., and (N-1, 0) when N is odd
}

std::vector<int> sphereChartAxes(int ambientDimension, int chart) {
  std::vector<int> axes(static_cast<size_t>(ambientDimension));
  std::iota(axes.begin(), axes.end(), 0);
  if (chart == 0) return axes;
  int first = 2 * chart, second = 2 * chart + 1;
  if (ambientDimension == 3)
    first = 1, second = 2;  // x = (sin phi', cos phi' cos t', cos phi' sin t')
  else if (second >= ambientDimension)
    first = ambientDimension - 1, second = 0;
  std::vector<int> rest;
  for (int a = 0; a < ambientDimension; ++a)
    if (a != first && a != second) rest.push_back(a);
  axes = {first, second};
  axes.insert(axes.end(), rest.begin(), rest.end());
  return axes;
}

double sphereChartRegularity(const Eigen::VectorXd& x, int chart) {
  const std::vector<int> axes = sphereChartAxes(static_cast<int>(x.size()), chart);
  return std::hypot(x(axes[0]), x(axes[1])) / x.norm();
}

int bestSphereChart(const Eigen::VectorXd& x) {
  int best = 0;
  double bestRegularity = -1;
  for (int j = 0; j < sphereChartCount(static_cast<int>(x.size())); ++j) {
    const double regularity = sphereChartRegularity(x, j);
    if (regularity > bestRegularity) best = j, bestRegularity = regularity;
  }
  return best;
}

Eigen::VectorXd coordinatesInChart(const std::vector<int>& axes, const Eigen::VectorXd& x, double previousT) {
  Eigen::VectorXd s(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) s(i) = x(axes[static_cast<size_t>(i)]);
  return coordinatesFromSpherePoint(s, previousT);
}

Eigen::VectorXd sphereVelocityInChart(const std::vector<int>& axes, const Eigen::VectorXd& coords,
                                      const Eigen::VectorXd& rates) {
  const Eigen::VectorXd s = sphereVelocityFromCoordinateRates(coords, rates);
  Eigen::VectorXd xdot(s.size());
  for (Eigen::Index i = 0; i < s.size(); ++i) xdot(axes[static_cast<size_t>(i)]) = s(i);
  return xdot;
}

Eigen::VectorXd ratesInChart(const std::vector<int>& axes, const Eigen::VectorXd& coords, const Eigen::VectorXd& xdot) {
  Eigen::VectorXd s(xdot.size());
  for (Eigen::Index i = 0; i < s.size(); ++i) s(i) = xdot(axes[static_cast<size_t>(i)]);
  return coordinateRatesFromSphereVelocity(coords, s);
}

}  // namespace sl

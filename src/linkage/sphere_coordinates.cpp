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

Eigen::VectorXd coordinateRatesFromSphereVelocity(const Eigen::VectorXd& coords, const Eigen::VectorXd& xdot) {
  const Eigen::Index k = coords.size();
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

}  // namespace sl

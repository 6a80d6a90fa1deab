#include "frames/configuration_view.hpp"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// The Householder reflection taking the unit vector a to the last axis (identity if a already is it).
Eigen::MatrixXd reflectionOnto(const Eigen::VectorXd& a) {
  const Eigen::Index size = a.size();
  Eigen::VectorXd axis = Eigen::VectorXd::Unit(size, size - 1);
  Eigen::VectorXd w = a - axis;
  if (w.norm() < 1e-15) return Eigen::MatrixXd::Identity(size, size);
  w.normalize();
  return Eigen::MatrixXd::Identity(size, size) - 2.0 * w * w.transpose();
}

}  // namespace

ConfigurationView::ConfigurationView(int rods, const Eigen::VectorXd& startPoint) : rods_(rods) {
  if (rods_ >= 5) toNorthPole_ = reflectionOnto(startPoint.normalized());
}

ViewSpace ConfigurationView::space() const {
  if (rods_ == 3) return ViewSpace::Circle;
  return rods_ == 4 ? ViewSpace::Sphere : ViewSpace::Ball;
}

Vec3 ConfigurationView::project(const Eigen::VectorXd& x) const {
  if (rods_ == 3) return {x(0), x(1), 0.0};
  if (rods_ == 4) return {x(0), x(1), x(2)};
  const Eigen::VectorXd y = toNorthPole_ * x;  // the start is e_last
  const Eigen::Index last = y.size() - 1;
  const double across = y.head(last).norm();                             // sin(theta)
  const double theta = std::atan2(across, y(last));                      // the angle from the start, in [0, pi]
  if (!(across > 0)) return y(last) > 0 ? Vec3{} : Vec3{0.0, 0.0, 1.0};  // the start; the antipode (any direction)
  const double scale = theta / (std::acos(-1.0) * across);
  return {y(0) * scale, y(1) * scale, y(2) * scale};
}

}  // namespace sl

#include "frames/configuration_view.hpp"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// The unit vector w of the Householder reflection I - 2 w w^T taking the unit vector a to the last axis (zero, the
// identity, if a already is it).
Eigen::VectorXd reflectionOnto(const Eigen::VectorXd& a) {
  const Eigen::Index size = a.size();
  Eigen::VectorXd w = a - Eigen::VectorXd::Unit(size, size - 1);
  return w.norm() < 1e-15 ? Eigen::VectorXd::Zero(size) : Eigen::VectorXd(w.normalized());
}

}  // namespace

ConfigurationView::ConfigurationView(int rods, const Eigen::VectorXd& startPoint) : rods_(rods) {
  if (rods_ >= 5 && startPoint.size() > 0) reflection_ = reflectionOnto(startPoint.normalized());
}

ViewSpace ConfigurationView::space() const {
  if (rods_ == 3) return ViewSpace::Circle;
  return rods_ == 4 ? ViewSpace::Sphere : ViewSpace::Ball;
}

Vec3 ConfigurationView::project(const Eigen::VectorXd& x) const {
  if (rods_ == 3) return {x(0), x(1), 0.0};
  if (rods_ == 4) return {x(0), x(1), x(2)};
  // The start is e_last (no start point given: x as it is).
  const Eigen::VectorXd y = reflection_.size() == x.size() ? Eigen::VectorXd(x - 2.0 * reflection_.dot(x) * reflection_) : x;
  const Eigen::Index last = y.size() - 1;
  const double across = y.head(last).norm();                             // sin(theta)
  const double theta = std::atan2(across, y(last));                      // the angle from the start, in [0, pi]
  if (!(across > 0)) return y(last) > 0 ? Vec3{} : Vec3{0.0, 0.0, 1.0};  // the start; the antipode (any direction)
  const double scale = theta / (std::acos(-1.0) * across);
  return {y(0) * scale, y(1) * scale, y(2) * scale};
}

}  // namespace sl

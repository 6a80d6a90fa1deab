#include "frames/sphere_view.hpp"

#include <algorithm>

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

SphereView::SphereView(int rods, const Eigen::VectorXd& startPoint) : rods_(rods) {
  if (rods_ >= 5) toNorthPole_ = reflectionOnto(startPoint.normalized());
}

ViewSpace SphereView::space() const {
  if (rods_ == 3) return ViewSpace::Circle;
  return rods_ == 4 ? ViewSpace::Sphere : ViewSpace::Stereographic;
}

Vec3 SphereView::project(const Eigen::VectorXd& x) const {
  if (rods_ == 3) return {x(0), x(1), 0.0};
  if (rods_ == 4) return {x(0), x(1), x(2)};
  const Eigen::VectorXd y = toNorthPole_ * x;
  // Projection from the south pole -e_last; the start point (y = e_last) goes to 0. Points within
  // 1e-9 of the pole would go to infinity: they are drawn at a large finite distance instead.
  const double denominator = std::max(1.0 + y(y.size() - 1), 1e-9);
  return {y(0) / denominator, y(1) / denominator, y(2) / denominator};
}

}  // namespace sl

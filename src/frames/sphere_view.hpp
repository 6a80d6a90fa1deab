#pragma once
// Where a configuration (a point x of S^(n-2)) is drawn in the sphere panel (frame_state.hpp, ViewSpace).
//   3 rods: x in R^2 is drawn on the equator circle (x0, x1, 0).
//   4 rods: x itself, the point (cos phi cos t, cos phi sin t, sin phi) of S^2.
//   5+ rods: stereographic projection of S^(n-2) from the antipode of the start point, so the start sits
//            at the origin and the hemisphere around it fills the unit ball; for n = 5 this is a
//            faithful (conformal, one-to-one) picture of S^3 minus one point in R^3. For n > 5 the first
//            three of the n-2 projected coordinates are shown.

#include <Eigen/Dense>

#include "frames/frame_state.hpp"

namespace sl {

class SphereView {
 public:
  SphereView(int rods, const Eigen::VectorXd& startPoint);
  ViewSpace space() const;
  Vec3 project(const Eigen::VectorXd& spherePoint) const;

 private:
  int rods_;
  Eigen::MatrixXd toNorthPole_;  // an orthogonal map taking the start point to the last axis e_(n-2)
};

}  // namespace sl

#pragma once
// Where a configuration (a point x of S^(n-2)) is drawn in the sphere panel (frame_state.hpp, ViewSpace).
//   3 rods: x in R^2 is drawn on the equator circle (x0, x1, 0).
//   4 rods: x itself, the point (cos phi cos t, cos phi sin t, sin phi) of S^2.
//   5+ rods: S^(n-2) mapped into the unit ball by the azimuthal equidistant projection about the start point
//            (the inverse of the exponential map there): the start sits at the centre, a point at angle theta
//            from it lands at distance theta / pi in its direction, so the great sphere orthogonal to the
//            start is the sphere of radius 1/2 and the antipode is the boundary. For n = 5 this is one-to-one
//            on S^3 minus the antipode, and every path stays inside the ball. (A stereographic projection
//            would send the neighbourhood of the antipode to infinity, and paths off the panel.)
//            A path through the antipode reappears on the opposite side of the boundary; the renderer
//            leaves a gap there. For n > 5 the first three of the n-2 directions are shown.
// A slack chain (L <= n-2) has no sphere: constructed with an empty start point, the view draws nothing.

#include <Eigen/Dense>

#include "contracts/frame_state.hpp"

namespace sl {

class ConfigurationView {
 public:
  ConfigurationView(int rods, const Eigen::VectorXd& startPoint);
  ViewSpace space() const;
  Vec3 project(const Eigen::VectorXd& spherePoint) const;

 private:
  int rods_;
  // The Householder reflection I - 2 w w^T taking the start point to the last axis e_(n-2) (w = 0: identity),
  // applied in O(n): chains of a thousand rods have a 999-dimensional sphere.
  Eigen::VectorXd reflection_;
};

}  // namespace sl

#pragma once
// Shared by the inverse stage's tests.
#include <Eigen/Dense>

#include "inverse/constrained_model.hpp"
#include "linkage/chart.hpp"

namespace sl {

// The stacked hinges of a 4-rod chain at chart 0's (phi, t).
inline Eigen::VectorXd pointOf(const Chain& chain, double phi, double t) {
  Eigen::VectorXd c(2);
  c << phi, t;
  return ConstrainedModel::stack(hingePositions(chain, c));
}

}  // namespace sl

#pragma once
// What a run uses of its chain at every step, computed once when the run is bound to the chain: the chart's
// amplitude alpha_n(L) (spec section 2, linkage/chart.hpp) and the ambient mass matrix in both of its forms
// (spec section 1). The functions taking a Chain compute these on each call; the hot paths take these.

#include <Eigen/Dense>

#include "linkage/chain.hpp"

namespace sl {

struct ChainConstants {
  explicit ChainConstants(const Chain& chain);  // throws std::invalid_argument for an invalid chain

  Chain chain;
  double amplitude = 0;         // alpha_n(L): cos alpha = (L^2 + 1 - (n-1)^2) / (2L)
  AmbientMassMatrix mass;       // block-tridiagonal, scalar blocks
  // The same as a 2(n-1) square matrix on q = (p1x, p1y, p2x, ...), for the chart methods' chains (at most
  // limits::kMaxRods rods); empty for longer ones, where it would cost every run 32 MB at 1000 rods.
  Eigen::MatrixXd stackedMass;
};

}  // namespace sl

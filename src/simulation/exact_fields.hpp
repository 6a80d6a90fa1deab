#pragma once
// Geodesic accelerations from exact derivatives of the chart Psi (forward-mode AD), any n, any masses,
// in any chart of the atlas (sphereChartAxes). Two independent assemblies of the same geometry:
//   christoffel: h = J^T M J differentiated by nested AD, then a^i = -Gamma^i_jk v^j v^k (spec section 4);
//   embedded:    the normal-acceleration condition h a = -J^T M (q_bc v^b v^c) (spec section 5).

#include <vector>

#include <Eigen/Dense>

#include "linkage/chain_constants.hpp"

namespace sl {

Eigen::VectorXd christoffelAcceleration(const ChainConstants& bound, const std::vector<int>& axes,
                                        const Eigen::VectorXd& coords, const Eigen::VectorXd& rates);

Eigen::VectorXd embeddedAcceleration(const ChainConstants& bound, const std::vector<int>& axes,
                                     const Eigen::VectorXd& coords, const Eigen::VectorXd& rates);

// The Christoffel symbols themselves, Gamma[i](j, k) = Gamma^i_jk, for tests.
std::vector<Eigen::MatrixXd> christoffelSymbols(const ChainConstants& bound, const std::vector<int>& axes,
                                                const Eigen::VectorXd& coords);

}  // namespace sl

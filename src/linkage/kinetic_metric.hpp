#pragma once
// The kinetic metric on the sphere (spec sections 2-3): h = J^T M J, the pullback of the ambient
// kinetic metric M along the chart. Three independent routes, tested against each other:
//   - the spec's closed form for 4 rods (unit hinge masses, massless rods), made numerically stable;
//   - the pullback with J from forward-mode AD of the chart, any n and any masses;
//   - the pullback with J from central differences of the chart.
// The closed form as printed is kept too: the published methods use it.

#include <vector>

#include <Eigen/Dense>

#include "linkage/chain.hpp"

namespace sl {

// Spec section 3, 4 rods, chart (phi, t), unit hinge masses and massless rods. Stable: nu_in in sinc
// form and Omega_a = Im(d_a p2 / p2) + d_a nu_in / |p2| (from |p2|^2 + nu_in^2 = 4), so nothing
// divides by nu_in at the seam t = +-pi/2. Singular only at the poles phi = +-pi/2, like the chart.
Eigen::Matrix2d kineticMetricClosedForm(double baseLength, double phi, double t);

// metric4 exactly as printed in the spec (acos helpers, nu_in with its |cos t| < 1e-6 branch,
// Omega_a with d_a|p2| / nu_in). Loses digits near the seam and fails on it.
Eigen::Matrix2d kineticMetricPublished(double baseLength, double phi, double t);

// Its two levels, for stencils that share work: linkage/published_metric_levels.hpp.

// h = J^T M J with J = d q / d coords by forward-mode AD, in the chart with the given axes
// (sphereChartAxes; chart 0 is the spec's).
Eigen::MatrixXd kineticMetricPullback(const Chain& chain, const std::vector<int>& axes, const Eigen::VectorXd& coords);

// The same pullback with J from central differences of step eps.
Eigen::MatrixXd kineticMetricCentralDifferences(const Chain& chain, const std::vector<int>& axes,
                                                const Eigen::VectorXd& coords, double eps = 1e-6);

// M applied to stacked hinge vectors q = (p1x, p1y, p2x, ...): the 2(n-1) x 2(n-1) ambient matrix.
Eigen::MatrixXd stackedMassMatrix(const Chain& chain);

}  // namespace sl

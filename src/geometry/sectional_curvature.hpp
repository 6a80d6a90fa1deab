#pragma once
// Sectional curvature of the configuration sphere S^(n-2) of an n-rod chain, any n >= 4 (docs/geometry.md,
// "Sectional curvature"). For 4 rods the one tangent plane's curvature is the Gaussian curvature K
// (geometry/curvature.hpp); from 5 rods on every tangent plane has its own, and Jacobi fields along a motion are
// governed by the curvature of the plane of the velocity and the field (J'' + R(J, v)v = 0).
//
// Two independent routes, sharing nothing past the chart Psi (linkage/chart.hpp):
//   Gauss equation (ambient):  K(X, Y) = (<II(X,X), II(Y,Y)>_M - |II(X,Y)|_M^2) / (|X|^2 |Y|^2 - <X,Y>^2),
//     II(X, Y) = the M-orthogonal normal part of q_XY = d^2 Psi[X, Y] (spec section 1's mass inner product),
//     from one second-order jet of Psi per pair of directions (geometry/second_order_jet.hpp);
//   Riemann tensor of the chart metric (intrinsic): R(X,Y,Y,X) from the metric g = J^T M J, its exact first and
//     second derivatives along the plane and its Christoffel symbols,
//       R(X,Y,Y,X) = d_X d_Y g_XY - (d_Y d_Y g_XX + d_X d_X g_YY) / 2 + g(G(X,Y), G(X,Y)) - g(G(X,X), G(Y,Y)),
//     G(P, Q) = Gamma^i_jk P^j Q^k, with Psi's third derivatives (forward AD of the Jacobian, each entry a
//     second-order jet along the plane).
// Tangent vectors are given as sphere velocities (tangent vectors of S^(n-2) in R^(n-1), like Sample's
// sphereVelocity); every evaluation uses the atlas chart best conditioned at the point, so no point is special.

#include <array>
#include <vector>

#include <Eigen/Dense>

#include "linkage/chain_constants.hpp"

namespace sl {

// The range of the sectional curvature over the tangent planes at one point, with planes attaining it.
struct SectionalRange {
  double minimum = 0, maximum = 0;
  // Each plane as two g-orthonormal sphere velocities.
  Eigen::VectorXd minimumPlane[2], maximumPlane[2];
};

// The curvature of the plane spanned by X and Y at the sphere point x: the Gauss-equation route. Throws
// std::invalid_argument if X and Y do not span a plane (or the chain has fewer than 4 rods).
double sectionalCurvature(const ChainConstants& bound, const Eigen::VectorXd& spherePoint, const Eigen::VectorXd& X,
                          const Eigen::VectorXd& Y);

// The same from the Riemann tensor of the chart metric: the intrinsic route (tests and cross-checks).
double sectionalCurvatureIntrinsic(const ChainConstants& bound, const Eigen::VectorXd& spherePoint,
                                   const Eigen::VectorXd& X, const Eigen::VectorXd& Y);

// Minimum and maximum over every tangent plane at x (Gauss route). 4 rods: both K. 5 rods (a 3-dimensional
// tangent space): exact, as the extreme eigenvalues of the curvature operator on bivectors, each of which is a
// plane there. 6 and more: the largest and smallest of alternating Rayleigh-quotient ascents over planes started
// from every pair of the curvature operator's eigen-directions, each a local extremum (docs/geometry.md).
SectionalRange sectionalCurvatureRange(const ChainConstants& bound, const Eigen::VectorXd& spherePoint);

// The smallest and largest curvature of the planes through the tangent vector v at x: {min, max} of K(v, w) over w.
// A motion's Jacobi fields feel these (J'' + R(J, v)v = 0): where both are positive, nearby motions refocus.
std::array<double, 2> sectionalCurvatureThrough(const ChainConstants& bound, const Eigen::VectorXd& spherePoint,
                                                const Eigen::VectorXd& velocity);

}  // namespace sl

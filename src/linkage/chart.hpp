#pragma once
// The chart Psi^n_L (spec section 2 and the recursive suspension of post 2): a point x of the unit
// sphere S^(n-2) to the interior hinge positions p1..p(n-1) of the chain.
//
// Recursion, for an m-rod chain whose base runs from 0 to (d, 0) (the top level is m = n, d = L):
//   its amplitude alpha_m(d):  cos alpha = (d^2 + 1 - (m-1)^2) / (2d)
//   last rod angle             theta = alpha * x_last
//   last hinge                 p_(m-1) = d - e^(i theta),   sub-base d' = |p_(m-1)|
//   the (m-1)-chain on d' with sphere point x_rest / |x_rest|, computed with its base on the real
//   axis and rotated by p_(m-1)/d'; down to 2 rods, whose elbow is at angle +-alpha_2(d').
//
// The textbook form divides 0 by 0 wherever an inner chain is straight (x_rest = 0: the poles, and
// for the innermost elbow the seam t = +-pi/2, where the spec's nu_in degenerates). Here each level
// receives its sphere point pre-scaled by its amplitude, v = alpha * x (|v| = alpha), and every
// quotient of vanishing quantities is rewritten exactly:
//   alpha^2 - theta^2 = |v_rest|^2 =: rho2,
//   d'^2 = (d-1)^2 + 4d sin^2(theta/2),
//   (m-1)^2 - d'^2 = 2d(cos theta - cos alpha) = d * rho2 * sinc((alpha+theta)/2) * sinc((alpha-theta)/2),
//   sin^2(alpha'/2) = (m-1-d')(m-3+d') / (4d') = rho2 * Q2,
//   alpha' / |v_rest| = 2 sqrt(Q2) * asin(z)/z with z^2 = rho2 * Q2,
//   v' = v_rest * alpha' / |v_rest|.
// Every step is smooth in x, so forward-mode AD gives exact derivatives everywhere, poles included,
// and every rod has length 1 to rounding. (For n = 4 the elbow offset is nu_in = 2 sin v'', the
// cancellation-free form of the spec's cos t * sqrt(2d(cos theta_in - cos alpha_in)/cos^2 t).)

#include <cmath>

#include <Eigen/Dense>

#include "linkage/chain.hpp"
#include "linkage/chain_constants.hpp"
#include "linkage/smooth_functions.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {

template <class S>
using HingeMatrix = Eigen::Matrix<S, 2, Eigen::Dynamic>;  // column k = p_(k+1)

// alpha_m(d) from cos alpha = (d^2 + 1 - (m-1)^2)/(2d), as 2 atan2(sqrt(1 - cos), sqrt(1 + cos)) with
// both factors in product form: no cancellation near alpha = 0 (d -> m) or alpha = pi (d -> m-2).
double chainAmplitude(int rods, double base);

namespace detail {

// Hinges of an m-rod chain on base d in its own frame, from its scaled sphere point v (|v| = alpha).
template <class S>
void scaledChainHinges(int m, const S& d, const VectorX<S>& v, const S& alpha, HingeMatrix<S>& hinges) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (m == 2) {  // the elbow, at signed angle v(0) from the base: p1 = (d/2, sin v)
    hinges.resize(2, 1);
    hinges(0, 0) = d / 2.0;
    hinges(1, 0) = sin(v(0));
    return;
  }
  const S theta = v(m - 2);
  const VectorX<S> rest = v.head(m - 2);
  const S rho2 = rest.squaredNorm();
  // alpha + theta and alpha - theta, the small one from their product rho2.
  S sum, difference;
  if (valueOf(theta) >= 0.0) {
    sum = alpha + theta;
    difference = valueOf(sum) > 0.0 ? S(rho2 / sum) : S(0.0 * rho2);
  } else {
    difference = alpha - theta;
    sum = rho2 / difference;
  }
  const S sincProduct = sinc<S>(sum / 2.0) * sinc<S>(difference / 2.0);
  const double outer = m - 1.0;
  // d'^2 = (d-1)^2 + 4d sin^2(theta/2): a sum of non-negative terms (d > m-2 >= 1), never a difference.
  const S halfSine = sin(theta / 2.0);
  // AutoDiff: a constant base (the top level's L) has empty derivatives, which Eigen pads with zeros only
  // in some operations (not in the sum below): give it theta's derivative size first.
  const S base = d + 0.0 * theta;
  const S subBase = sqrt((base - 1.0) * (base - 1.0) + 4.0 * base * halfSine * halfSine);
  const S q2 = d * sincProduct * (m - 3.0 + subBase) / (4.0 * subBase * (outer + subBase));
  const S ratio = 2.0 * sqrt(q2) * asincOfSquare<S>(rho2 * q2);  // alpha' / |v_rest|
  const VectorX<S> innerV = rest * ratio;
  const S innerAlpha = guardedSqrt(rho2) * ratio;

  HingeMatrix<S> inner;
  scaledChainHinges<S>(m - 1, subBase, innerV, innerAlpha, inner);

  const S lastX = d - cos(theta), lastY = -sin(theta);
  const S ux = lastX / subBase, uy = lastY / subBase;  // rotation taking the sub-base onto p_(m-1)
  hinges.resize(2, m - 1);
  for (int k = 0; k < m - 2; ++k) {
    hinges(0, k) = ux * inner(0, k) - uy * inner(1, k);
    hinges(1, k) = uy * inner(0, k) + ux * inner(1, k);
  }
  hinges(0, m - 2) = lastX;
  hinges(1, m - 2) = lastY;
}

}  // namespace detail

// Psi^n_L(x) for a unit vector x in R^(n-1), with the chain's amplitude alpha_n(L) given.
template <class S>
HingeMatrix<S> hingePositionsOnSphere(const Chain& chain, double alpha, const VectorX<S>& x) {
  HingeMatrix<S> hinges;
  const VectorX<S> v = x * alpha;
  detail::scaledChainHinges<S>(chain.rods, S(chain.baseLength), v, S(alpha), hinges);
  return hinges;
}
template <class S>
HingeMatrix<S> hingePositionsOnSphere(const ChainConstants& bound, const VectorX<S>& x) {
  return hingePositionsOnSphere<S>(bound.chain, bound.amplitude, x);
}
template <class S>
HingeMatrix<S> hingePositionsOnSphere(const Chain& chain, const VectorX<S>& x) {
  return hingePositionsOnSphere<S>(chain, chainAmplitude(chain.rods, chain.baseLength), x);
}

// Psi in a chart of the atlas (chart 0 = the spec's coordinates, (phi, t) for 4 rods).
template <class S>
HingeMatrix<S> hingePositionsInChart(const ChainConstants& bound, const std::vector<int>& axes,
                                     const VectorX<S>& coords) {
  return hingePositionsOnSphere<S>(bound, spherePointInChart<S>(axes, coords));
}
template <class S>
HingeMatrix<S> hingePositionsInChart(const Chain& chain, const std::vector<int>& axes, const VectorX<S>& coords) {
  return hingePositionsOnSphere<S>(chain, spherePointInChart<S>(axes, coords));
}

// Double-precision conveniences, chart 0.
Eigen::Matrix2Xd hingePositions(const Chain& chain, const Eigen::VectorXd& coords);
Eigen::Matrix2Xd hingePositionsAt(const Chain& chain, const Eigen::VectorXd& spherePoint);

// The inverse of Psi: hinge positions to the unit sphere point. Well conditioned at the seams (the
// innermost elbow is read off as an angle, not an arcsine) and near the poles (the inner chains'
// shapes give the pole distance, not the last rod's angle).
Eigen::VectorXd spherePointFromHinges(const Chain& chain, const Eigen::Matrix2Xd& hinges);

// Chart 0 coordinates of a configuration (t unwrapped near previousT).
Eigen::VectorXd coordinatesFromHinges(const Chain& chain, const Eigen::Matrix2Xd& hinges, double previousT = 0.0);

// Jacobian of the stacked hinges q = (p1x, p1y, p2x, ...) with respect to the coordinates of a chart,
// by forward-mode AD: 2(n-1) x (n-2).
Eigen::MatrixXd chartJacobian(const Chain& chain, const std::vector<int>& axes, const Eigen::VectorXd& coords);
Eigen::MatrixXd chartJacobian(const ChainConstants& bound, const std::vector<int>& axes, const Eigen::VectorXd& coords);

// Jacobian of q with respect to the sphere point x in R^(n-1) (the derivative of Psi as a map on
// R^(n-1) restricted to unit vectors; apply it to tangent vectors only): 2(n-1) x (n-1).
Eigen::MatrixXd sphereJacobian(const Chain& chain, const Eigen::VectorXd& spherePoint);

}  // namespace sl

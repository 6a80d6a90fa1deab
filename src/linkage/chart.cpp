#include "linkage/chart.hpp"

#include <algorithm>

namespace sl {

double chainAmplitude(int rods, double base) {
  const double m = rods;
  const double oneMinusCos = std::max((m - base) * (m - 2.0 + base), 0.0);  // times 2d
  const double onePlusCos = std::max((base + 2.0 - m) * (base + m), 0.0);   // times 2d
  return 2.0 * std::atan2(std::sqrt(oneMinusCos), std::sqrt(onePlusCos));
}

Eigen::Matrix2Xd hingePositions(const Chain& chain, const Eigen::VectorXd& coords) {
  return hingePositionsOnSphere<double>(chain, spherePointFromCoordinates<double>(coords));
}

Eigen::Matrix2Xd hingePositionsAt(const Chain& chain, const Eigen::VectorXd& spherePoint) {
  return hingePositionsOnSphere<double>(chain, spherePoint);
}

namespace {

// The scaled sphere point v (|v| = alpha_m(d)) of an m-rod chain on base d, from its hinges in its own
// frame: the inverse of detail::scaledChainHinges, level by level.
Eigen::VectorXd scaledPointFromHinges(int m, double d, const Eigen::Matrix2Xd& hinges) {
  if (m == 2) return Eigen::VectorXd::Constant(1, std::atan2(hinges(1, 0), hinges(0, 0)));  // the elbow angle
  const Eigen::Vector2d last = hinges.col(m - 2);
  const double theta = std::atan2(-last.y(), d - last.x());
  const double subBase = last.norm();
  const Eigen::Vector2d u = last / subBase;
  Eigen::Matrix2Xd inner(2, m - 2);
  for (int k = 0; k < m - 2; ++k)  // rotate by conj(u) into the inner chain's frame
    inner.col(k) << u.x() * hinges(0, k) + u.y() * hinges(1, k), -u.y() * hinges(0, k) + u.x() * hinges(1, k);
  const Eigen::VectorXd innerV = scaledPointFromHinges(m - 1, subBase, inner);
  const double innerAlpha = innerV.norm();

  // |v_rest| = sin(alpha'/2) / Q: from the inner chain's shape, not from alpha - theta.
  const double alpha = chainAmplitude(m, d);
  const double sincProduct = sinc(0.5 * (alpha + theta)) * sinc(0.5 * (alpha - theta));
  const double outer = m - 1.0;
  const double q = std::sqrt(d * sincProduct * (m - 3.0 + subBase) / (4.0 * subBase * (outer + subBase)));
  Eigen::VectorXd v(m - 1);
  v.head(m - 2) = innerV * (0.5 * sinc(0.5 * innerAlpha) / q);
  v(m - 2) = theta;
  return v;
}

}  // namespace

Eigen::VectorXd spherePointFromHinges(const Chain& chain, const Eigen::Matrix2Xd& hinges) {
  const Eigen::VectorXd v = scaledPointFromHinges(chain.rods, chain.baseLength, hinges);
  return v.normalized();
}

Eigen::VectorXd coordinatesFromHinges(const Chain& chain, const Eigen::Matrix2Xd& hinges, double previousT) {
  return coordinatesFromSpherePoint(spherePointFromHinges(chain, hinges), previousT);
}

namespace {
// Forward AD with `Derivatives` as the dual numbers' derivative vectors, k = at.size() of them.
template <class Derivatives, class Map>
Eigen::MatrixXd forwardJacobianWith(const Eigen::VectorXd& at, Map&& map, Eigen::Index outputs) {
  using Dual = Eigen::AutoDiffScalar<Derivatives>;
  const Eigen::Index k = at.size();
  VectorX<Dual> arg(k);
  for (Eigen::Index i = 0; i < k; ++i) arg(i) = Dual(at(i), k, i);
  const HingeMatrix<Dual> hinges = map(arg);
  Eigen::MatrixXd jacobian(outputs, k);
  for (Eigen::Index h = 0; h < hinges.cols(); ++h)
    for (int c = 0; c < 2; ++c) {
      const auto& derivative = hinges(c, h).derivatives();
      if (derivative.size())
        jacobian.row(2 * h + c) = derivative.transpose();
      else
        jacobian.row(2 * h + c).setZero();
    }
  return jacobian;
}

// Up to this many variables the derivative vectors live on the stack: a heap vector per intermediate value cost
// most of a sample's time (a 64-member fan samples every member every frame). The same operations on the same
// numbers either way, so the same Jacobian to the bit.
constexpr int kStackDerivatives = 8;

template <class Map>
Eigen::MatrixXd forwardJacobian(const Eigen::VectorXd& at, Map&& map, Eigen::Index outputs) {
  if (at.size() <= kStackDerivatives)
    return forwardJacobianWith<Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kStackDerivatives, 1>>(at, map, outputs);
  return forwardJacobianWith<Eigen::VectorXd>(at, map, outputs);
}
}  // namespace

Eigen::MatrixXd chartJacobian(const Chain& chain, const std::vector<int>& axes, const Eigen::VectorXd& coords) {
  return forwardJacobian(
      coords,
      [&]<class Dual>(const VectorX<Dual>& c) { return hingePositionsInChart<Dual>(chain, axes, c); },
      2 * chain.hingeCount());
}

Eigen::MatrixXd chartJacobian(const ChainConstants& bound, const std::vector<int>& axes,
                              const Eigen::VectorXd& coords) {
  return forwardJacobian(
      coords,
      [&]<class Dual>(const VectorX<Dual>& c) { return hingePositionsInChart<Dual>(bound, axes, c); },
      2 * bound.chain.hingeCount());
}

Eigen::MatrixXd sphereJacobian(const Chain& chain, const Eigen::VectorXd& spherePoint) {
  return forwardJacobian(
      spherePoint, [&]<class Dual>(const VectorX<Dual>& x) { return hingePositionsOnSphere<Dual>(chain, x); },
      2 * chain.hingeCount());
}

}  // namespace sl

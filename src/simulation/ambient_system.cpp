#include "simulation/ambient_system.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "linkage/chart.hpp"

namespace sl {

namespace {
constexpr int maxNewtonIterations = 8;
}

double chartZeroAngleForUnwrapping(const Chain& chain, const Eigen::Matrix2Xd& hinges, double previousT) {
  // Chart 0's angle t is the direction of the innermost pair of the sphere point, which the chart maps to
  // the 3-rod sub-chain p0 p1 p2 on the base from 0 to p3 (to (L, 0) for n = 3): its scaled point is
  // (v0, v1) = (side * sqrt(alpha3^2 - theta3^2), theta3), theta3 = that chain's last rod angle and side =
  // which side of 0->p2 the elbow p1 lies on (linkage/chart.hpp). O(1) for any n, instead of inverting the
  // whole chart; accurate to ~1e-8 near the seams, plenty to choose the branch of t.
  const Eigen::Vector2d base =
      chain.rods == 3 ? Eigen::Vector2d(chain.baseLength, 0.0) : Eigen::Vector2d(hinges.col(2));
  const double d = base.norm();
  const Eigen::Vector2d u = base / d, p1 = hinges.col(0), p2 = hinges.col(1);
  const Eigen::Vector2d inFrame(u.x() * p2.x() + u.y() * p2.y(), -u.y() * p2.x() + u.x() * p2.y());
  const double theta = std::atan2(-inFrame.y(), d - inFrame.x());
  const double alpha = chainAmplitude(3, d);
  const double side = p2.x() * p1.y() - p2.y() * p1.x() >= 0 ? 1.0 : -1.0;
  const double t = std::atan2(theta, side * std::sqrt(std::max(alpha * alpha - theta * theta, 0.0)));
  return previousT + std::remainder(t - previousT, 2.0 * M_PI);
}

Eigen::VectorXd sphereVelocityFromHingeVelocities(const Chain& chain, const Eigen::VectorXd& x,
                                                  const Eigen::Matrix2Xd& hingeVelocities) {
  const Eigen::Index dim = x.size(), rows = 2 * chain.hingeCount();
  Eigen::MatrixXd system(rows + 1, dim);
  Eigen::VectorXd rhs(rows + 1);
  if (chain.rods <= 64) {  // exact: dPsi by forward AD (O(n^3) in n, fine for the sizes people look at)
    system.topRows(rows) = sphereJacobian(chain, x);
  } else {  // large n: the AD Jacobian is too slow; difference the inverse chart along the motion instead,
    // (x(q + h v) - x(q - h v)) / 2h, accurate to ~1e-8: for display only.
    const double h = 1e-6;
    Eigen::Matrix2Xd ahead = hingePositionsAt(chain, x);
    Eigen::Matrix2Xd behind = ahead;
    ahead += h * hingeVelocities;
    behind -= h * hingeVelocities;
    Eigen::VectorXd xdot = (spherePointFromHinges(chain, ahead) - spherePointFromHinges(chain, behind)) / (2 * h);
    return xdot - x * x.dot(xdot);
  }
  system.row(rows) = x.transpose();  // tangency x . xdot = 0
  rhs.head(rows) = Eigen::Map<const Eigen::VectorXd>(hingeVelocities.data(), rows);
  rhs(rows) = 0.0;
  return system.colPivHouseholderQr().solve(rhs);
}

AmbientSystem::AmbientSystem(const Chain& chain, const InitialState& start, double projectBeyond)
    : chain_(chain), mass_(ambientMassMatrix(chain)), projectBeyond_(projectBeyond), solver_(chain) {
  const Eigen::Index hinges = chain.hingeCount();
  start_.assign(static_cast<size_t>(4 * hinges), 0.0);
  Eigen::Map<Eigen::Matrix2Xd> q(start_.data(), 2, hinges), v(start_.data() + 2 * hinges, 2, hinges);
  if (start.byHinges()) {  // already on the constraints (initialStateFromHinges); projecting again changes nothing
    q = start.hinges;
    v = start.hingeVelocities;
    projectPositions(q);
    projectVelocities(q, v);
    projections_ = 0;
    return;
  }
  // Positions and velocities in one forward-AD pass along xdot (O(n^2), unlike the full Jacobian).
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  VectorX<Dual> x(start.spherePoint.size());
  for (Eigen::Index i = 0; i < x.size(); ++i)
    x(i) = Dual(start.spherePoint(i), Eigen::Matrix<double, 1, 1>(start.sphereVelocity(i)));
  const HingeMatrix<Dual> moving = hingePositionsOnSphere<Dual>(chain, x);
  for (Eigen::Index h = 0; h < hinges; ++h)
    for (int xy = 0; xy < 2; ++xy) {
      q(xy, h) = moving(xy, h).value();
      v(xy, h) = moving(xy, h).derivatives().size() ? moving(xy, h).derivatives()(0) : 0.0;
    }
  projectPositions(q);
  projectVelocities(q, v);
  projections_ = 0;
}

void AmbientSystem::derivative(const State& y, State& dydt) const {
  const Eigen::Index hinges = chain_.hingeCount();
  const Eigen::Map<const Eigen::Matrix2Xd> q(y.data(), 2, hinges), v(y.data() + 2 * hinges, 2, hinges);
  ConstraintSolver::relativeVelocities(v, relative_);
  rhs_ = -relative_.colwise().squaredNorm().transpose();  // c_k'' = D_k . (a_k - a_(k-1)) + |v_k - v_(k-1)|^2 = 0
  solver_.solve(q, rhs_, acceleration_);
  dydt.resize(y.size());
  Eigen::Map<Eigen::Matrix2Xd>(dydt.data(), 2, hinges) = v;
  Eigen::Map<Eigen::Matrix2Xd>(dydt.data() + 2 * hinges, 2, hinges) = acceleration_;
}

void AmbientSystem::projectPositions(Eigen::Map<Eigen::Matrix2Xd> q) {
  for (int iteration = 0; iteration < maxNewtonIterations; ++iteration) {
    solver_.rodVectors(q, rods_);
    rhs_ = -0.5 * (rods_.colwise().squaredNorm().array() - 1.0).matrix().transpose();  // -c(q)
    if (rhs_.cwiseAbs().maxCoeff() < 1e-16) return;
    solver_.solve(q, rhs_, acceleration_);
    q += acceleration_;
  }
}

void AmbientSystem::projectVelocities(const Eigen::Matrix2Xd& q, Eigen::Map<Eigen::Matrix2Xd> v) {
  solver_.rodVectors(q, rods_);
  ConstraintSolver::relativeVelocities(v, relative_);
  rhs_ = -(rods_.cwiseProduct(relative_)).colwise().sum().transpose();  // -G v
  solver_.solve(q, rhs_, acceleration_);
  v += acceleration_;
}

bool AmbientSystem::settleBetweenSteps(State& y) {
  const Eigen::Index hinges = chain_.hingeCount();
  Eigen::Map<Eigen::Matrix2Xd> q(y.data(), 2, hinges), v(y.data() + 2 * hinges, 2, hinges);
  if (rodLengthError(chain_, q) <= projectBeyond_) return false;
  projectPositions(q);
  projectVelocities(q, v);
  ++projections_;
  return true;
}

PhysicalState AmbientSystem::physicalState(const State& y) const {
  const Eigen::Index hinges = chain_.hingeCount();
  PhysicalState o;
  o.hinges = Eigen::Map<const Eigen::Matrix2Xd>(y.data(), 2, hinges);
  o.hingeVelocities = Eigen::Map<const Eigen::Matrix2Xd>(y.data() + 2 * hinges, 2, hinges);
  if (chain_.isSlack()) return o;  // no configuration sphere: hinges only
  o.spherePoint = spherePointFromHinges(chain_, o.hinges);
  o.sphereVelocity = sphereVelocityFromHingeVelocities(chain_, o.spherePoint, o.hingeVelocities);
  return o;
}

std::string AmbientSystem::describe(const State& y) const {
  std::ostringstream out;
  out.precision(17);
  out << "hinges (";
  for (size_t i = 0; i < y.size() / 2 && i < 6; ++i) out << (i ? ", " : "") << y[i];
  out << (y.size() / 2 > 6 ? ", ...)" : ")");
  return out.str();
}

}  // namespace sl

namespace sl {

StepInvariants AmbientSystem::stepInvariants(const State& y, double previousT) const {
  const Eigen::Index hinges = chain_.hingeCount();
  const Eigen::Map<const Eigen::Matrix2Xd> q(y.data(), 2, hinges), v(y.data() + 2 * hinges, 2, hinges);
  StepInvariants summary;
  summary.energy = kineticEnergy(mass_, v);
  summary.rodLengthError = rodLengthError(chain_, q);
  summary.chartZeroT = chain_.isSlack() ? previousT : chartZeroAngleForUnwrapping(chain_, q, previousT);
  return summary;
}

}  // namespace sl

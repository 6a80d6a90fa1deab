#include "inverse/constrained_model.hpp"

#include <cmath>
#include <stdexcept>

#include "linkage/kinetic_metric.hpp"

namespace sl {

ConstrainedModel ConstrainedModel::fromChain(const Chain& chain) {
  chain.validate(/*allowSlack=*/true);
  ConstrainedModel model;
  const int hinges = chain.hingeCount();
  model.dimension_ = 2 * hinges;
  const double length = chain.baseLength;
  for (int rod = 1; rod <= chain.rods; ++rod) {
    QuadraticConstraint c;
    const int head = rod - 1;  // hinge p_rod, 0-based column, or the pin (L, 0) for the last rod
    const int tail = rod - 2;  // hinge p_(rod-1), or the pin 0 for the first rod
    for (int axis = 0; axis < 2; ++axis) {
      if (rod < chain.rods) c.hessian.push_back({2 * head + axis, 2 * head + axis, 1.0});
      if (rod > 1) c.hessian.push_back({2 * tail + axis, 2 * tail + axis, 1.0});
      if (rod > 1 && rod < chain.rods) {
        c.hessian.push_back({2 * head + axis, 2 * tail + axis, -1.0});
        c.hessian.push_back({2 * tail + axis, 2 * head + axis, -1.0});
      }
    }
    c.constant = -0.5;
    if (rod == chain.rods) {  // |(L, 0) - p|^2 = L^2 - 2 L x + |p|^2
      c.linear.push_back({2 * tail, -length});
      c.constant = (length * length - 1.0) / 2.0;
    }
    model.constraints_.push_back(c);
  }
  model.setMass(stackedMassMatrix(chain));
  return model;
}

ConstrainedModel ConstrainedModel::ellipsoid(double a, double b, double c) {
  if (!(a > 0 && b > 0 && c > 0 && std::isfinite(a) && std::isfinite(b) && std::isfinite(c)))
    throw std::invalid_argument("ellipsoid: the semi-axes must be positive and finite");
  ConstrainedModel model;
  model.dimension_ = 3;
  QuadraticConstraint constraint;  // (x^2/a^2 + y^2/b^2 + z^2/c^2 - 1)/2
  constraint.hessian = {{0, 0, 1.0 / (a * a)}, {1, 1, 1.0 / (b * b)}, {2, 2, 1.0 / (c * c)}};
  constraint.constant = -0.5;
  model.constraints_.push_back(constraint);
  model.setMass(Eigen::MatrixXd::Identity(3, 3));
  return model;
}

void ConstrainedModel::setMass(Eigen::MatrixXd mass) {
  mass_ = std::move(mass);
  sparseMass_ = mass_.sparseView();
  if (!sparse()) inverseMass_ = mass_.inverse();  // O(N^3): the dense path only
}

Eigen::SparseMatrix<double> ConstrainedModel::sparseJacobian(const Eigen::VectorXd& q) const {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < constraintCount(); ++i) {
    const QuadraticConstraint& c = constraints_[static_cast<std::size_t>(i)];
    for (const auto& e : c.hessian) entries.emplace_back(i, e.row, e.value * q(e.col));
    for (const auto& [index, coefficient] : c.linear) entries.emplace_back(i, index, coefficient);
  }
  Eigen::SparseMatrix<double> g(constraintCount(), dimension_);
  g.setFromTriplets(entries.begin(), entries.end());  // duplicates summed, as jacobian() adds them
  return g;
}

KktFactor::KktFactor(const ConstrainedModel& model, const Eigen::VectorXd& q) : model_(model), sparse_(model.sparse()) {
  const int n = model.dimension(), m = model.constraintCount();
  if (!sparse_) {
    g_ = model.jacobian(q);  // the KKT matrix is factored when a solve first needs it
    return;
  }
  sparseG_ = model.sparseJacobian(q);
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < model.sparseMass_.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(model.sparseMass_, k); it; ++it)
      entries.emplace_back(it.row(), it.col(), it.value());
  for (int k = 0; k < sparseG_.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(sparseG_, k); it; ++it) {
      entries.emplace_back(n + it.row(), it.col(), it.value());
      entries.emplace_back(it.col(), n + it.row(), it.value());
    }
  Eigen::SparseMatrix<double> kkt(n + m, n + m);
  kkt.setFromTriplets(entries.begin(), entries.end());
  sparseLu_ = std::make_shared<Eigen::SparseLU<Eigen::SparseMatrix<double>>>();
  sparseLu_->compute(kkt);
  if (sparseLu_->info() != Eigen::Success) throw std::runtime_error("the constraints lost rank at this point");
}

Eigen::VectorXd KktFactor::solve(const Eigen::VectorXd& top, const Eigen::VectorXd& bottom, Eigen::VectorXd* mu) const {
  const int n = model_.dimension(), m = model_.constraintCount();
  Eigen::VectorXd rhs(n + m);
  rhs << top, bottom;
  if (!sparse_ && !denseLu_) {
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + m, n + m);
    kkt.topLeftCorner(n, n) = model_.mass();
    kkt.topRightCorner(n, m) = g_.transpose();
    kkt.bottomLeftCorner(m, n) = g_;
    denseLu_.emplace(kkt);
  }
  const Eigen::VectorXd solution = sparse_ ? Eigen::VectorXd(sparseLu_->solve(rhs)) : Eigen::VectorXd(denseLu_->solve(rhs));
  if (mu != nullptr) *mu = solution.tail(m);
  return solution.head(n);
}

Eigen::VectorXd KktFactor::correction(const Eigen::VectorXd& residual) const {
  if (sparse_) return solve(Eigen::VectorXd::Zero(model_.dimension()), -residual);
  // -M^-1 G^T (G M^-1 G^T)^-1 r: the same x by the Schur complement, as the small models always had it.
  const Eigen::MatrixXd mg = model_.inverseMass_ * g_.transpose();
  const Eigen::MatrixXd schur = g_ * mg;
  return -mg * schur.ldlt().solve(residual);
}

Eigen::VectorXd KktFactor::jacobianTimes(const Eigen::VectorXd& u) const {
  return sparse_ ? Eigen::VectorXd(sparseG_ * u) : Eigen::VectorXd(g_ * u);
}

Eigen::VectorXd ConstrainedModel::values(const Eigen::VectorXd& q) const {
  Eigen::VectorXd out(constraintCount());
  for (int i = 0; i < constraintCount(); ++i) {
    const QuadraticConstraint& c = constraints_[static_cast<std::size_t>(i)];
    double value = c.constant;
    for (const auto& e : c.hessian) value += 0.5 * q(e.row) * e.value * q(e.col);
    for (const auto& [index, coefficient] : c.linear) value += coefficient * q(index);
    out(i) = value;
  }
  return out;
}

Eigen::MatrixXd ConstrainedModel::jacobian(const Eigen::VectorXd& q) const {
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(constraintCount(), dimension_);
  for (int i = 0; i < constraintCount(); ++i) {
    const QuadraticConstraint& c = constraints_[static_cast<std::size_t>(i)];
    for (const auto& e : c.hessian) g(i, e.row) += e.value * q(e.col);
    for (const auto& [index, coefficient] : c.linear) g(i, index) += coefficient;
  }
  return g;
}

Eigen::VectorXd ConstrainedModel::secondDerivatives(const Eigen::VectorXd& u, const Eigen::VectorXd& w) const {
  Eigen::VectorXd out(constraintCount());
  for (int i = 0; i < constraintCount(); ++i) {
    double value = 0;
    for (const auto& e : constraints_[static_cast<std::size_t>(i)].hessian) value += u(e.row) * e.value * w(e.col);
    out(i) = value;
  }
  return out;
}

Eigen::VectorXd ConstrainedModel::hessianCombination(const Eigen::VectorXd& mu, const Eigen::VectorXd& u) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(dimension_);
  for (int i = 0; i < constraintCount(); ++i)
    for (const auto& e : constraints_[static_cast<std::size_t>(i)].hessian) out(e.row) += mu(i) * e.value * u(e.col);
  return out;
}

Eigen::MatrixXd ConstrainedModel::hessianMatrix(const Eigen::VectorXd& mu) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(dimension_, dimension_);
  for (int i = 0; i < constraintCount(); ++i)
    for (const auto& e : constraints_[static_cast<std::size_t>(i)].hessian) out(e.row, e.col) += mu(i) * e.value;
  return out;
}

void ConstrainedModel::hessianEntries(const Eigen::VectorXd& mu, int rowOffset, int colOffset,
                                      std::vector<Eigen::Triplet<double>>& out) const {
  for (int i = 0; i < constraintCount(); ++i)
    for (const auto& e : constraints_[static_cast<std::size_t>(i)].hessian)
      out.emplace_back(rowOffset + e.row, colOffset + e.col, mu(i) * e.value);
}

Eigen::VectorXd ConstrainedModel::correctionFor(const Eigen::VectorXd& q, const Eigen::VectorXd& residual) const {
  return KktFactor(*this, q).correction(residual);
}

double ConstrainedModel::relativeResidual(const Eigen::VectorXd& q) const {
  // A constraint's value is a sum of quadratic terms as large as |q|^2 (hinges far from the origin), which
  // cancel; rounding leaves about 1e-16 of that size, so the residual is judged relative to it.
  const double size = q.size() ? q.cwiseAbs().maxCoeff() : 0.0;
  return values(q).cwiseAbs().maxCoeff() / (1.0 + size * size);
}

bool ConstrainedModel::projectPosition(Eigen::VectorXd& q) const {
  for (int iteration = 0; iteration < 50; ++iteration) {
    if (relativeResidual(q) <= 1e-15) return true;
    q += correctionFor(q, values(q));
  }
  return relativeResidual(q) <= 1e-13;
}

Eigen::VectorXd ConstrainedModel::projectVelocity(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  const KktFactor kkt(*this, q);
  return v + kkt.correction(kkt.jacobianTimes(v));
}

void ConstrainedModel::projectVariation(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& dq,
                                        Eigen::VectorXd& dv) const {
  Eigen::MatrixXd columnQ = dq, columnV = dv;
  projectVariations(q, v, columnQ, columnV);
  dq = columnQ.col(0);
  dv = columnV.col(0);
}

void ConstrainedModel::projectVariations(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::MatrixXd& dq,
                                         Eigen::MatrixXd& dv) const {
  const KktFactor kkt(*this, q);
  for (Eigen::Index j = 0; j < dq.cols(); ++j) {
    dq.col(j) += kkt.correction(kkt.jacobianTimes(dq.col(j)));
    dv.col(j) += kkt.correction(kkt.jacobianTimes(dv.col(j)) + secondDerivatives(dq.col(j), v));
  }
}

Eigen::MatrixXd ConstrainedModel::tangentBasis(const Eigen::VectorXd& q) const {
  // Project the coordinate axes onto the tangent space and orthonormalise (Gram-Schmidt in M, twice),
  // keeping the first `freedom` independent ones: deterministic for a given q.
  Eigen::MatrixXd basis(dimension_, freedom());
  const KktFactor kkt(*this, q);
  int found = 0;
  for (int axis = 0; axis < dimension_ && found < freedom(); ++axis) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(dimension_, axis);
    Eigen::VectorXd u = e + kkt.correction(kkt.jacobianTimes(e));
    for (int pass = 0; pass < 2; ++pass)
      for (int j = 0; j < found; ++j) u -= inner(basis.col(j), u) * basis.col(j);
    const double size = norm(u);
    if (size < 1e-3) continue;
    basis.col(found++) = u / size;
  }
  if (found < freedom()) throw std::runtime_error("tangentBasis: the constraints lost rank at this point");
  return basis;
}

Eigen::VectorXd ConstrainedModel::stack(const Eigen::Matrix2Xd& hinges) {
  return Eigen::Map<const Eigen::VectorXd>(hinges.data(), hinges.size());
}

Eigen::Matrix2Xd ConstrainedModel::unstack(const Eigen::VectorXd& q) {
  return Eigen::Map<const Eigen::Matrix2Xd>(q.data(), 2, q.size() / 2);
}

}  // namespace sl

#include "simulation/constraint_solver.hpp"

#include <stdexcept>

#include <Eigen/SparseLU>

namespace sl {

struct ConstraintSolver::Kkt {
  Eigen::SparseMatrix<double> matrix;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  Eigen::VectorXd rhs, solution;
  // Unknown order: mu_0, x_1 (2), mu_1, x_2 (2), ..., x_(n-1) (2), mu_(n-1): rod r's multiplier at 3r,
  // hinge p_h's coordinates at 3h - 2 and 3h - 1.
  static Eigen::Index mu(Eigen::Index rod) { return 3 * rod; }
  static Eigen::Index x(Eigen::Index hinge, int xy) { return 3 * hinge - 2 + xy; }
};

ConstraintSolver::ConstraintSolver(const Chain& chain) : baseLength_(chain.baseLength) {
  const AmbientMassMatrix mass = ambientMassMatrix(chain);
  const int n = chain.rods;
  inverseMass_ = Eigen::VectorXd::Zero(n + 1);
  inverseMass_.segment(1, n - 1) = mass.diagonal.cwiseInverse();
  diagonalMass_ = mass.isDiagonal;
  rods_.resize(2, n);
  lower_.resize(n), diagonal_.resize(n), upper_.resize(n), pivots_.resize(n), mu_.resize(n);
  if (diagonalMass_) return;

  kkt_ = std::make_unique<Kkt>();
  const Eigen::Index size = 3 * n - 2;
  std::vector<Eigen::Triplet<double>> entries;
  for (int h = 1; h < n; ++h)
    for (int xy = 0; xy < 2; ++xy) {
      entries.emplace_back(Kkt::x(h, xy), Kkt::x(h, xy), mass.diagonal(h - 1));
      if (h + 1 < n) {
        entries.emplace_back(Kkt::x(h, xy), Kkt::x(h + 1, xy), mass.coupling(h - 1));
        entries.emplace_back(Kkt::x(h + 1, xy), Kkt::x(h, xy), mass.coupling(h - 1));
      }
    }
  for (int r = 0; r < n; ++r)  // rod r joins p_r and p_(r+1)
    for (int xy = 0; xy < 2; ++xy)
      for (int h : {r, r + 1})
        if (h >= 1 && h < n) {
          entries.emplace_back(Kkt::mu(r), Kkt::x(h, xy), 1.0);
          entries.emplace_back(Kkt::x(h, xy), Kkt::mu(r), 1.0);
        }
  kkt_->matrix.resize(size, size);
  kkt_->matrix.setFromTriplets(entries.begin(), entries.end());
  kkt_->matrix.makeCompressed();
  kkt_->lu.analyzePattern(kkt_->matrix);
  kkt_->rhs.resize(size);
}

ConstraintSolver::~ConstraintSolver() = default;
ConstraintSolver::ConstraintSolver(ConstraintSolver&&) noexcept = default;

void ConstraintSolver::rodVectors(const Eigen::Matrix2Xd& hinges, Eigen::Matrix2Xd& rods) const {
  const Eigen::Index n = hinges.cols() + 1;
  rods.resize(2, n);
  rods.col(0) = hinges.col(0);
  for (Eigen::Index k = 1; k + 1 < n; ++k) rods.col(k) = hinges.col(k) - hinges.col(k - 1);
  rods.col(n - 1) = Eigen::Vector2d(baseLength_, 0.0) - hinges.col(n - 2);
}

void ConstraintSolver::relativeVelocities(const Eigen::Matrix2Xd& velocities, Eigen::Matrix2Xd& relative) {
  const Eigen::Index n = velocities.cols() + 1;
  relative.resize(2, n);
  relative.col(0) = velocities.col(0);
  for (Eigen::Index k = 1; k + 1 < n; ++k) relative.col(k) = velocities.col(k) - velocities.col(k - 1);
  relative.col(n - 1) = -velocities.col(n - 2);
}

void ConstraintSolver::solve(const Eigen::Matrix2Xd& hinges, const Eigen::VectorXd& rhs, Eigen::Matrix2Xd& correction) {
  if (!hinges.allFinite() || !rhs.allFinite())
    throw NonFiniteConstraintData("the hinge positions or velocities are no longer finite numbers (the step overflowed)");
  rodVectors(hinges, rods_);
  if (diagonalMass_)
    factorTridiagonal();
  else
    factorKkt();
  solveAgain(rhs, correction);
}

void ConstraintSolver::solveAgain(const Eigen::VectorXd& rhs, Eigen::Matrix2Xd& correction) {
  correction.resize(2, rods_.cols() - 1);
  if (diagonalMass_)
    substituteTridiagonal(rhs, correction);
  else
    substituteKkt(rhs, correction);
}

void ConstraintSolver::factorTridiagonal() {
  // (G M^-1 G^T)_rr = |D_r|^2 (w_r + w_(r+1)), (.)_(r,r+1) = -(D_r . D_(r+1)) w_(r+1): rods r and r+1 share p_(r+1).
  const Eigen::Index n = rods_.cols();
  for (Eigen::Index r = 0; r < n; ++r) {
    diagonal_(r) = rods_.col(r).squaredNorm() * (inverseMass_(r) + inverseMass_(r + 1));
    if (r + 1 < n) upper_(r) = -rods_.col(r).dot(rods_.col(r + 1)) * inverseMass_(r + 1);
  }
  // Thomas algorithm (SPD, so no pivoting): the elimination's pivots and multipliers here, the right-hand side's
  // forward elimination and back substitution in substituteTridiagonal().
  pivots_(0) = diagonal_(0);
  for (Eigen::Index r = 1; r < n; ++r) {
    lower_(r - 1) = upper_(r - 1) / pivots_(r - 1);
    pivots_(r) = diagonal_(r) - upper_(r - 1) * lower_(r - 1);
    // Relative to the row's own size: every rod on one line gives pivot 0 up to rounding.
    if (!(pivots_(r) > 1e-12 * diagonal_(r)))
      throw ConstraintRankLoss("the rod constraints lose rank: every rod lies on one line (folded flat or stretched "
                               "straight)");
  }
}

void ConstraintSolver::substituteTridiagonal(const Eigen::VectorXd& rhs, Eigen::Matrix2Xd& correction) {
  const Eigen::Index n = rods_.cols();
  mu_(0) = rhs(0) / pivots_(0);
  for (Eigen::Index r = 1; r < n; ++r) mu_(r) = (rhs(r) - upper_(r - 1) * mu_(r - 1)) / pivots_(r);
  for (Eigen::Index r = n - 2; r >= 0; --r) mu_(r) -= lower_(r) * mu_(r + 1);
  // x = M^-1 G^T mu: hinge p_h ends rod h-1 and starts rod h.
  for (Eigen::Index h = 1; h < n; ++h)
    correction.col(h - 1) = inverseMass_(h) * (rods_.col(h - 1) * mu_(h - 1) - rods_.col(h) * mu_(h));
}

void ConstraintSolver::factorKkt() {
  const Eigen::Index n = rods_.cols();
  Eigen::SparseMatrix<double>& K = kkt_->matrix;
  for (Eigen::Index r = 0; r < n; ++r)
    for (int xy = 0; xy < 2; ++xy) {
      if (r >= 1) K.coeffRef(Kkt::mu(r), Kkt::x(r, xy)) = K.coeffRef(Kkt::x(r, xy), Kkt::mu(r)) = -rods_(xy, r);
      if (r + 1 < n)
        K.coeffRef(Kkt::mu(r), Kkt::x(r + 1, xy)) = K.coeffRef(Kkt::x(r + 1, xy), Kkt::mu(r)) = rods_(xy, r);
    }
  kkt_->lu.factorize(K);
  if (kkt_->lu.info() != Eigen::Success)
    throw ConstraintRankLoss("the rod constraints lose rank (KKT factorisation failed): every rod lies on one line");
}

void ConstraintSolver::substituteKkt(const Eigen::VectorXd& rhs, Eigen::Matrix2Xd& correction) {
  const Eigen::Index n = rods_.cols();
  kkt_->rhs.setZero();
  for (Eigen::Index r = 0; r < n; ++r) kkt_->rhs(Kkt::mu(r)) = rhs(r);
  kkt_->solution = kkt_->lu.solve(kkt_->rhs);
  for (Eigen::Index h = 1; h < n; ++h)
    for (int xy = 0; xy < 2; ++xy) correction(xy, h - 1) = kkt_->solution(Kkt::x(h, xy));
  // The KKT rows read M x + G^T nu = 0 with G's row r = (-D_r at p_r, +D_r at p_(r+1)): x = M^-1 G^T (-nu).
  for (Eigen::Index r = 0; r < n; ++r) mu_(r) = -kkt_->solution(Kkt::mu(r));
}

}  // namespace sl

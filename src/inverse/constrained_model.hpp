#pragma once
// A configuration space cut out of R^N by quadratic constraints, with a constant mass metric M: the
// common ground of the inverse problems (two-point motions, closed geodesics). Two instances:
//   - the chain (spec section 1): q = (p1, ..., p(n-1)) stacked, one constraint (|p_k - p_(k-1)|^2 - 1)/2
//     per rod, M the ambient kinetic metric (block-tridiagonal with rod masses);
//   - a triaxial ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 in R^3 with M = I: a 2-sphere whose closed
//     geodesics are known in closed form (its principal ellipses), run through the same code.
// Constraint i is c_i(q) = q^T A_i q / 2 + b_i . q + e_i, so its gradient is A_i q + b_i and its second
// derivative the constant A_i: geodesics, their linearisation and the discrete action all need only these.
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include "linkage/chain.hpp"

namespace sl {

// The largest coordinate in size: the inverse problems' closures, steps and path differences are measured in it.
inline double maxAbs(const Eigen::VectorXd& v) { return v.cwiseAbs().maxCoeff(); }

struct QuadraticConstraint {
  struct Entry {
    int row, col;
    double value;
  };
  std::vector<Entry> hessian;                  // the entries of A (both (i, j) and (j, i) of a symmetric pair)
  std::vector<std::pair<int, double>> linear;  // b
  double constant = 0;
};

class ConstrainedModel;

// The KKT matrix [M G^T; G 0] of a model at q, factored once for several solves. Small systems (4 rods, the
// ellipsoid) by dense formulas; beyond kDenseKktSize unknowns by sparse LU, which for a chain (M and G banded)
// costs O(n) per factorisation and per solve instead of O(n^3) and O(n^2): what lets `connect` reach long chains.
class KktFactor {
 public:
  static constexpr int kDenseKktSize = 30;  // N + m: a chain of 11 rods is the first one solved sparsely
  KktFactor(const ConstrainedModel& model, const Eigen::VectorXd& q);
  // The x of M x + G^T mu = top, G x = bottom, and (when asked) its multipliers mu.
  Eigen::VectorXd solve(const Eigen::VectorXd& top, const Eigen::VectorXd& bottom, Eigen::VectorXd* mu = nullptr) const;
  // The M-orthogonal smallest x with G x = -residual: the correction of every projection.
  Eigen::VectorXd correction(const Eigen::VectorXd& residual) const;
  Eigen::VectorXd jacobianTimes(const Eigen::VectorXd& u) const;  // G u

 private:
  const ConstrainedModel& model_;
  bool sparse_ = false;
  Eigen::MatrixXd g_;                             // dense path: G
  mutable std::optional<Eigen::PartialPivLU<Eigen::MatrixXd>> denseLu_;  // dense path: the KKT matrix, when solved
  Eigen::SparseMatrix<double> sparseG_;
  std::shared_ptr<Eigen::SparseLU<Eigen::SparseMatrix<double>>> sparseLu_;
};

class ConstrainedModel {
 public:
  // Throws std::invalid_argument for a chain that is not valid (slack chains included: they move too).
  static ConstrainedModel fromChain(const Chain& chain);
  // Semi-axes a, b, c > 0 along x, y, z.
  static ConstrainedModel ellipsoid(double a, double b, double c);

  int dimension() const { return dimension_; }                                   // N
  int constraintCount() const { return static_cast<int>(constraints_.size()); }  // m
  int freedom() const { return dimension_ - constraintCount(); }                 // dimension of the space
  const Eigen::MatrixXd& mass() const { return mass_; }
  const Eigen::SparseMatrix<double>& sparseMass() const { return sparseMass_; }

  Eigen::VectorXd values(const Eigen::VectorXd& q) const;    // c(q), m entries
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& q) const;  // G = dc/dq, m x N
  // (u^T A_i w)_i: the constraints' second derivatives along u and w.
  Eigen::VectorXd secondDerivatives(const Eigen::VectorXd& u, const Eigen::VectorXd& w) const;
  // sum_i mu_i A_i u.
  Eigen::VectorXd hessianCombination(const Eigen::VectorXd& mu, const Eigen::VectorXd& u) const;
  // sum_i mu_i A_i as a dense matrix.
  Eigen::MatrixXd hessianMatrix(const Eigen::VectorXd& mu) const;
  // The same as (row, col, value) entries, duplicates to be summed: O(n) for a chain.
  void hessianEntries(const Eigen::VectorXd& mu, int rowOffset, int colOffset,
                      std::vector<Eigen::Triplet<double>>& out) const;

  double norm(const Eigen::VectorXd& u) const { return std::sqrt(inner(u, u)); }
  double inner(const Eigen::VectorXd& u, const Eigen::VectorXd& w) const {
    return sparse() ? u.dot(sparseMass_ * w) : u.dot(mass_ * w);
  }
  // G as a sparse matrix (m x N, O(n) entries for a chain).
  Eigen::SparseMatrix<double> sparseJacobian(const Eigen::VectorXd& q) const;
  // Whether KKT systems of this model are solved sparsely (KktFactor).
  bool sparse() const { return dimension_ + constraintCount() > KktFactor::kDenseKktSize; }

  // max |c(q)| / (1 + max |q|^2): the constraints' residual against the rounding their terms leave.
  double relativeResidual(const Eigen::VectorXd& q) const;
  // Newton's method M-orthogonally onto c = 0; true when relativeResidual <= 1e-15 was reached.
  bool projectPosition(Eigen::VectorXd& q) const;
  // The M-orthogonal projection onto the tangent space ker G(q).
  Eigen::VectorXd projectVelocity(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  // The M-orthogonal correction taking a variation (dq, dv) of a state (q, v) onto the linearised
  // constraints G dq = 0, G dv + (dq^T A_i v)_i = 0.
  void projectVariation(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& dq,
                        Eigen::VectorXd& dv) const;
  // The same for every column of dq and dv, with one factorisation.
  void projectVariations(const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::MatrixXd& dq,
                         Eigen::MatrixXd& dv) const;
  // An M-orthonormal basis of the tangent space at q (N x freedom), deterministic.
  Eigen::MatrixXd tangentBasis(const Eigen::VectorXd& q) const;

  // The chain's stacked hinges and back (only for models made from a chain).
  static Eigen::VectorXd stack(const Eigen::Matrix2Xd& hinges);
  static Eigen::Matrix2Xd unstack(const Eigen::VectorXd& q);

 private:
  friend class KktFactor;
  Eigen::VectorXd correctionFor(const Eigen::VectorXd& q, const Eigen::VectorXd& residual) const;
  void setMass(Eigen::MatrixXd mass);
  int dimension_ = 0;
  Eigen::MatrixXd mass_, inverseMass_;  // the inverse only for the dense path
  Eigen::SparseMatrix<double> sparseMass_;
  std::vector<QuadraticConstraint> constraints_;
};

}  // namespace sl

#pragma once
// The chain model (spec section 1): n unit rods, p0 = 0 and pn = (L, 0) pinned, n-2 < L < n. A slack chain
// (0 < L <= n-2) is a chain too, but its configuration space is no longer a sphere: only the
// chart-free ambient method moves it.
// Mass lives at the n-1 interior hinges (M_j) and uniformly along the rods (m_k).

#include <Eigen/Dense>

namespace sl {

struct Chain {
  int rods = 4;                 // n
  double baseLength = 3.0;      // L, the distance between the pins
  Eigen::VectorXd hingeMasses;  // M_1..M_(n-1), default 1
  Eigen::VectorXd rodMasses;    // m_1..m_n, default 0

  // Unit hinge masses and massless rods: the spec's Euclidean case.
  static Chain uniform(int rods, double baseLength);

  int hingeCount() const { return rods - 1; }
  int sphereDimension() const { return rods - 2; }  // configuration space S^(n-2)
  bool hasRodMass() const;
  bool isSlack() const { return baseLength <= rods - 2; }  // no configuration sphere, no chart

  // Throws std::invalid_argument naming the rule that fails. allowSlack admits 0 < L <= n-2 (ambient method).
  void validate(bool allowSlack = false) const;
};

// The ambient kinetic metric on (R^2)^(n-1), block-tridiagonal with scalar blocks (spec section 1):
// diagonal j: M_j + (m_j + m_(j+1))/3, coupling of hinges j and j+1: m_(j+1)/6.
// Indices are 0-based: diagonal(j) belongs to hinge p_(j+1).
struct AmbientMassMatrix {
  Eigen::VectorXd diagonal;  // n-1 entries
  Eigen::VectorXd coupling;  // n-2 entries
  bool isDiagonal = true;    // no coupling (massless rods)

  // (M v) for hinge velocities stacked as a 2 x (n-1) matrix.
  Eigen::Matrix2Xd apply(const Eigen::Matrix2Xd& hingeVectors) const;
  // <a, M b> summed over hinges.
  double innerProduct(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) const;
};

AmbientMassMatrix ambientMassMatrix(const Chain& chain);

// T = (1/2) <v, M v>.
double kineticEnergy(const AmbientMassMatrix& mass, const Eigen::Matrix2Xd& hingeVelocities);

// max_k |a_k - b_k| over the hinges of two configurations (Euclidean in the plane): how far apart two
// linkages are. NaN if any coordinate is NaN, so a broken state is never reported as close.
double hingeDistance(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b);

// max_k | |p_k - p_(k-1)| - 1 | over all n rods, pins included.
double rodLengthError(const Chain& chain, const Eigen::Matrix2Xd& hinges);

}  // namespace sl

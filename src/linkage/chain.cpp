#include "linkage/chain.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sl {

Chain Chain::uniform(int rods, double baseLength) {
  Chain chain;
  chain.rods = rods;
  chain.baseLength = baseLength;
  chain.hingeMasses = Eigen::VectorXd::Ones(std::max(rods - 1, 0));
  chain.rodMasses = Eigen::VectorXd::Zero(std::max(rods, 0));
  return chain;
}

bool Chain::hasRodMass() const { return (rodMasses.array() != 0.0).any(); }

void Chain::validate(bool allowSlack) const {
  if (rods < 3) throw std::invalid_argument("a chain needs at least 3 rods, got " + std::to_string(rods));
  const double lowest = allowSlack ? 0.0 : rods - 2;
  if (!std::isfinite(baseLength) || !(baseLength > lowest) || !(baseLength < rods))
    throw std::invalid_argument("L must lie in (" + std::to_string(lowest) + ", n) = (" + std::to_string(lowest) +
                                ", " + std::to_string(rods) + "), got " + std::to_string(baseLength));
  if (hingeMasses.size() != rods - 1)
    throw std::invalid_argument("expected " + std::to_string(rods - 1) + " hinge masses");
  if (rodMasses.size() != rods) throw std::invalid_argument("expected " + std::to_string(rods) + " rod masses");
  if (!hingeMasses.allFinite() || (hingeMasses.array() < 0).any() || !rodMasses.allFinite() ||
      (rodMasses.array() < 0).any())
    throw std::invalid_argument("masses must be finite and non-negative");
  const AmbientMassMatrix mass = ambientMassMatrix(*this);
  if ((mass.diagonal.array() <= 0).any())
    throw std::invalid_argument("every hinge must carry mass (its own or from an adjacent rod)");
}

AmbientMassMatrix ambientMassMatrix(const Chain& chain) {
  const int hinges = chain.hingeCount();
  AmbientMassMatrix mass;
  mass.diagonal.resize(hinges);
  mass.coupling = Eigen::VectorXd::Zero(std::max(hinges - 1, 0));
  // Rod k (1-based) joins p_(k-1) and p_k; its kinetic energy (m_k/2) int_0^1 |(1-s) v_(k-1) + s v_k|^2 ds
  // contributes m_k/3 to each end's diagonal and m_k/6 to their coupling (spec section 1).
  for (int j = 0; j < hinges; ++j)
    mass.diagonal(j) = chain.hingeMasses(j) + (chain.rodMasses(j) + chain.rodMasses(j + 1)) / 3.0;
  for (int j = 0; j + 1 < hinges; ++j) mass.coupling(j) = chain.rodMasses(j + 1) / 6.0;
  mass.isDiagonal = (mass.coupling.array() == 0.0).all();
  return mass;
}

Eigen::Matrix2Xd AmbientMassMatrix::apply(const Eigen::Matrix2Xd& v) const {
  Eigen::Matrix2Xd out = v * diagonal.asDiagonal();
  for (Eigen::Index j = 0; j < coupling.size(); ++j) {
    out.col(j) += coupling(j) * v.col(j + 1);
    out.col(j + 1) += coupling(j) * v.col(j);
  }
  return out;
}

double AmbientMassMatrix::innerProduct(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) const {
  return (a.array() * apply(b).array()).sum();
}

double kineticEnergy(const AmbientMassMatrix& mass, const Eigen::Matrix2Xd& v) { return 0.5 * mass.innerProduct(v, v); }

double rodLengthError(const Chain& chain, const Eigen::Matrix2Xd& hinges) {
  double worst = 0;
  Eigen::Vector2d previous(0.0, 0.0);
  for (int k = 0; k <= hinges.cols(); ++k) {
    const Eigen::Vector2d next =
        k < hinges.cols() ? Eigen::Vector2d(hinges.col(k)) : Eigen::Vector2d(chain.baseLength, 0.0);
    const double error = std::abs((next - previous).norm() - 1.0);
    worst = std::isfinite(error) ? std::max(worst, error) : error;
    if (!std::isfinite(worst)) return worst;
    previous = next;
  }
  return worst;
}

double hingeDistance(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  double worst = 0;
  for (Eigen::Index k = 0; k < std::min(a.cols(), b.cols()); ++k) {
    const double d = std::hypot(a(0, k) - b(0, k), a(1, k) - b(1, k));
    if (std::isnan(d)) return d;
    worst = std::max(worst, d);
  }
  return worst;
}

}  // namespace sl

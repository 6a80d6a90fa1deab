#include "geometry/sectional_curvature.hpp"

#include <stdexcept>
#include <string>

#include "contracts/limits.hpp"
#include "geometry/sectional_curvature_routes.hpp"
#include "linkage/chart.hpp"

namespace sl {
namespace {

// The chain's configuration sphere in (R^(2(n-1)), M): the stacked hinges Psi(x) (spec sections 1-2).
struct ChainEmbedding {
  const ChainConstants& bound;

  int sphereDimension() const { return bound.chain.rods - 2; }
  const Eigen::MatrixXd& mass() const { return bound.stackedMass; }
  template <class S>
  VectorX<S> operator()(const std::vector<int>& axes, const VectorX<S>& coords) const {
    const HingeMatrix<S> hinges = hingePositionsInChart<S>(bound, axes, coords);
    VectorX<S> q(hinges.size());
    for (Eigen::Index h = 0; h < hinges.cols(); ++h) {
      q(2 * h) = hinges(0, h);
      q(2 * h + 1) = hinges(1, h);
    }
    return q;
  }
};

ChainEmbedding checkedEmbedding(const ChainConstants& bound, const Eigen::VectorXd& spherePoint) {
  if (bound.chain.rods < 4)
    throw std::invalid_argument(
        "sectional curvature: expected a chain of at least 4 rods (a sphere of dimension >= 2)");
  if (bound.stackedMass.size() == 0)
    throw std::invalid_argument("sectional curvature: computed for chains of at most " +
                                std::to_string(limits::kMaxRods) + " rods");
  if (spherePoint.size() != bound.chain.rods - 1 || !spherePoint.allFinite() || spherePoint.norm() == 0.0)
    throw std::invalid_argument("sectional curvature: expected a sphere point of " +
                                std::to_string(bound.chain.rods - 1) + " finite numbers, not all zero");
  return ChainEmbedding{bound};
}

}  // namespace

double sectionalCurvature(const ChainConstants& bound, const Eigen::VectorXd& spherePoint, const Eigen::VectorXd& X,
                          const Eigen::VectorXd& Y) {
  return sectional::gaussRoute(checkedEmbedding(bound, spherePoint), spherePoint, X, Y);
}

double sectionalCurvatureIntrinsic(const ChainConstants& bound, const Eigen::VectorXd& spherePoint,
                                   const Eigen::VectorXd& X, const Eigen::VectorXd& Y) {
  return sectional::intrinsicRoute(checkedEmbedding(bound, spherePoint), spherePoint, X, Y);
}

SectionalRange sectionalCurvatureRange(const ChainConstants& bound, const Eigen::VectorXd& spherePoint) {
  return sectional::curvatureRange(checkedEmbedding(bound, spherePoint), spherePoint);
}

std::array<double, 2> sectionalCurvatureThrough(const ChainConstants& bound, const Eigen::VectorXd& spherePoint,
                                                const Eigen::VectorXd& velocity) {
  return sectional::rangeThrough(checkedEmbedding(bound, spherePoint), spherePoint, velocity);
}

}  // namespace sl

// The set-up of long chains by routes whose cost grows no faster than n^3 (Jacobi's determinant rate, dPsi
// along one vector, the tangent frame), each checked against an independent route.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "linkage/chain.hpp"
#include "linkage/chart.hpp"
#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/jacobi_system.hpp"

namespace sl {
namespace {

// A symmetric positive semi-definite m x m matrix of rank `rank`, and a symmetric rate.
std::pair<Eigen::MatrixXd, Eigen::MatrixXd> gramAndRate(int m, int rank, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(m, rank), r(m, m);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < rank; ++j) a(i, j) = normal(random);
    for (int j = 0; j < m; ++j) r(i, j) = normal(random);
  }
  return {a * a.transpose(), r + r.transpose()};
}

// d/dt det(G + t G') at t = 0 by central differences, against the closed form, for Gram matrices of every size
// the cofactors handle (1-3) and beyond (the eigen decomposition), regular and singular (at a conjugate point).
TEST(LongChains, TheGramDeterminantRateMatchesDifferencesAtEverySize) {
  for (int m = 1; m <= 9; ++m) {
    for (int rank : {m, m - 1}) {
      if (rank < 1) continue;
      const auto [gram, rate] = gramAndRate(m, rank, static_cast<unsigned>(10 * m + rank));
      const double h = 1e-6;
      const double differenced = ((gram + h * rate).determinant() - (gram - h * rate).determinant()) / (2 * h);
      const double closed = gramDeterminantRate(gram, rate);
      EXPECT_NEAR(closed, differenced, 1e-6 * (1.0 + std::abs(differenced))) << m << " fields, rank " << rank;
    }
  }
}

Chain longChain(int rods) { return Chain::uniform(rods, rods - 1.3); }

InitialState longStart(const Chain& chain, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd x(chain.rods - 1), v(chain.rods - 1);
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    x(i) = normal(random);
    v(i) = normal(random);
  }
  x.normalize();
  v -= x * x.dot(v);
  return {x, v};
}

// Beyond kWholeJacobianRods dPsi(x) v is one forward-AD pass: equal to the whole Jacobian times v.
TEST(LongChains, DPsiAlongOneVectorEqualsTheWholeJacobian) {
  const Chain chain = longChain(kWholeJacobianRods + 6);
  const InitialState start = longStart(chain, 3);
  const Eigen::VectorXd whole = sphereJacobian(chain, start.spherePoint) * start.sphereVelocity;
  const Eigen::Matrix2Xd along = hingeVelocitiesOnSphere(chain, start.spherePoint, start.sphereVelocity);
  EXPECT_LT((Eigen::Map<const Eigen::VectorXd>(along.data(), along.size()) - whole).cwiseAbs().maxCoeff(),
            1e-12 * whole.cwiseAbs().maxCoeff());
}

// The long chains' frame (Gram-Schmidt on the images) is g-orthonormal by kineticInner and starts along the
// velocity; a fan asks for two vectors only.
TEST(LongChains, TheTangentFrameOfALongChainIsOrthonormal) {
  const Chain chain = longChain(kWholeJacobianRods + 6);
  const InitialState start = longStart(chain, 5);
  const std::vector<Eigen::VectorXd> frame = orthonormalTangentFrame(chain, start.spherePoint, start.sphereVelocity);
  ASSERT_EQ(static_cast<int>(frame.size()), chain.rods - 2);
  for (std::size_t i : {std::size_t{0}, std::size_t{1}, frame.size() / 2, frame.size() - 1}) {
    EXPECT_NEAR(kineticInner(chain, start.spherePoint, frame[i], frame[i]), 1.0, 1e-9) << i;
    if (i > 0) {
      EXPECT_NEAR(kineticInner(chain, start.spherePoint, frame[0], frame[i]), 0.0, 1e-9) << i;
    }
    EXPECT_NEAR(frame[i].dot(start.spherePoint), 0.0, 1e-12) << i;
  }
  const Eigen::VectorXd along = start.sphereVelocity / start.sphereVelocity.norm();
  EXPECT_NEAR(std::abs(frame[0].normalized().dot(along)), 1.0, 1e-12);
  EXPECT_EQ(orthonormalTangentFrame(chain, start.spherePoint, start.sphereVelocity, 2).size(), 2u);
}

}  // namespace
}  // namespace sl

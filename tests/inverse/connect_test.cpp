#include <cmath>

#include <gtest/gtest.h>

#include "support.hpp"

#include "inverse/connect.hpp"
#include "inverse/method_shooting.hpp"
#include "linkage/chart.hpp"

namespace sl {
namespace {

void expectRoutesAgree(const std::vector<Connection>& found) {
  ASSERT_FALSE(found.empty());
  int both = 0;
  for (const Connection& c : found) {
    EXPECT_LE(c.endError, 1e-12);
    if (!c.discrete) continue;
    ++both;
    EXPECT_LT(c.lengthDifference, 1e-8) << "length " << c.length;
    EXPECT_LT(c.pathDifference, 1e-7) << "length " << c.length;
  }
  EXPECT_GE(both, 1);
  ASSERT_TRUE(found[0].discrete.has_value());
  EXPECT_EQ(found[0].discrete->seed, DiscreteSeed::SphereArc);  // the shortest, found by route 2 on its own
  EXPECT_EQ(found[0].morseIndex, 0);                 // a shortest path passes no conjugate point
}

TEST(Connect, FourRodsBothRoutesAgree) {
  const Chain chain = Chain::uniform(4, 3.0);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  ConnectOptions options;
  options.maxLength = 6.0;
  const auto found = findConnections(model, &chain, pointOf(chain, 0.5, 0.3), pointOf(chain, -0.6, 2.2), options);
  expectRoutesAgree(found);
  EXPECT_GE(found.size(), 2u);  // the shortest and more round the sphere
  for (std::size_t i = 1; i < found.size(); ++i) EXPECT_GE(found[i].length, found[0].length);
}

TEST(Connect, HeavyRodsAndFiveRods) {
  Chain chain = Chain::uniform(5, 3.5);
  chain.rodMasses = Eigen::VectorXd::Constant(5, 2.0);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  Eigen::VectorXd a(3), b(3);
  a << 0.4, -0.3, 0.2;
  b << -0.5, 0.6, -0.1;
  const Eigen::VectorXd from = ConstrainedModel::stack(hingePositionsAt(chain, a.normalized()));
  const Eigen::VectorXd to = ConstrainedModel::stack(hingePositionsAt(chain, b.normalized()));
  ConnectOptions options;
  options.maxLength = 0;  // default bound
  expectRoutesAgree(findConnections(model, &chain, from, to, options));
}

// The Morse index long chains take from the discrete action's second variation agrees with the Jacobi
// fields' conjugate points on the motions that pass some (4 rods: indices 0, 1, 1, ...; 5 rods).
TEST(Connect, DiscreteMorseIndexAgreesWithTheJacobiFields) {
  const Chain chain = Chain::uniform(4, 3.0);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  ConnectOptions options;
  options.maxLength = 6.0;
  options.discreteRoute = false;
  const Eigen::VectorXd from = pointOf(chain, 0.5, 0.3);
  const auto found = findConnections(model, &chain, from, pointOf(chain, -0.6, 2.2), options);
  int passing = 0;
  for (const Connection& c : found) {
    EXPECT_EQ(discreteMorseIndex(model, from, c.velocity), c.morseIndex) << "length " << c.length;
    if (c.morseIndex > 0) ++passing;
  }
  EXPECT_GE(passing, 1);
}

// The Jacobi fields' count of conjugate points against the discrete second variation (independent of the
// fields) on a 12-rod geodesic that passes 39 conjugate points: each zero of det G is accepted by G's smallest
// eigenvalue. Tested on det G itself, one zero was refused (38 counted): det G, a product of 9 eigenvalues, had
// grown so much before it that its value there was above any fixed share of its largest so far.
TEST(Connect, JacobiCountAgreesWithTheDiscreteIndexOnALongTwelveRodGeodesic) {
  const Chain chain = Chain::uniform(12, 11.0);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  Eigen::VectorXd x(11), d(11);
  for (int k = 0; k < 11; ++k) x(k) = std::sin(1.3 * k + 0.4), d(k) = std::cos(0.7 * k * k + 0.1);
  x.normalize();
  d -= d.dot(x) * x;
  const Eigen::VectorXd from = ConstrainedModel::stack(hingePositionsAt(chain, x));
  Eigen::VectorXd velocity = sphereJacobian(chain, x) * d;
  velocity *= 22.5 / model.norm(velocity);
  const int fields = morseIndexOnChain(chain, from, velocity);
  EXPECT_EQ(fields, discreteMorseIndex(model, from, velocity, 800));
  EXPECT_GE(fields, 30);
}

// Long chains: hinge coordinates as large as the base L, whose rounding (about 1e-16 of L^2 in a constraint,
// 1e-14 of L in a Newton step) stopped both the projection and route 2 short of their absolute bounds.
TEST(Connect, LongChainsBothRoutesAgree) {
  const Chain chain = Chain::uniform(12, 11.2);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(11), b = Eigen::VectorXd::Zero(11);
  a(0) = 0.8, a(3) = -0.4, a(7) = 0.3, a(10) = 0.2;
  b(0) = 0.7, b(3) = 0.2, b(6) = -0.5, b(9) = 0.3;
  const Eigen::VectorXd from = ConstrainedModel::stack(hingePositionsAt(chain, a.normalized()));
  const Eigen::VectorXd to = ConstrainedModel::stack(hingePositionsAt(chain, b.normalized()));
  ConnectOptions options;
  options.directions = 8;
  expectRoutesAgree(findConnections(model, &chain, from, to, options));
}

// Beyond 12 rods shooting takes its derivative once and then Broyden's updates, the fan shoots fewer seeds and
// the Morse index comes from the discrete action: 60 rods, both routes agree and the end point is hit.
TEST(Connect, SixtyRodsBothRoutesAgree) {
  const Chain chain = Chain::uniform(60, 59.2);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  ASSERT_GT(model.freedom(), kExactShootingFreedom);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(59), b = Eigen::VectorXd::Zero(59);
  a(0) = 0.8, a(3) = -0.4, a(7) = 0.3, a(10) = 0.2, a(30) = 0.1, a(58) = -0.1;
  b(0) = 0.7, b(3) = 0.2, b(6) = -0.5, b(9) = 0.3, b(41) = 0.1, b(57) = 0.1;
  const Eigen::VectorXd from = ConstrainedModel::stack(hingePositionsAt(chain, a.normalized()));
  const Eigen::VectorXd to = ConstrainedModel::stack(hingePositionsAt(chain, b.normalized()));
  ConnectOptions options;
  options.maxLength = 2.5;
  const auto found = findConnections(model, &chain, from, to, options);
  expectRoutesAgree(found);
  const auto direct = directConnection(model, &chain, from, to);
  ASSERT_TRUE(direct.has_value());
  EXPECT_LE(direct->endError, 1e-12);
  EXPECT_NEAR(direct->length, found[0].length, 1e-10);
}

// Shapes bent along every coordinate (as the benchmark's, amplitude 0.4): the continuation along the sphere arc
// meets a fold at its last stage and the arc's first chord misses too; the shortest motion is found from
// route 2's descent from the arc (docs/geometry.md, "Long chains").
TEST(Connect, LongChainTargetBeyondTheArcsFold) {
  const int rods = 35, d = rods - 1;
  const Chain chain = Chain::uniform(rods, rods - 0.8);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(d), b = Eigen::VectorXd::Zero(d);
  a(0) = 0.8, a(3) = -0.4, a(7) = 0.3, a(10) = 0.2;
  b(0) = 0.7, b(3) = 0.2, b(6) = -0.5, b(9) = 0.3;
  for (int i = 0; i < d; ++i) {
    a(i) += 0.4 * std::cos(0.7 * i + 0.3) / std::sqrt(d / 10.0);
    b(i) += 0.4 * std::sin(1.3 * i) / std::sqrt(d / 10.0);
  }
  const Eigen::VectorXd from = ConstrainedModel::stack(hingePositionsAt(chain, a.normalized()));
  const Eigen::VectorXd to = ConstrainedModel::stack(hingePositionsAt(chain, b.normalized()));
  const auto direct = directConnection(model, &chain, from, to);
  ASSERT_TRUE(direct.has_value());
  EXPECT_LE(direct->endError, 1e-12);
  // Route 2 on its own: Newton from the arc fails, the descent reaches the same geodesic.
  const auto arc = sphereArcPaths(chain, from, to, 5 * kPathSamples)[0];
  EXPECT_FALSE(discreteGeodesic(model, arc, DiscreteSeed::SphereArc).has_value());
  const auto discrete = discreteGeodesic(model, arc, DiscreteSeed::SphereArc, true);
  ASSERT_TRUE(discrete.has_value());
  EXPECT_NEAR(discrete->length, direct->length, 1e-8);
  const auto path = shootingPath(model, from, direct->velocity, kPathSamples);
  for (int j = 0; j <= kPathSamples; ++j)
    EXPECT_LT((path[j] - discrete->path[j]).cwiseAbs().maxCoeff(), 1e-7) << "t = " << j << " / " << kPathSamples;
  EXPECT_EQ(discreteMorseIndex(model, from, direct->velocity), 0);
}

// The sparse KKT solve (long chains) against the dense one written out: the same x and multipliers.
TEST(ConstrainedModel, SparseKktSolveAgreesWithTheDenseOne) {
  Chain chain = Chain::uniform(20, 18.5);
  chain.rodMasses = Eigen::VectorXd::LinSpaced(20, 0.5, 2.0);  // M block-tridiagonal
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  ASSERT_TRUE(model.sparse());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(19);
  x(0) = 0.6, x(5) = 0.5, x(11) = -0.6;
  const Eigen::VectorXd q = ConstrainedModel::stack(hingePositionsAt(chain, x.normalized()));
  const int n = model.dimension(), m = model.constraintCount();
  const Eigen::MatrixXd g = model.jacobian(q);
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + m, n + m);
  kkt << model.mass(), g.transpose(), g, Eigen::MatrixXd::Zero(m, m);
  const Eigen::VectorXd top = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0),
                        bottom = Eigen::VectorXd::LinSpaced(m, 0.3, -0.7);
  Eigen::VectorXd rhs(n + m);
  rhs << top, bottom;
  const Eigen::VectorXd dense = kkt.fullPivLu().solve(rhs);
  Eigen::VectorXd mu;
  const KktFactor factor(model, q);
  const Eigen::VectorXd sparse = factor.solve(top, bottom, &mu);
  EXPECT_LT((sparse - dense.head(n)).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((mu - dense.tail(m)).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((factor.jacobianTimes(top) - g * top).cwiseAbs().maxCoeff(), 1e-12);
  // The correction is the M-smallest x with G x = -r.
  const Eigen::VectorXd correction = factor.correction(bottom);
  EXPECT_LT((g * correction + bottom).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_NEAR(model.norm(correction),
              std::sqrt(bottom.dot((g * model.mass().inverse() * g.transpose()).ldlt().solve(bottom))), 1e-10);
}

TEST(ConstrainedModel, ProjectsFortyRodsOntoTheirConstraints) {
  const Chain chain = Chain::uniform(40, 39.0);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(39);
  x(0) = 0.6, x(12) = 0.5, x(30) = -0.6;
  const Eigen::VectorXd exact = ConstrainedModel::stack(hingePositionsAt(chain, x.normalized()));
  Eigen::VectorXd q = exact;
  EXPECT_TRUE(model.projectPosition(q));  // already on them, to rounding
  EXPECT_LT((q - exact).cwiseAbs().maxCoeff(), 1e-12);
  for (Eigen::Index i = 0; i < q.size(); ++i) q(i) += 1e-4 * std::sin(3.0 * static_cast<double>(i));
  EXPECT_TRUE(model.projectPosition(q));
  EXPECT_LT(model.values(q).cwiseAbs().maxCoeff(), 1e-13 * 39 * 39);
}

// Route 3: the chart methods' own equations of motion (exact Christoffel symbols; the normal acceleration of the
// embedding) reach the same target at the same length as route 1, for the shortest motion and the next. (The
// published finite-difference forms are too rough for the tight tolerance: their step control collapses.)
TEST(Connect, ChartMethodsFindTheSameMotions) {
  const Chain chain = Chain::uniform(4, 3.0);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const Eigen::VectorXd from = pointOf(chain, 0.5, 0.3), to = pointOf(chain, -0.6, 2.2);
  ConnectOptions options;
  options.maxLength = 6.0;
  options.discreteRoute = false;
  const auto found = findConnections(model, &chain, from, to, options);
  ASSERT_GE(found.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    for (const Method method : {Method::Christoffel, Method::Embedded}) {
      SCOPED_TRACE(nameOf(method) + " #" + std::to_string(i));
      const auto shot = shootWithMethod(chain, method, from, to, found[i].velocity);
      ASSERT_TRUE(shot.has_value());
      EXPECT_LE(shot->endError, 1e-12);
      EXPECT_NEAR(shot->length, found[i].length, 1e-8);
    }
  }
  // A method that cannot move the chain says why.
  const Chain five = Chain::uniform(5, 3.5);
  EXPECT_THROW(shootWithMethod(five, Method::ChristoffelFd,
                               ConstrainedModel::stack(hingePositionsAt(five, Eigen::Vector3d(1, 0, 0))),
                               ConstrainedModel::stack(hingePositionsAt(five, Eigen::Vector3d(0, 1, 0))),
                               Eigen::VectorXd::Zero(8)),
               std::invalid_argument);
}

// Route 2 alone on a path that is not a geodesic converges to the same one (the end points are fixed).
TEST(Connect, DiscreteRouteEndsOnTheTarget) {
  const Chain chain = Chain::uniform(4, 2.5);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const Eigen::VectorXd from = pointOf(chain, 0.2, 0.1), to = pointOf(chain, 0.9, -1.0);
  const auto arcs = sphereArcPaths(chain, from, to, 40);
  const auto g = discreteGeodesic(model, arcs[0], DiscreteSeed::SphereArc);
  ASSERT_TRUE(g.has_value());
  EXPECT_LT((g->path.back() - to).cwiseAbs().maxCoeff(), 1e-15);
  const auto shot = directConnection(model, &chain, from, to);
  ASSERT_TRUE(shot.has_value());
  EXPECT_NEAR(shot->length, g->length, 1e-8);
}

}  // namespace
}  // namespace sl

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include <gtest/gtest.h>

#include "inverse/connect.hpp"
#include "inverse/distance_map.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/trajectory.hpp"
#include "support.hpp"

namespace sl {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Vector3d radial(const Eigen::VectorXd& q) { return Eigen::Vector3d(q(0), q(1), q(2)).normalized(); }

double gridSpacing(const DistanceMap& map) { return kPi / (static_cast<double>(map.phis.size()) - 1); }

// A round sphere through the same code (an ellipsoid with equal axes): the distance is the great-circle
// distance, every first conjugate point is the antipode at pi, the cut locus shrinks to the antipode, and
// both sides of Klingenberg's lemma are pi (great circles are the loops, 2 pi long).
TEST(DistanceMap, RoundSphere) {
  const ConstrainedModel sphere = ConstrainedModel::ellipsoid(1, 1, 1);
  const Eigen::Vector3d p = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  DistanceMapOptions options;
  options.grid = 96;
  options.directions = 64;
  const DistanceMap map = distanceMap(sphere, radial, p, options);
  const double cell = gridSpacing(map);
  double worst = 0;
  for (std::size_t i = 0; i < map.phis.size(); ++i)
    for (std::size_t j = 0; j < map.ts.size(); ++j) {
      const Eigen::Vector3d x(std::cos(map.phis[i]) * std::cos(map.ts[j]), std::cos(map.phis[i]) * std::sin(map.ts[j]),
                              std::sin(map.phis[i]));
      worst = std::max(worst, std::abs(map.distance[i * map.ts.size() + j] - std::acos(std::clamp(x.dot(p), -1.0, 1.0))));
    }
  EXPECT_LT(worst, 0.05 * cell);
  EXPECT_EQ(map.uncovered, 0);
  ASSERT_GE(map.conjugateLocus.size(), 64u);
  for (const ConjugatePoint& c : map.conjugateLocus) {
    EXPECT_NEAR(c.distance, kPi, 1e-8);
    EXPECT_LT((c.x + p).norm(), 1e-7);
    EXPECT_TRUE(c.cut) << "the antipode is a cut point";
  }
  for (const CutEdge& e : map.cutLocus) EXPECT_LT((e.x + p).norm(), 4 * cell);
  EXPECT_NEAR(map.conjugateRadius, kPi, 1e-8);
  EXPECT_NEAR(map.shortestLoop, 2 * kPi, 1e-8);
  EXPECT_NEAR(map.klingenberg(), kPi, 1e-8);
  EXPECT_NEAR(map.injectivityRadius, kPi, 1e-8);
}

// Confocal (ellipsoidal) coordinates of a point of the ellipsoid with semi-axes a < b < c: the two roots
// lambda of sum x_i^2 / (a_i^2 + lambda) = 1 other than 0, one in (-c^2, -b^2), one in (-b^2, -a^2). The lines
// of curvature are the curves where one of them is constant.
Eigen::Vector2d confocal(const Eigen::Vector3d& axes, const Eigen::Vector3d& x) {
  auto f = [&](double lambda) {
    double sum = -1;
    for (int i = 0; i < 3; ++i) sum += x(i) * x(i) / (axes(i) * axes(i) + lambda);
    return sum;
  };
  Eigen::Vector2d roots;
  const double a2 = axes(0) * axes(0), b2 = axes(1) * axes(1), c2 = axes(2) * axes(2);
  const std::pair<double, double> brackets[2] = {{-c2, -b2}, {-b2, -a2}};
  for (int k = 0; k < 2; ++k) {
    double lo = brackets[k].first, hi = brackets[k].second;  // f > 0 near lo, < 0 near hi
    for (int it = 0; it < 200; ++it) {
      const double mid = (lo + hi) / 2;
      (f(mid) > 0 ? lo : hi) = mid;
    }
    roots(k) = (lo + hi) / 2;
  }
  return roots;
}

// A triaxial ellipsoid, a point on no principal ellipse (not umbilic): the conjugate locus has four cusps,
// and the cut locus lies on a line of curvature through the antipode (Itoh and Kiyohara): one of the
// confocal coordinates is the point's own all along it, the other varies.
TEST(DistanceMap, TriaxialEllipsoid) {
  const Eigen::Vector3d axes(1.0, 1.5, 2.0);
  const ConstrainedModel ellipsoid = ConstrainedModel::ellipsoid(axes(0), axes(1), axes(2));
  Eigen::VectorXd p = Eigen::Vector3d(0.45, 0.7, 1.2);
  ASSERT_TRUE(ellipsoid.projectPosition(p));
  DistanceMapOptions options;
  options.grid = 128;
  options.directions = 96;
  const DistanceMap map = distanceMap(ellipsoid, radial, p, options);
  EXPECT_EQ(map.uncovered, 0);
  EXPECT_EQ(conjugateCusps(map), 4);
  ASSERT_GE(map.cutLocus.size(), 10u);
  const Eigen::Vector2d own = confocal(axes, p);
  Eigen::Vector2d deviation = Eigen::Vector2d::Zero(), lo = Eigen::Vector2d::Constant(1e9), hi = -lo;
  for (const CutEdge& e : map.cutLocus) {
    Eigen::VectorXd x = e.x;
    x = x * (1 / std::sqrt((x.array() / axes.array()).square().sum()));  // radially onto the ellipsoid
    const Eigen::Vector2d c = confocal(axes, x);
    deviation = deviation.cwiseMax((c - own).cwiseAbs());
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const int line = deviation(0) < deviation(1) ? 0 : 1;
  EXPECT_LT(deviation(line), 0.05) << "cut points off the line of curvature";
  EXPECT_GT(hi(1 - line) - lo(1 - line), 0.5) << "the cut locus should be a segment along it";
  // Klingenberg: the nearest cut point at min(first conjugate distance, half the shortest loop).
  EXPECT_NEAR(map.injectivityRadius, map.klingenberg(), 3 * gridSpacing(map) * 2.0);
}

class LinkageDistanceMap : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    chain_ = new Chain(Chain::uniform(4, 3.0));
    model_ = new ConstrainedModel(ConstrainedModel::fromChain(*chain_));
    from_ = new Eigen::VectorXd(pointOf(*chain_, 0.5, 0.3));
    DistanceMapOptions options;
    options.grid = 128;
    const Chain chain = *chain_;
    map_ = new DistanceMap(distanceMap(
        *model_,
        [chain](const Eigen::VectorXd& q) -> Eigen::Vector3d {
          return spherePointFromHinges(chain, ConstrainedModel::unstack(q));
        },
        *from_, options));
  }
  static void TearDownTestSuite() {
    delete map_;
    delete from_;
    delete model_;
    delete chain_;
  }
  static Chain* chain_;
  static ConstrainedModel* model_;
  static Eigen::VectorXd* from_;
  static DistanceMap* map_;
};
Chain* LinkageDistanceMap::chain_ = nullptr;
ConstrainedModel* LinkageDistanceMap::model_ = nullptr;
Eigen::VectorXd* LinkageDistanceMap::from_ = nullptr;
DistanceMap* LinkageDistanceMap::map_ = nullptr;

// The map at sampled nodes against connect's shortest motion to that node's configuration.
TEST_F(LinkageDistanceMap, AgreesWithConnect) {
  const DistanceMap& map = *map_;
  EXPECT_EQ(map.uncovered, 0);
  ConnectOptions options;
  options.discreteRoute = false;
  int compared = 0;
  for (const auto& [i, j] : {std::pair{20, 10}, {40, 100}, {64, 64}, {90, 30}, {110, 70}, {75, 120}}) {
    const std::vector<Connection> found = findConnections(*model_, chain_, *from_,
                                                          pointOf(*chain_, map.phis[i], map.ts[j]), options);
    ASSERT_FALSE(found.empty());
    const double d = map.distance[static_cast<std::size_t>(i) * map.ts.size() + j];
    EXPECT_NEAR(d / found[0].length, 1.0, 1e-3) << "node (" << i << ", " << j << ")";
    ++compared;
  }
  EXPECT_EQ(compared, 6);
}

// The distance at points between the grid's nodes (geometry --distance-from --points): exact, connect's shortest
// motion to 1e-9, where the map itself is good to 1e-3; at a cut edge's midpoint too, where two geodesics arrive.
TEST_F(LinkageDistanceMap, ShortestArrivalBetweenNodesIsConnectsShortest) {
  const DistanceMap& map = *map_;
  ConnectOptions options;
  options.discreteRoute = false;
  std::vector<std::pair<double, double>> points = {{0.123, -2.71}, {-0.9, 0.4567}, {1.2345, 2.0}, {-1.4, -0.33}};
  ASSERT_FALSE(map.cutLocus.empty());
  const Eigen::Vector3d cut = map.cutLocus[map.cutLocus.size() / 2].x;
  points.emplace_back(std::asin(cut.z()), std::atan2(cut.y(), cut.x()));
  for (const auto& [phi, t] : points) {
    const Eigen::VectorXd to = pointOf(*chain_, phi, t);
    const Eigen::Vector3d x(std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi));
    const std::optional<Arrival> arrival = shortestArrival(*model_, map, *from_, to, x);
    ASSERT_TRUE(arrival) << phi << ", " << t;
    const std::vector<Connection> found = findConnections(*model_, chain_, *from_, to, options);
    ASSERT_FALSE(found.empty());
    EXPECT_NEAR(arrival->distance, found[0].length, 1e-9) << phi << ", " << t;
  }
}

// The cut locus is a tree: one component, no cycle, in the graph of the grid's faces.
TEST_F(LinkageDistanceMap, CutLocusIsATree) {
  const CutGraphShape shape = cutGraphShape(*map_);
  EXPECT_GT(shape.edges, 20);
  EXPECT_EQ(shape.components, 1);
  EXPECT_EQ(shape.cycles(), 0);
}

// From other points and at other L (128 x 128): a tree each time, and the nearest cut point at Klingenberg's
// minimum.
TEST(DistanceMap, CutLocusIsATreeFromOtherPoints) {
  for (const auto& [length, phi, t] : {std::tuple{3.0, -0.2, 1.7}, {3.0, 1.2, -2.5}, {3.0, 0.0, 0.0}, {3.5, 0.0, 0.0}}) {
    const Chain chain = Chain::uniform(4, length);
    DistanceMapOptions options;
    options.grid = 128;
    const DistanceMap map = distanceMap(
        ConstrainedModel::fromChain(chain),
        [chain](const Eigen::VectorXd& q) -> Eigen::Vector3d {
          return spherePointFromHinges(chain, ConstrainedModel::unstack(q));
        },
        pointOf(chain, phi, t), options);
    const CutGraphShape shape = cutGraphShape(map);
    EXPECT_EQ(shape.components, 1) << "L = " << length << " from (" << phi << ", " << t << ")";
    EXPECT_EQ(shape.cycles(), 0) << "L = " << length << " from (" << phi << ", " << t << ")";
    EXPECT_NEAR(map.injectivityRadius, map.klingenberg(), 0.05 * map.klingenberg());
  }
}

// The first conjugate points against the Jacobi fields of the ambient method (an independent integrator).
TEST_F(LinkageDistanceMap, ConjugatePointsAgreeWithTheJacobiRuns) {
  const DistanceMap& map = *map_;
  ASSERT_GE(map.conjugateLocus.size(), 100u);
  const Eigen::VectorXd x = spherePointFromHinges(*chain_, ConstrainedModel::unstack(*from_));
  for (std::size_t k = 0; k < map.conjugateLocus.size(); k += map.conjugateLocus.size() / 7) {
    const ConjugatePoint& c = map.conjugateLocus[k];
    const Eigen::VectorXd u = std::cos(c.angle) * map.basis.col(0) + std::sin(c.angle) * map.basis.col(1);
    const InitialState start(x, sphereVelocityFromHingeVelocities(*chain_, x, ConstrainedModel::unstack(u)));
    RunConfig config;
    config.jacobi = true;
    Trajectory run(*chain_, start, config);
    run.sampleAt(c.distance + 0.5);
    ASSERT_FALSE(run.conjugateTimes().empty());
    EXPECT_NEAR(run.conjugateTimes().front(), c.distance, 1e-6) << "angle " << c.angle;
  }
  // Klingenberg's lemma: the nearest cut point against min(conjugate radius, half the shortest loop).
  EXPECT_GT(map.shortestLoop, 0);
  EXPECT_NEAR(map.injectivityRadius, map.klingenberg(), 0.05 * map.klingenberg());
}

}  // namespace
}  // namespace sl

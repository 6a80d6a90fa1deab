// Inverse problems (src/inverse), 4 rods, L = 3, unit hinge masses, from (phi, t) = (0.5, 0.3) to (-0.6, 2.2).
//   BM_ConnectShortest: the shortest motion by shooting from the great-circle continuation (target: < 50 ms).
//   BM_ConnectDiscrete: route 2 alone from the sphere arc, refined until its extrapolated length settles.
//   BM_ConnectAll: both routes, every geodesic up to length 8 (what `linkage connect` does).
//   BM_ConnectLongChainShortest/n, BM_ConnectLongChain/n: the same on n rods, L = n - 0.8 (slack 0.8), between
//   two shapes bent along every sphere coordinate: the shortest motion by route 1, and every motion up to 1.5
//   times it by both routes with Morse indices (docs/geometry.md, "Long chains"). One iteration each.
#include <algorithm>
#include <cmath>

#include <benchmark/benchmark.h>

#include "inverse/connect.hpp"
#include "inverse/distance_map.hpp"
#include "inverse/periodic.hpp"
#include "linkage/chart.hpp"

namespace {

const sl::Chain chain = sl::Chain::uniform(4, 3.0);
const sl::ConstrainedModel model = sl::ConstrainedModel::fromChain(chain);

Eigen::VectorXd pointOf(double phi, double t) {
  Eigen::VectorXd c(2);
  c << phi, t;
  return sl::ConstrainedModel::stack(sl::hingePositions(chain, c));
}

const Eigen::VectorXd from = pointOf(0.5, 0.3), to = pointOf(-0.6, 2.2);

void BM_ConnectShortest(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sl::directConnection(model, &chain, from, to));
}

void BM_ConnectDiscrete(benchmark::State& state) {
  const auto arc = sl::sphereArcPaths(chain, from, to, 40)[0];
  for (auto _ : state) benchmark::DoNotOptimize(sl::discreteGeodesic(model, arc, sl::DiscreteSeed::SphereArc));
}

void BM_ConnectAll(benchmark::State& state) {
  sl::ConnectOptions options;
  options.maxLength = 8;
  for (auto _ : state) benchmark::DoNotOptimize(sl::findConnections(model, &chain, from, to, options));
}

}  // namespace

BENCHMARK(BM_ConnectShortest)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConnectDiscrete)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConnectAll)->Unit(benchmark::kMillisecond);

namespace {

struct LongChainCase {
  sl::Chain chain;
  sl::ConstrainedModel model;
  Eigen::VectorXd from, to;
  explicit LongChainCase(int rods)
      : chain(sl::Chain::uniform(rods, rods - 0.8)), model(sl::ConstrainedModel::fromChain(chain)) {
    const int d = rods - 1;
    Eigen::VectorXd a(d), b(d);
    a.setZero();
    b.setZero();
    a(0) = 0.8, a(3) = -0.4, a(7) = 0.3, a(10) = 0.2;  // as the 12-rod test, then bent along every coordinate
    b(0) = 0.7, b(3) = 0.2, b(6) = -0.5, b(9) = 0.3;
    for (int i = 0; i < d; ++i) {
      a(i) += 0.1 * std::cos(0.7 * i + 0.3) / std::sqrt(d / 10.0);
      b(i) += 0.1 * std::sin(1.3 * i) / std::sqrt(d / 10.0);
    }
    from = sl::ConstrainedModel::stack(sl::hingePositionsAt(chain, a.normalized()));
    to = sl::ConstrainedModel::stack(sl::hingePositionsAt(chain, b.normalized()));
  }
};

void BM_ConnectLongChainShortest(benchmark::State& state) {
  const LongChainCase c(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(sl::directConnection(c.model, &c.chain, c.from, c.to));
}

void BM_ConnectLongChain(benchmark::State& state) {
  const LongChainCase c(static_cast<int>(state.range(0)));
  const auto shortest = sl::directConnection(c.model, &c.chain, c.from, c.to);
  sl::ConnectOptions options;
  options.maxLength = shortest ? 1.5 * shortest->length : 0;
  std::size_t found = 0, both = 0;
  for (auto _ : state) {
    const auto motions = sl::findConnections(c.model, &c.chain, c.from, c.to, options);
    found = motions.size();
    both = static_cast<std::size_t>(std::count_if(motions.begin(), motions.end(),
                                                  [](const sl::Connection& m) { return m.discrete.has_value(); }));
  }
  state.counters["found"] = static_cast<double>(found);
  state.counters["both_routes"] = static_cast<double>(both);
  state.counters["length"] = shortest ? shortest->length : 0;
}

}  // namespace

BENCHMARK(BM_ConnectLongChainShortest)->Arg(40)->Arg(100)->Arg(200)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_ConnectLongChain)->Arg(40)->Arg(100)->Arg(200)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

namespace {

// BM_PeriodicChain: the simple closed geodesics of the 4-rod chain, L = 3, unit hinge masses, both routes
// (what `linkage periodic` does; target: the three simple ones in under 1 s).
void BM_PeriodicChain(benchmark::State& state) {
  const sl::Chain four = sl::Chain::uniform(4, 3.0);
  for (auto _ : state) benchmark::DoNotOptimize(sl::chainClosedGeodesics(four, sl::PeriodicOptions{}));
}

}  // namespace

BENCHMARK(BM_PeriodicChain)->Unit(benchmark::kMillisecond);

namespace {

// BM_DistanceMap256: the distance map from (phi, t) = (0.5, 0.3) on a 256 x 256 grid with its loci and the
// shortest loop (what `linkage geometry --distance-from` computes; target: under 5 s on 2 cores).
void BM_DistanceMap256(benchmark::State& state) {
  const sl::SphereProjection project = [](const Eigen::VectorXd& q) -> Eigen::Vector3d {
    return sl::spherePointFromHinges(chain, sl::ConstrainedModel::unstack(q));
  };
  sl::DistanceMapOptions options;
  options.grid = 256;
  for (auto _ : state) benchmark::DoNotOptimize(sl::distanceMap(model, project, from, options));
}

}  // namespace

BENCHMARK(BM_DistanceMap256)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

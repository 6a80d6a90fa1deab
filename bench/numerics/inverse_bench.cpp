// Inverse problems (src/inverse), 4 rods, L = 3, unit hinge masses, from (phi, t) = (0.5, 0.3) to (-0.6, 2.2).
//   BM_ConnectShortest: the shortest motion by shooting from the great-circle continuation (target: < 50 ms).
//   BM_ConnectDiscrete: route 2 alone from the sphere arc, refined until its extrapolated length settles.
//   BM_ConnectAll: both routes, every geodesic up to length 8 (what `linkage connect` does).
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
  for (auto _ : state) benchmark::DoNotOptimize(sl::discreteGeodesic(model, arc, "sphere arc"));
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

// Holonomy and sectional curvature (issue 42; docs/geometry.md, "Parallel transport and holonomy").
//   BM_HolonomyTriangle: the holonomy of a 3-corner loop on 4 rods, L = 3, including its three connects, both
//     transport routes, the enclosed curvature and the angle excess (target: < 0.5 s).
//   BM_HolonomyLatitude: the same for the latitude phi = 0.5 (both routes and the cap's curvature).
//   BM_HolonomyDrawn: the triangle with the samples frames draw (12 per side, each with its swept curvature).
//   BM_HolonomyClosedGeodesic: closed geodesic 0 of L = 3 (found once, outside the loop): both routes and the
//     curvature of the half sphere inside it.
//   BM_SectionalRange: the minimum and maximum of the sectional curvature over the planes at a point, 5 rods,
//     L = 4 (target: < 1 ms); BM_SectionalRange/6: 6 rods (the alternating search).
//   BM_SectionalPlane, BM_SectionalPlaneIntrinsic: one plane's curvature by each route, 5 rods.
#include <benchmark/benchmark.h>

#include "geometry/sectional_curvature.hpp"
#include "inverse/holonomy.hpp"
#include "linkage/chain_constants.hpp"

namespace {

Eigen::VectorXd unit(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values) v(i++) = x;
  return v.normalized();
}

void BM_HolonomyTriangle(benchmark::State& state) {
  const sl::Chain chain = sl::Chain::uniform(4, 3.0);
  const std::vector<Eigen::VectorXd> corners = {unit({1, 0, 0.2}), unit({0.2, 1, 0.3}), unit({0.4, 0.3, 1})};
  for (auto _ : state) benchmark::DoNotOptimize(sl::polygonHolonomy(chain, corners));
}

void BM_HolonomyDrawn(benchmark::State& state) {
  const sl::Chain chain = sl::Chain::uniform(4, 3.0);
  const std::vector<Eigen::VectorXd> corners = {unit({1, 0, 0.2}), unit({0.2, 1, 0.3}), unit({0.4, 0.3, 1})};
  for (auto _ : state) benchmark::DoNotOptimize(sl::polygonHolonomy(chain, corners, nullptr, 12));
}

void BM_HolonomyClosedGeodesic(benchmark::State& state) {
  const sl::Chain chain = sl::Chain::uniform(4, 3.0);
  const sl::ClosedGeodesic geodesic = sl::closedGeodesicsOf(chain, 0).at(0);
  for (auto _ : state) benchmark::DoNotOptimize(sl::closedGeodesicHolonomy(chain, geodesic));
}

void BM_HolonomyLatitude(benchmark::State& state) {
  const sl::Chain chain = sl::Chain::uniform(4, 3.0);
  for (auto _ : state) benchmark::DoNotOptimize(sl::latitudeHolonomy(chain, 0.5));
}

void BM_SectionalRange(benchmark::State& state) {
  const int rods = static_cast<int>(state.range(0));
  const sl::ChainConstants bound(sl::Chain::uniform(rods, rods - 1.0));
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(rods - 1, 0.3, -0.7).normalized();
  for (auto _ : state) benchmark::DoNotOptimize(sl::sectionalCurvatureRange(bound, x));
}

template <bool intrinsic>
void BM_SectionalPlane(benchmark::State& state) {
  const sl::ChainConstants bound(sl::Chain::uniform(5, 4.0));
  const Eigen::VectorXd x = unit({0.3, -0.2, 0.5, 0.6});
  const Eigen::VectorXd X = unit({0.6, 0, 0, -0.3}), Y = unit({0, 1, 0.4, 0});
  const Eigen::VectorXd Xt = X - X.dot(x) * x, Yt = Y - Y.dot(x) * x;
  for (auto _ : state)
    benchmark::DoNotOptimize(intrinsic ? sl::sectionalCurvatureIntrinsic(bound, x, Xt, Yt)
                                       : sl::sectionalCurvature(bound, x, Xt, Yt));
}

}  // namespace

BENCHMARK(BM_HolonomyTriangle)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HolonomyDrawn)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HolonomyClosedGeodesic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HolonomyLatitude)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SectionalRange)->Arg(5)->Arg(6)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SectionalPlane, false)->Name("BM_SectionalPlane")->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_SectionalPlane, true)->Name("BM_SectionalPlaneIntrinsic")->Unit(benchmark::kMicrosecond);

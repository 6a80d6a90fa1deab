// Curvature of the configuration sphere, 4 rods, L = 3, unit hinge masses.
//   BM_CurvatureGrid/256/threads: every quantity (K, bending, stiffness max/min/angle, area density) on a
//     256 x 256 chart 0 grid, both poles included (target: under 50 ms on 2 cores); wall time.
//   BM_CurvatureSample: one point, everything; BM_SecondFundamentalForm: the jet pass and the projection only.
//   BM_StiffnessExtremes: the exact max/min of S(a) from a Gram matrix.
//   BM_GaussBonnet/n: area and total curvature with n Gauss-Legendre x 2n trapezoid nodes, 2 threads.
//   BM_CurvatureSummary: area, total curvature (converged to 1e-12), K min/max and bending max refined, 2 threads.
#include <benchmark/benchmark.h>

#include "geometry/curvature_grid.hpp"

namespace {

const sl::ConfigurationSurface surface(sl::Chain::uniform(4, 3.0));

void BM_CurvatureGrid(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), threads = static_cast<int>(state.range(1));
  const sl::ChartGrid grid = sl::uniformChartGrid(n, n);
  for (auto _ : state) benchmark::DoNotOptimize(sl::curvatureGrid(surface, grid.phis, grid.ts, threads));
  state.counters["points"] = n * n;
}

void BM_CurvatureSample(benchmark::State& state) {
  double phi = 0.3;
  for (auto _ : state) {
    benchmark::DoNotOptimize(surface.curvatureAtCoordinates(phi, 0.2));
    phi = phi < 1.0 ? phi + 1e-3 : 0.3;
  }
}

void BM_SecondFundamentalForm(benchmark::State& state) {
  double phi = 0.3;
  for (auto _ : state) {
    benchmark::DoNotOptimize(surface.secondFundamentalForm(0, Eigen::Vector2d(phi, 0.2)));
    phi = phi < 1.0 ? phi + 1e-3 : 0.3;
  }
}

void BM_StiffnessExtremes(benchmark::State& state) {
  const sl::CurvatureSample sample = surface.curvatureAtCoordinates(0.3, 0.2);
  Eigen::Matrix3d gram = sample.frameGram;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sl::stiffnessExtremes(gram));
    gram(0, 0) *= 1.0 + 1e-12;
  }
}

void BM_GaussBonnet(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(sl::integrateOverSphere(surface, n, 2 * n, 2));
}

void BM_CurvatureSummary(benchmark::State& state) {
  sl::SummaryOptions options;
  options.threads = 2;
  for (auto _ : state) benchmark::DoNotOptimize(sl::curvatureSummary(surface.chain(), options));
}

}  // namespace

BENCHMARK(BM_CurvatureGrid)->Args({256, 1})->Args({256, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CurvatureSample);
BENCHMARK(BM_SecondFundamentalForm);
BENCHMARK(BM_StiffnessExtremes);
BENCHMARK(BM_GaussBonnet)->Arg(96)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CurvatureSummary)->Unit(benchmark::kMillisecond)->UseRealTime();

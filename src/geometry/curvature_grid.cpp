#include "geometry/curvature_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <boost/math/special_functions/legendre.hpp>

#include "contracts/parallel_for.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {

namespace {

// fn(i) for i in [0, count) on up to `threads` threads (0: the machine's): each item's result depends on i alone.
template <class Fn>
void forEachIndex(int count, int threads, const Fn& fn) {
  parallelFor(static_cast<std::size_t>(std::max(0, count)), static_cast<std::size_t>(std::max(0, threads)),
                  [&fn](std::size_t i) { fn(static_cast<int>(i)); });
}

Eigen::Vector3d chartZeroPoint(double phi, double t) {
  return {std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)};
}

}  // namespace

// === Maps

ChartGrid uniformChartGrid(int phiCount, int tCount) {
  if (phiCount < 2 || tCount < 1) throw std::invalid_argument("a chart grid needs at least 2 x 1 nodes");
  ChartGrid grid;
  for (int i = 0; i < phiCount; ++i) grid.phis.push_back(-M_PI / 2 + M_PI * i / (phiCount - 1));
  for (int j = 0; j < tCount; ++j) grid.ts.push_back(-M_PI + 2 * M_PI * j / tCount);
  return grid;
}

std::vector<CurvatureSample> curvatureGrid(const ConfigurationSurface& surface, const std::vector<double>& phis,
                                           const std::vector<double>& ts, int threads) {
  std::vector<CurvatureSample> samples(phis.size() * ts.size());
  forEachIndex(static_cast<int>(phis.size()), threads, [&](int i) {
    for (size_t j = 0; j < ts.size(); ++j)
      samples[static_cast<size_t>(i) * ts.size() + j] =
          surface.curvatureAtCoordinates(phis[static_cast<size_t>(i)], ts[j]);
  });
  return samples;
}

std::vector<CurvatureSample> curvatureSamples(const ConfigurationSurface& surface,
                                              const std::vector<Eigen::Vector2d>& coords, int threads) {
  std::vector<CurvatureSample> samples(coords.size());
  constexpr int kBlock = 64;
  const int blocks = static_cast<int>((coords.size() + kBlock - 1) / kBlock);
  forEachIndex(blocks, threads, [&](int b) {
    const size_t end = std::min(coords.size(), static_cast<size_t>(b + 1) * kBlock);
    for (size_t k = static_cast<size_t>(b) * kBlock; k < end; ++k)
      samples[k] = surface.curvatureAtCoordinates(coords[k](0), coords[k](1));
  });
  return samples;
}

// === Integrals

void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  if (n < 1) throw std::invalid_argument("Gauss-Legendre needs at least one node");
  // Boost's rule for a number of nodes known only at run time: the non-negative roots of P_n
  // (boost::math::legendre_p_zeros, ascending, 0 first for odd n) and w = 2 / ((1 - x^2) P_n'(x)^2), as
  // boost::math::quadrature::gauss computes them for its compile-time sizes.
  const std::vector<double> roots = boost::math::legendre_p_zeros<double>(n);
  nodes.assign(static_cast<size_t>(n), 0.0);
  weights.assign(static_cast<size_t>(n), 0.0);
  for (size_t k = 0; k < roots.size(); ++k) {
    const double x = roots[k];
    const double derivative = boost::math::legendre_p_prime(n, x);
    const double w = 2.0 / ((1.0 - x * x) * derivative * derivative);
    // Root x >= 0 is node n/2 + k counted from the middle; its mirror -x is placed symmetrically.
    const size_t upper = static_cast<size_t>(n / 2) + k, lower = static_cast<size_t>(n - 1) - upper;
    nodes[upper] = x;
    nodes[lower] = -x;
    weights[upper] = weights[lower] = w;
  }
}

SphereIntegrals integrateOverSphere(const ConfigurationSurface& surface, int phiNodes, int tNodes, int threads) {
  if (tNodes < 1) throw std::invalid_argument("the t rule needs at least one node");
  std::vector<double> nodes, weights;
  gaussLegendre(phiNodes, nodes, weights);
  std::vector<double> rowArea(static_cast<size_t>(phiNodes)), rowCurvature(static_cast<size_t>(phiNodes));
  forEachIndex(phiNodes, threads, [&](int i) {
    const double phi = 0.5 * M_PI * nodes[static_cast<size_t>(i)];
    double area = 0.0, curvature = 0.0;
    for (int j = 0; j < tNodes; ++j) {
      const double t = -M_PI + 2.0 * M_PI * j / tNodes;
      const SecondFundamentalForm form = surface.secondFundamentalFormAt(chartZeroPoint(phi, t));
      // dA = rho(x) dOmega, dOmega = cos(phi) dphi dt in chart 0.
      const double dA = areaDensity(form) * std::cos(phi);
      area += dA;
      curvature += gaussianCurvature(form) * dA;
    }
    rowArea[static_cast<size_t>(i)] = area;
    rowCurvature[static_cast<size_t>(i)] = curvature;
  });
  SphereIntegrals out;
  out.phiNodes = phiNodes;
  out.tNodes = tNodes;
  const double scale = 0.5 * M_PI * 2.0 * M_PI / tNodes;
  for (int i = 0; i < phiNodes; ++i) {
    out.area += scale * weights[static_cast<size_t>(i)] * rowArea[static_cast<size_t>(i)];
    out.totalCurvature += scale * weights[static_cast<size_t>(i)] * rowCurvature[static_cast<size_t>(i)];
  }
  return out;
}

SphereIntegrals integrateOverSphereConverged(const ConfigurationSurface& surface, double tolerance, int maxPhiNodes,
                                             int threads) {
  int n = 24;
  SphereIntegrals previous = integrateOverSphere(surface, n, 2 * n, threads);
  for (;;) {
    n = (3 * n) / 2;
    SphereIntegrals next = integrateOverSphere(surface, n, 2 * n, threads);
    next.areaChange = std::abs(next.area - previous.area);
    next.curvatureChange = std::abs(next.totalCurvature - previous.totalCurvature);
    next.converged = next.areaChange <= tolerance * next.area && next.curvatureChange <= tolerance * 4.0 * M_PI;
    if (next.converged || (3 * n) / 2 > maxPhiNodes) return next;
    previous = next;
  }
}

// === Extrema

double surfaceQuantity(const ConfigurationSurface& surface, SurfaceQuantity quantity, const Eigen::Vector3d& x) {
  return quantity == SurfaceQuantity::gaussianCurvature ? surface.gaussianCurvature(x) : surface.bending(x);
}

SurfaceExtremum refineExtremum(const ConfigurationSurface& surface, SurfaceQuantity quantity, bool maximum,
                               const Eigen::Vector3d& start) {
  constexpr double kStep = 1e-3, kMaxMove = 0.05;
  constexpr int kMaxIterations = 60;
  const double sign = maximum ? -1.0 : 1.0;  // minimise sign * quantity
  Eigen::Vector3d x = start.normalized();
  SurfaceExtremum out;
  double previousMove = INFINITY;
  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    // Orthonormal tangent basis at x, from the axis x is least aligned with.
    Eigen::Index axis;
    x.cwiseAbs().minCoeff(&axis);
    const Eigen::Vector3d eu = (Eigen::Vector3d::Unit(axis) - x(axis) * x).normalized();
    const Eigen::Vector3d ev = x.cross(eu);
    const auto f = [&](double u, double v) { return sign * surfaceQuantity(surface, quantity, x + u * eu + v * ev); };
    const double f0 = f(0, 0);
    const double up = f(kStep, 0), um = f(-kStep, 0), vp = f(0, kStep), vm = f(0, -kStep);
    const double uph = f(kStep / 2, 0), umh = f(-kStep / 2, 0), vph = f(0, kStep / 2), vmh = f(0, -kStep / 2);
    // Richardson: (4 D(h/2) - D(h)) / 3 cancels the h^2 term of the central difference.
    const Eigen::Vector2d gradient((4.0 * (uph - umh) / kStep - (up - um) / (2 * kStep)) / 3.0,
                                   (4.0 * (vph - vmh) / kStep - (vp - vm) / (2 * kStep)) / 3.0);
    Eigen::Matrix2d hessian;
    hessian(0, 0) = (up - 2 * f0 + um) / (kStep * kStep);
    hessian(1, 1) = (vp - 2 * f0 + vm) / (kStep * kStep);
    hessian(0, 1) = hessian(1, 0) =
        (f(kStep, kStep) - f(kStep, -kStep) - f(-kStep, kStep) + f(-kStep, -kStep)) / (4 * kStep * kStep);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(hessian);
    Eigen::Vector2d move;
    if (eigen.eigenvalues().minCoeff() > 0.0) {
      move = -hessian.ldlt().solve(gradient);
    } else {  // not yet in a minimum's basin: a gradient step on the scale of the largest curvature
      move = -gradient / std::max(eigen.eigenvalues().cwiseAbs().maxCoeff(), 1e-3);
    }
    if (move.norm() > kMaxMove) move *= kMaxMove / move.norm();
    x = (x + move(0) * eu + move(1) * ev).normalized();
    out.iterations = iteration;
    out.positionError = move.norm();
    // Stop at 1e-12, or once below 1e-10 the steps stop contracting (the gradient's rounding floor).
    if (out.positionError <= 1e-12 || (out.positionError <= 1e-10 && out.positionError > 0.5 * previousMove)) break;
    previousMove = out.positionError;
  }
  out.converged = out.positionError <= 1e-10;
  out.spherePoint = x;
  out.value = surfaceQuantity(surface, quantity, x);
  const Eigen::VectorXd c = coordinatesFromSpherePoint(x);
  out.phi = c(0);
  out.t = c(1);
  return out;
}

namespace {

struct ScanGrid {
  int rows = 0, columns = 0;
  std::vector<double> phis, ts;
  std::vector<double> values;  // row-major
  double at(int i, int j) const { return values[static_cast<size_t>(i * columns + ((j + columns) % columns))]; }
};

ScanGrid scanQuantity(const ConfigurationSurface& surface, SurfaceQuantity quantity, int scan, int threads) {
  ScanGrid grid;
  const ChartGrid nodes = uniformChartGrid(scan + 1, 2 * scan);
  grid.rows = scan + 1;
  grid.columns = 2 * scan;
  grid.phis = nodes.phis;
  grid.ts = nodes.ts;
  grid.values.resize(static_cast<size_t>(grid.rows * grid.columns));
  forEachIndex(grid.rows, threads, [&](int i) {
    for (int j = 0; j < grid.columns; ++j)
      grid.values[static_cast<size_t>(i * grid.columns + j)] = surfaceQuantity(
          surface, quantity, chartZeroPoint(grid.phis[static_cast<size_t>(i)], grid.ts[static_cast<size_t>(j)]));
  });
  return grid;
}

// Refine the best few discrete local extrema of the scan and keep the best result.
SurfaceExtremum bestExtremum(const ConfigurationSurface& surface, SurfaceQuantity quantity, bool maximum,
                             const ScanGrid& grid) {
  const double sign = maximum ? -1.0 : 1.0;
  std::vector<std::pair<double, Eigen::Vector2i>> candidates;
  for (int i = 0; i < grid.rows; ++i)
    for (int j = 0; j < grid.columns; ++j) {
      const double v = sign * grid.at(i, j);
      bool local = true;
      for (int di = -1; di <= 1 && local; ++di)
        for (int dj = -1; dj <= 1 && local; ++dj) {
          if ((di == 0 && dj == 0) || i + di < 0 || i + di >= grid.rows) continue;
          if (sign * grid.at(i + di, j + dj) < v) local = false;
        }
      if (local) candidates.push_back({v, Eigen::Vector2i(i, j)});
    }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  constexpr size_t kRefined = 8;
  std::vector<SurfaceExtremum> refined;
  for (size_t k = 0; k < std::min(kRefined, candidates.size()); ++k) {
    const Eigen::Vector2i& ij = candidates[k].second;
    refined.push_back(
        refineExtremum(surface, quantity, maximum,
                       chartZeroPoint(grid.phis[static_cast<size_t>(ij(0))], grid.ts[static_cast<size_t>(ij(1))])));
  }
  if (refined.empty()) throw std::runtime_error("curvature scan found no discrete extremum");
  // Best value; values tied to rounding (mirror images) go to the larger phi, then the smaller t.
  SurfaceExtremum best = refined.front();
  for (const SurfaceExtremum& e : refined) {
    const double tie = 1e-10 * std::max(1.0, std::abs(best.value));
    const double difference = sign * (e.value - best.value);
    if (difference < -tie) {
      best = e;
    } else if (difference <= tie && (e.phi > best.phi + 1e-9 || (std::abs(e.phi - best.phi) <= 1e-9 && e.t < best.t))) {
      best = e;
    }
  }
  return best;
}

}  // namespace

CurvatureExtrema curvatureExtrema(const ConfigurationSurface& surface, int scan, int threads) {
  const ScanGrid curvature = scanQuantity(surface, SurfaceQuantity::gaussianCurvature, scan, threads);
  const ScanGrid bending = scanQuantity(surface, SurfaceQuantity::bending, scan, threads);
  CurvatureExtrema out;
  out.curvatureMin = bestExtremum(surface, SurfaceQuantity::gaussianCurvature, false, curvature);
  out.curvatureMax = bestExtremum(surface, SurfaceQuantity::gaussianCurvature, true, curvature);
  out.bendingMax = bestExtremum(surface, SurfaceQuantity::bending, true, bending);
  return out;
}

// === Summaries

CurvatureSummary curvatureSummary(const Chain& chain, const SummaryOptions& options) {
  const ConfigurationSurface surface(chain);
  CurvatureSummary out;
  out.baseLength = chain.baseLength;
  out.integrals = integrateOverSphereConverged(surface, options.quadratureTolerance, 768, options.threads);
  out.area = out.integrals.area;
  out.totalCurvature = out.integrals.totalCurvature;
  out.gaussBonnetError = out.totalCurvature - 4.0 * M_PI;
  const CurvatureExtrema extrema = curvatureExtrema(surface, options.scan, options.threads);
  out.curvatureMin = extrema.curvatureMin;
  out.curvatureMax = extrema.curvatureMax;
  out.bendingMax = extrema.bendingMax;
  return out;
}

std::vector<CurvatureSummary> curvatureSweep(const Chain& chain, double firstL, double lastL, int count,
                                             const SummaryOptions& options) {
  if (count < 1) throw std::invalid_argument("an L sweep needs at least one value");
  std::vector<CurvatureSummary> out;
  for (int k = 0; k < count; ++k) {
    Chain at = chain;
    at.baseLength = count == 1 ? firstL : firstL + (lastL - firstL) * k / (count - 1);
    out.push_back(curvatureSummary(at, options));
  }
  return out;
}

double minimumCurvature(const Chain& chain, double baseLength, const SummaryOptions& options) {
  Chain at = chain;
  at.baseLength = baseLength;
  const ConfigurationSurface surface(at);
  const ScanGrid grid = scanQuantity(surface, SurfaceQuantity::gaussianCurvature, options.scan, options.threads);
  return bestExtremum(surface, SurfaceQuantity::gaussianCurvature, false, grid).value;
}

double positiveCurvatureThreshold(const Chain& chain, double lo, double hi, double tolerance,
                                  const SummaryOptions& options) {
  double kLo = minimumCurvature(chain, lo, options), kHi = minimumCurvature(chain, hi, options);
  if ((kLo > 0) == (kHi > 0))
    throw std::invalid_argument("min K has the same sign at L = " + std::to_string(lo) + " and " + std::to_string(hi));
  for (int k = 0; k < 60 && hi - lo > tolerance; ++k) {
    const double mid = 0.5 * (lo + hi);
    const double kMid = minimumCurvature(chain, mid, options);
    if ((kMid > 0) == (kHi > 0))
      hi = mid, kHi = kMid;
    else
      lo = mid, kLo = kMid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace sl

#pragma once
// The configuration sphere as a whole: maps of the pointwise quantities of geometry/curvature.hpp,
// the area and the Gauss-Bonnet integral, the extrema of K and of the bending, a summary per chain and a sweep
// over L. Everything is computed through the best-conditioned chart at each point, so nothing here is special
// at chart 0's poles or seams.
//
// Threads: `threads` = 0 means all cores. Work is split by rows (or points) and every value is computed
// independently of the split, so results are bit-identical for any thread count.

#include <vector>

#include <Eigen/Dense>

#include "geometry/curvature.hpp"
#include "linkage/chain.hpp"

namespace sl {

// === Maps

// Chart 0 nodes for maps: phiCount latitudes from -pi/2 to pi/2 inclusive (both poles), tCount longitudes
// -pi + 2 pi j / tCount (periodic, the endpoint pi left out).
struct ChartGrid {
  std::vector<double> phis, ts;
};
ChartGrid uniformChartGrid(int phiCount, int tCount);

// Samples at every (phi, t) of the tensor grid, row-major (phi outer, t inner).
std::vector<CurvatureSample> curvatureGrid(const ConfigurationSurface& surface, const std::vector<double>& phis,
                                           const std::vector<double>& ts, int threads = 0);
// Samples at given chart 0 coordinates (phi, t), in order.
std::vector<CurvatureSample> curvatureSamples(const ConfigurationSurface& surface,
                                              const std::vector<Eigen::Vector2d>& coords, int threads = 0);

// === Integrals

// Gauss-Legendre nodes and weights on [-1, 1], ascending (Boost.Math's Legendre roots; exact for degree 2n - 1).
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

// Area = int dA and total curvature = int K dA over the sphere. In chart 0, dA = rho(x) cos(phi) dphi dt with
// rho = areaDensity smooth on S^2, so the integrand is analytic and periodic in t and analytic in phi up to and
// across the poles: Gauss-Legendre in phi, the trapezoid rule in t, both converging geometrically. Each
// integrand value is computed in the best chart at its point (none at a pole exactly: Gauss nodes are interior).
struct SphereIntegrals {
  double area = 0.0;
  double totalCurvature = 0.0;  // 4 pi by Gauss-Bonnet
  int phiNodes = 0, tNodes = 0;
  // Change from the previous (half-size) rule; the convergence check of integrateOverSphereConverged.
  double areaChange = 0.0, curvatureChange = 0.0;
  bool converged = false;
};
SphereIntegrals integrateOverSphere(const ConfigurationSurface& surface, int phiNodes, int tNodes, int threads = 0);
// Grows phiNodes by half (24, 36, 54, ...; tNodes = 2 phiNodes) until two successive rules agree to `tolerance`,
// relative (area) and relative to 4 pi (curvature), or the next rule would pass maxPhiNodes; the finer result is
// returned. The convergence is geometric: at L = 3 the area is good to 1e-14 with 96 x 192 nodes; near L = 2 the
// metric concentrates and L = 2.2 needs about 250 x 500.
SphereIntegrals integrateOverSphereConverged(const ConfigurationSurface& surface, double tolerance = 1e-12,
                                             int maxPhiNodes = 768, int threads = 0);

// === Extrema

enum class SurfaceQuantity { gaussianCurvature, bending };
double surfaceQuantity(const ConfigurationSurface& surface, SurfaceQuantity quantity, const Eigen::Vector3d& x);

struct SurfaceExtremum {
  double value = 0.0;
  Eigen::Vector3d spherePoint = Eigen::Vector3d::Zero();
  double phi = 0.0, t = 0.0;   // chart 0 coordinates of spherePoint, t in (-pi, pi]
  double positionError = 0.0;  // length of the last Newton step (radians on the round sphere)
  int iterations = 0;
  bool converged = false;  // the last step was below 1e-11 within the iteration cap
};

// Newton's method on the gradient of the quantity, in tangent-plane coordinates centred at the current point
// (u, v) -> normalize(x + u e_u + v e_v), so no chart ever degenerates. The gradient is a Richardson-extrapolated
// central difference of the exact quantity (step 1e-3, error ~1e-12), the Hessian a central difference; steps
// are capped at 0.05 and the iteration count at 60.
SurfaceExtremum refineExtremum(const ConfigurationSurface& surface, SurfaceQuantity quantity, bool maximum,
                               const Eigen::Vector3d& start);

struct CurvatureExtrema {
  SurfaceExtremum curvatureMin, curvatureMax, bendingMax;
};
// Scan a chart 0 grid of (scan + 1) x 2 scan nodes, refine the best few discrete local extrema of each kind
// and keep the best. Mirror images (K(phi, t) = K(-phi, t + pi)) tie: the one with phi >= 0 is reported.
CurvatureExtrema curvatureExtrema(const ConfigurationSurface& surface, int scan = 64, int threads = 0);

// === Summaries

struct SummaryOptions {
  int scan = 64;                       // extremum scan, see curvatureExtrema
  double quadratureTolerance = 1e-12;  // see integrateOverSphereConverged
  int threads = 0;
};

struct CurvatureSummary {
  double baseLength = 0.0;
  SphereIntegrals integrals;  // area, total curvature and their convergence
  double area = 0.0;
  double totalCurvature = 0.0;
  double gaussBonnetError = 0.0;  // totalCurvature - 4 pi
  SurfaceExtremum curvatureMin, curvatureMax, bendingMax;
};
CurvatureSummary curvatureSummary(const Chain& chain, const SummaryOptions& options = {});

// Summaries for `count` values of L evenly spaced from firstL to lastL (inclusive), the chain's masses kept.
std::vector<CurvatureSummary> curvatureSweep(const Chain& chain, double firstL, double lastL, int count,
                                             const SummaryOptions& options = {});

// min over the sphere of K, as a function of L (the chain's masses kept).
double minimumCurvature(const Chain& chain, double baseLength, const SummaryOptions& options = {});
// The L in [lo, hi] where min K changes sign (K > 0 everywhere above it), by bisection to `tolerance` (at most
// 60 halvings). Throws std::invalid_argument if min K has the same sign at both ends.
double positiveCurvatureThreshold(const Chain& chain, double lo, double hi, double tolerance = 1e-9,
                                  const SummaryOptions& options = {});

}  // namespace sl

#pragma once
// The two geodesic vector fields exactly as the spec publishes them, 4 rods, chart (phi, t), unit hinge
// masses and massless rods. Fixed-size and allocation-free: they are the speed baseline.
//   christoffel-fd (section 4): metric4 (kineticMetricPublished) and its partials by central differences,
//                               eps = 1e-5, then the six Christoffel symbols of the 2D cheatsheet.
//   embedded-fd    (section 5): first and second partials of q = Psi(phi, t) in R^6 by central differences,
//                               eps = 1e-4, then the 2x2 normal-acceleration system.
// The fields share work across the stencil (what depends on phi alone is computed for 3 phi values, not
// 5 or 9; sines and cosines of neighbouring stencil angles come from one sincos by angle addition). The
// tests' references (tests/fixtures/published_references.hpp) evaluate every stencil point from scratch, as the
// spec's code does, and finish with the same algebra (below).

#include <array>

#include <Eigen/Dense>

namespace sl {

// The 4-rod chain on base L with its two amplitudes, constant over a run: computed once when a run is bound.
struct PublishedChain {
  explicit PublishedChain(double baseLength);
  double baseLength;
  double amplitude;         // alpha_4(L) = chainAmplitude(4, L) (linkage/chart.hpp), as fourRodHinges
  double printedAmplitude;  // metric4's alpha = acos((L^2 - 8) / 2L), as printed
};

// (phiddot, tddot) from (phi, t) and (phidot, tdot).
Eigen::Vector2d christoffelFdAcceleration(const PublishedChain& chain, const Eigen::Vector2d& coords,
                                          const Eigen::Vector2d& rates);
Eigen::Vector2d embeddedFdAcceleration(const PublishedChain& chain, const Eigen::Vector2d& coords,
                                       const Eigen::Vector2d& rates);

// The spec's difference steps and stencils: index 0 the centre, 1 plus eps, 2 minus eps.
inline constexpr double kChristoffelFdEps = 1e-5;  // section 4
inline constexpr double kEmbeddedFdEps = 1e-4;     // section 5
inline std::array<double, 3> stencilOf(double x, double eps) { return {x, x + eps, x - eps}; }

// Section 4's Christoffel algebra on the metric at the centre and at phi +- eps, t +- eps.
Eigen::Vector2d christoffelFdFromMetrics(const Eigen::Matrix2d& m, const Eigen::Matrix2d& mPh,
                                         const Eigen::Matrix2d& mPl, const Eigen::Matrix2d& mTh,
                                         const Eigen::Matrix2d& mTl, double eps, const Eigen::Vector2d& rates);

// Section 5's normal-acceleration algebra on the 3x3 stencil of q = Psi(phi, t) in R^6, [phi index][t index].
using HingeStencil = std::array<std::array<Eigen::Matrix<double, 6, 1>, 3>, 3>;
Eigen::Vector2d embeddedFdFromHinges(const HingeStencil& q, double eps, const Eigen::Vector2d& rates);

}  // namespace sl

#pragma once
// The two geodesic vector fields exactly as the spec publishes them, 4 rods, chart (phi, t), unit hinge
// masses and massless rods. Fixed-size and allocation-free: they are the speed baseline.
//   christoffel-fd (section 4): metric4 (kineticMetricPublished) and its partials by central differences,
//                               eps = 1e-5, then the six Christoffel symbols of the 2D cheatsheet.
//   embedded-fd    (section 5): first and second partials of q = Psi(phi, t) in R^6 by central differences,
//                               eps = 1e-4, then the 2x2 normal-acceleration system.
// The fields share work across the stencil (what depends on phi alone is computed for 3 phi values, not
// 5 or 9; sines and cosines of neighbouring stencil angles come from one sincos by angle addition). The
// ...StencilByStencil versions evaluate every stencil point from scratch, as the spec's code does: the
// reference the shared versions are tested against (they agree to roundoff) and benchmarked with.

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

// The same, every stencil point evaluated from scratch from L (the spec's code): the reference.

Eigen::Vector2d christoffelFdAccelerationStencilByStencil(double baseLength, const Eigen::Vector2d& coords,
                                                          const Eigen::Vector2d& rates);
Eigen::Vector2d embeddedFdAccelerationStencilByStencil(double baseLength, const Eigen::Vector2d& coords,
                                                       const Eigen::Vector2d& rates);

// Psi^4_L(phi, t) stacked as (p1, p2, p3) in R^6, fixed-size: the recursion of linkage/chart.hpp written
// out for 4 rods (the spec's psi4Position with nu_in in its cancellation-free form).
Eigen::Matrix<double, 6, 1> fourRodHinges(double baseLength, double phi, double t);

}  // namespace sl

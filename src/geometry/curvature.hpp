#pragma once
// Pointwise extrinsic and intrinsic geometry of the configuration sphere of a 4-rod chain.
//
// The stacked hinges q = Psi(x) in R^6 = (R^2)^3 embed the sphere in the ambient space with the mass inner
// product <u, w>_M = u^T M w (spec section 1; M block-tridiagonal, linkage/chain.hpp). The kinetic metric is
// its pullback g_ab = <q_a, q_b>_M (spec section 2). In a chart c = (c0, c1):
//   II_ab = q_ab - q_l g^lm <q_m, q_ab>_M    the M-orthogonal projection of q_ab onto the normal space;
//   K = (<II_00, II_11>_M - <II_01, II_01>_M) / det g     (the Gauss equation);
//   |II|^2 = |A|^2 + 2|B|^2 + |C|^2 with A = II(e1,e1), B = II(e1,e2), C = II(e2,e2), (e1, e2) g-orthonormal;
//   S(v) = |II(v,v)|^2_M for g-unit v (the directional stiffness, geometry/stiffness.hpp).
// q, q_a, q_ab come from one pass of the chart with a second-order jet (geometry/second_order_jet.hpp), exact
// to rounding. Every quantity is a property of the configuration, i.e. of the sphere point x: it is computed
// in the atlas chart best conditioned at x (linkage/sphere_coordinates.hpp), so the spec's chart (phi, t)
// (chart 0) has no special points here: its poles and seams are ordinary.
//
// The stiffness angle. S(a) is measured in the frame built from chart 0's coordinate vector d/dphi:
//   e1 = d/dphi / |d/dphi|_g,   e2 = the g-unit vector g-orthogonal to e1 on the side of d/dt
// ((e1, e2) has the orientation of (d/dphi, d/dt)). stiffnessAngle is the angle a in (-pi/2, pi/2] of the
// maximising direction cos(a) e1 + sin(a) e2 in that frame: 0 means "along d/dphi", pi/2 "g-perpendicular to it,
// towards increasing t". Directions, not vectors: a and a + pi are the same. d/dphi is never 0, poles included;
// at a pole it depends on the t given (the x overload takes t = atan2(x1, x0), 0 exactly at the pole).

#include <Eigen/Dense>

#include "geometry/stiffness.hpp"
#include "linkage/chain.hpp"

namespace sl {

using StackedVector = Eigen::Matrix<double, 6, 1>;  // q = (p1x, p1y, p2x, p2y, p3x, p3y)

// Everything the Gauss equation needs at one point, in one chart. Index pairs (00, 01, 11) are stored as
// columns 0, 1, 2.
struct SecondFundamentalForm {
  int chart = 0;                              // the atlas chart used (sphereChartAxes(3, chart))
  Eigen::Vector2d coords;                     // the point's coordinates in that chart
  Eigen::Vector3d spherePoint;                // x
  Eigen::Matrix<double, 3, 2> sphereTangent;  // x_a = dx/dc_a (orthogonal columns)
  StackedVector hinges;                       // q
  Eigen::Matrix<double, 6, 2> tangent;        // q_a
  Eigen::Matrix<double, 6, 3> second;         // q_ab
  Eigen::Matrix2d metric;                     // g_ab = <q_a, q_b>_M
  Eigen::Matrix<double, 6, 3> normal;         // II_ab
  Eigen::Matrix3d gram;                       // <II_i, II_j>_M over the pairs (00, 01, 11)
};

// II in a g-orthonormal frame (e1, e2): gram(i, j) = <X_i, X_j>_M for (X_0, X_1, X_2) = (A, B, C).
struct OrthonormalFrameForm {
  Eigen::Vector2d e1, e2;  // as rates in the chart of the SecondFundamentalForm
  Eigen::Matrix3d gram;
};

// The pointwise quantities at one configuration.
struct CurvatureSample {
  Eigen::Vector3d spherePoint;  // x
  double phi = 0.0, t = 0.0;    // chart 0 coordinates (as given, or from x with t in (-pi, pi])
  int chart = 0;                // the chart the derivatives were taken in
  double gaussianCurvature = 0.0;
  double bending = 0.0;  // |II|^2
  double stiffnessMax = 0.0, stiffnessMin = 0.0;
  double stiffnessAngle = 0.0;                                   // see the header comment
  Eigen::Vector3d stiffnessDirection = Eigen::Vector3d::Zero();  // that direction, g-unit, as a tangent vector in R^3
  double areaDensity = 0.0;                                      // dA / dOmega: kinetic area per unit round area of S^2
  Eigen::Matrix3d frameGram;  // Gram matrix of (A, B, C) in the frame of stiffnessAngle
};

// The configuration sphere of one chain as a surface in the ambient mass metric. Holds what every point
// shares (M, the atlas); cheap to copy; evaluation is const and thread-safe.
class ConfigurationSurface {
 public:
  // Throws std::invalid_argument unless the chain is valid and has 4 rods (configuration space S^2).
  explicit ConfigurationSurface(const Chain& chain);

  const Chain& chain() const { return chain_; }

  // q, q_a, q_ab and II in a given chart at given coordinates (the chart must be regular there).
  SecondFundamentalForm secondFundamentalForm(int chart, const Eigen::Vector2d& coords) const;
  // The same in the best chart at x (any nonzero multiple of a sphere point).
  SecondFundamentalForm secondFundamentalFormAt(const Eigen::Vector3d& spherePoint) const;

  // The primary API: everything at a sphere point. Chart 0's (phi, t) are reported alongside.
  CurvatureSample curvatureAt(const Eigen::Vector3d& spherePoint) const;
  // Convenience: at chart 0 coordinates; the frame uses d/dphi at exactly this (phi, t), poles included.
  CurvatureSample curvatureAtCoordinates(double phi, double t) const;

  double gaussianCurvature(const Eigen::Vector3d& spherePoint) const;
  double bending(const Eigen::Vector3d& spherePoint) const;

 private:
  CurvatureSample sample(const Eigen::Vector3d& x, double phi, double t, const Eigen::Vector3d& phiDirection) const;

  Chain chain_;
  Eigen::Matrix<double, 6, 6> mass_;
};

// K by the Gauss equation from the second fundamental form.
double gaussianCurvature(const SecondFundamentalForm& form);
// |II|^2 = g^ac g^bd <II_ab, II_cd>_M, frame-free.
double bending(const SecondFundamentalForm& form);
// dA / dOmega = sqrt(det g) / |x_0 x x_1|: kinetic area per unit round area.
double areaDensity(const SecondFundamentalForm& form);

// II in the g-orthonormal frame whose first vector is the tangent direction firstDirection (a vector in R^3
// tangent to the sphere at the form's point, nonzero); e2 follows the orientation of chart 0's (d/dphi, d/dt).
OrthonormalFrameForm orthonormalFrameForm(const SecondFundamentalForm& form, const Eigen::Vector3d& firstDirection);

// Chart 0's coordinate vector d/dphi at (phi, t), as a tangent vector of the sphere in R^3.
Eigen::Vector3d chartZeroPhiDirection(double phi, double t);

// Conveniences for a single evaluation (each builds a ConfigurationSurface).
CurvatureSample curvatureAt(const Chain& chain, const Eigen::Vector3d& spherePoint);
CurvatureSample curvatureAtCoordinates(const Chain& chain, double phi, double t);

// === The intrinsic route, independent of the one above (tests and cross-checks; slow)

// The kinetic metric with its first and second derivatives in a chart, exact (the chart's third-order Taylor
// polynomial, geometry/taylor_jet.hpp, then g = J^T M J expanded to second order).
struct MetricJet {
  Eigen::Matrix2d g;
  Eigen::Matrix2d d0, d1;         // d g / dc0, d g / dc1
  Eigen::Matrix2d d00, d01, d11;  // second derivatives
};
MetricJet kineticMetricJet(const Chain& chain, int chart, const Eigen::Vector2d& coords);

// Brioschi's formula: K from E = g00, F = g01, G = g11 and their derivatives alone (Theorema egregium).
double brioschiCurvature(const MetricJet& metric);

// K by Brioschi's formula in the best chart at x.
double gaussianCurvatureIntrinsic(const Chain& chain, const Eigen::Vector3d& spherePoint);

}  // namespace sl

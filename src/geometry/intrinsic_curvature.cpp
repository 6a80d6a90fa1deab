// The intrinsic route to K (the Gauss route's cross-check): Brioschi's formula from the kinetic metric and its exact
// first and second derivatives. It shares nothing with the Gauss-equation route past the chart itself: the
// derivatives come from the generic third-order Taylor jet (the metric needs q_a, its second derivatives need
// q_abc), not from the second-order jet, and no normal space or projection appears.
#include "geometry/curvature.hpp"

#include <stdexcept>
#include <string>

#include "geometry/taylor_jet.hpp"
#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {

MetricJet kineticMetricJet(const Chain& chain, int chart, const Eigen::Vector2d& coords) {
  if (chain.rods != 4) throw std::invalid_argument("Brioschi's formula is for surfaces: 4 rods");
  if (chart < 0 || chart > 1) throw std::invalid_argument("S^2 has charts 0 and 1, got " + std::to_string(chart));
  using Jet = TaylorJet<3>;
  const std::vector<int> axes = sphereChartAxes(3, chart);
  VectorX<Jet> c(2);
  c(0) = Jet::variable(coords(0), 0);
  c(1) = Jet::variable(coords(1), 1);
  const HingeMatrix<Jet> hinges = hingePositionsInChart<Jet>(chain, axes, c);
  // q_a as second-order polynomials: d_a q with its first and second derivatives.
  Eigen::Matrix<TaylorJet<2>, 6, 2> tangent;
  for (int k = 0; k < 3; ++k)
    for (int xy = 0; xy < 2; ++xy)
      for (int a = 0; a < 2; ++a) tangent(2 * k + xy, a) = partialDerivative(hinges(xy, k), a);
  const Eigen::MatrixXd M = stackedMassMatrix(chain);
  MetricJet out;
  for (int a = 0; a < 2; ++a)
    for (int b = a; b < 2; ++b) {
      // g_ab = sum_rs M_rs q_a,r q_b,s (spec section 2), as a polynomial: its derivatives to second order.
      TaylorJet<2> sum(0.0);
      for (int r = 0; r < 6; ++r)
        for (int s = 0; s < 6; ++s)
          if (M(r, s) != 0.0) sum += M(r, s) * (tangent(r, a) * tangent(s, b));
      out.g(a, b) = out.g(b, a) = sum.partial(0, 0);
      out.d0(a, b) = out.d0(b, a) = sum.partial(1, 0);
      out.d1(a, b) = out.d1(b, a) = sum.partial(0, 1);
      out.d00(a, b) = out.d00(b, a) = sum.partial(2, 0);
      out.d01(a, b) = out.d01(b, a) = sum.partial(1, 1);
      out.d11(a, b) = out.d11(b, a) = sum.partial(0, 2);
    }
  return out;
}

double brioschiCurvature(const MetricJet& m) {
  // u = c0, v = c1; E = g00, F = g01, G = g11.
  const double E = m.g(0, 0), F = m.g(0, 1), G = m.g(1, 1);
  const double Eu = m.d0(0, 0), Ev = m.d1(0, 0), Fu = m.d0(0, 1), Fv = m.d1(0, 1), Gu = m.d0(1, 1), Gv = m.d1(1, 1);
  const double Evv = m.d11(0, 0), Fuv = m.d01(0, 1), Guu = m.d00(1, 1);
  Eigen::Matrix3d first, second;
  first << -0.5 * Evv + Fuv - 0.5 * Guu, 0.5 * Eu, Fu - 0.5 * Ev,  //
      Fv - 0.5 * Gu, E, F,                                         //
      0.5 * Gv, F, G;
  second << 0.0, 0.5 * Ev, 0.5 * Gu,  //
      0.5 * Ev, E, F,                 //
      0.5 * Gu, F, G;
  const double D = E * G - F * F;
  return (first.determinant() - second.determinant()) / (D * D);
}

double gaussianCurvatureIntrinsic(const Chain& chain, const Eigen::Vector3d& spherePoint) {
  const Eigen::VectorXd x = spherePoint.normalized();
  const int chart = bestSphereChart(x);
  const Eigen::VectorXd c = coordinatesInChart(sphereChartAxes(3, chart), x);
  return brioschiCurvature(kineticMetricJet(chain, chart, Eigen::Vector2d(c(0), c(1))));
}

}  // namespace sl

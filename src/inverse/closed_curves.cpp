// Closed curves measured independently of the search for closed geodesics (inverse/periodic.hpp): route 2's
// pieces (a closed curve's length by extrapolated polygons, the fixed sets of the 4-rod chain's symmetries, the
// perimeter of an ellipse) and the 3-rod chain's configuration circle, itself a closed geodesic, with its exact
// length.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include "inverse/geodesic_flow.hpp"
#include "inverse/periodic.hpp"
#include "inverse/richardson.hpp"
#include "linkage/chart.hpp"

namespace sl {

double closedCurveLength(const ConstrainedModel& model, const std::function<Eigen::VectorXd(double)>& curve) {
  Richardson table;
  double previous = NAN;
  for (int level = 0; level < 9; ++level) {
    const int points = 16 << level;
    double length = 0;
    Eigen::VectorXd first = curve(0.0), last = first;
    for (int i = 1; i <= points; ++i) {
      const Eigen::VectorXd q = i == points ? first : curve(2 * std::numbers::pi * i / points);
      length += model.norm(q - last);
      last = q;
    }
    const double estimate = table.add(Eigen::VectorXd::Constant(1, length))(0);
    if (level >= 3 && std::abs(estimate - previous) < 1e-13 * std::max(1.0, estimate)) return estimate;
    previous = estimate;
  }
  return previous;
}

Eigen::VectorXd endSwapFixedPoint(const Chain& chain, double w) {
  // p1 = e^(ia), p2 = p1 + e^(ib) with cos a + cos b = L/2 (p2 on x = L/2), p3 = (L - x1, y1); the oval
  // cos a + cos b = L/2 round (0, 0) is star-shaped: (a, b) = r (cos w, sin w), r by bisection.
  const double half = chain.baseLength / 2;
  auto f = [&](double r) { return std::cos(r * std::cos(w)) + std::cos(r * std::sin(w)) - half; };
  double lo = 0, hi = std::numbers::pi;
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = (lo + hi) / 2;
    (f(mid) > 0 ? lo : hi) = mid;
  }
  const double r = (lo + hi) / 2, a = r * std::cos(w), b = r * std::sin(w);
  Eigen::VectorXd q(6);
  q << std::cos(a), std::sin(a), std::cos(a) + std::cos(b), std::sin(a) + std::sin(b), chain.baseLength - std::cos(a),
      std::sin(a);
  return q;
}

std::vector<Eigen::VectorXd> halfTurnFixedPoints(const Chain& chain) {
  const double length = chain.baseLength, x = length / 4, y = std::sqrt(1 - x * x);
  std::vector<Eigen::VectorXd> out;
  for (double sign : {1.0, -1.0}) {
    Eigen::VectorXd q(6);
    q << x, sign * y, length / 2, 0.0, length - x, -sign * y;
    out.push_back(q);
  }
  return out;
}

double ellipsePerimeter(double a, double b) {
  const double major = std::max(a, b), minor = std::min(a, b);
  return 4 * major * boost::math::ellint_2(std::sqrt(1 - (minor / major) * (minor / major)));
}

namespace {

// The length of the 3-rod chain's configuration circle, w -> Psi(cos w, sin w), as the integral of its speed
// |dq/dw|_M with dq/dw exact (automatic differentiation through Psi), by adaptive Gauss-Kronrod quadrature
// (Boost.Math) to 1e-13. The polygon route (closedCurveLength) converges only as h^2 and lost five digits near
// L = 1, where the speed peaks sharply at the folded shapes; the adaptive rule spends its points there. Its
// own error estimate is pessimistic there (it is not used): what decides is the agreement with route 1.
double circleLength(const Chain& chain, const ConstrainedModel& model) {
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  auto speed = [&](double w) {
    VectorX<Dual> x(2);
    x(0) = Dual(std::cos(w), Eigen::Matrix<double, 1, 1>(-std::sin(w)));
    x(1) = Dual(std::sin(w), Eigen::Matrix<double, 1, 1>(std::cos(w)));
    const HingeMatrix<Dual> hinges = hingePositionsOnSphere<Dual>(chain, x);
    Eigen::Matrix2Xd tangent(2, hinges.cols());
    for (Eigen::Index k = 0; k < hinges.cols(); ++k)
      for (int r = 0; r < 2; ++r) tangent(r, k) = hinges(r, k).derivatives()(0);
    return model.norm(ConstrainedModel::stack(tangent));
  };
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(speed, 0.0, 2 * std::numbers::pi, 20, 1e-13);
}

}  // namespace

ClosedGeodesic circleClosedGeodesic(const Chain& chain) {
  if (chain.rods != 3 || chain.isSlack()) throw std::invalid_argument("the circle needs 3 rods and 1 < L < 3");
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const Eigen::VectorXd q0 = ConstrainedModel::stack(hingePositionsAt(chain, Eigen::Vector2d(1, 0)));
  Eigen::VectorXd v0 = model.tangentBasis(q0).col(0);
  const GeodesicFlow flow(model, 1e-12);
  // Route 1: the first return, then Newton on <q(T) - q0, v(T)> = 0. The return is the first crossing of the
  // plane through q0 normal to v0 made close to q0 (within a quarter of the farthest distance reached): the
  // distance to q0 alone has other local minima along the circle (at L < 2 one at 0.75 of the farthest
  // distance, a third of the way round), which are not returns.
  double period = 0, farthest = 0;
  FlowState s{q0, v0, Eigen::MatrixXd(q0.size(), 0), Eigen::MatrixXd(q0.size(), 0)};
  flow.advance(s, 100.0, [&](double t, const FlowState& st) {
    const double r0 = model.norm(st.q - q0);
    farthest = std::max(farthest, r0);
    period = t;
    return !(r0 < 0.25 * farthest && model.inner(st.q - q0, v0) >= 0);
  });
  for (int iteration = 0; iteration < 20; ++iteration) {
    s = FlowState{q0, v0, Eigen::MatrixXd(q0.size(), 0), Eigen::MatrixXd(q0.size(), 0)};
    flow.advance(s, period);
    const Eigen::VectorXd a = flow.acceleration(s.q, s.v);
    const double g = model.inner(s.q - q0, s.v), slope = model.inner(s.v, s.v) + model.inner(s.q - q0, a);
    period -= g / slope;
    if (std::abs(g) < 1e-15) break;
  }
  ClosedGeodesic out;
  out.length = period;
  out.point = q0;
  out.velocity = v0;
  s = FlowState{q0, v0, Eigen::MatrixXd(q0.size(), 0), Eigen::MatrixXd(q0.size(), 0)};
  flow.advance(s, period);
  out.positionClosure = maxAbs(s.q - q0);
  out.velocityClosure = maxAbs(s.v - v0);
  out.symmetries = {{ChainSymmetry::Mirror, false}};
  out.independentLength = circleLength(chain, model);
  out.independentRoute = "the circle's length, its exact speed integrated (adaptive Gauss-Kronrod)";
  return out;
}

}  // namespace sl

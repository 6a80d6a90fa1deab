#include "geometry/curvature.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/second_order_jet.hpp"
#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {

namespace {

constexpr int kSphereAmbient = 3;  // x in R^3 for 4 rods

const std::vector<int>& chartAxes(int chart) {
  static const std::vector<int> axes[2] = {sphereChartAxes(kSphereAmbient, 0), sphereChartAxes(kSphereAmbient, 1)};
  return axes[chart];
}

// bestSphereChart and coordinatesInChart for S^2, on fixed-size vectors (the grid calls them 65,536 times per
// map); tested equal to them (Curvature.ChartChoiceIsTheAtlasBestChart).
int bestChart(const Eigen::Vector3d& x) {
  int best = 0;
  double bestRegularity = -1.0;
  for (int chart = 0; chart < 2; ++chart) {
    const std::vector<int>& axes = chartAxes(chart);
    const double regularity = x(axes[0]) * x(axes[0]) + x(axes[1]) * x(axes[1]);  // squared: same order
    if (regularity > bestRegularity) best = chart, bestRegularity = regularity;
  }
  return best;
}
Eigen::Vector2d coordinatesIn(int chart, const Eigen::Vector3d& x) {
  const std::vector<int>& axes = chartAxes(chart);
  const double s0 = x(axes[0]), s1 = x(axes[1]), s2 = x(axes[2]);
  return {std::atan2(s2, std::sqrt(s0 * s0 + s1 * s1)), std::atan2(s1, s0)};
}

double determinant3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return a.dot(b.cross(c));
}

}  // namespace

ConfigurationSurface::ConfigurationSurface(const Chain& chain) : chain_(chain) {
  chain_.validate();
  if (chain_.rods != 4)
    throw std::invalid_argument("curvature is computed for 4 rods (configuration space S^2); the chain has " +
                                std::to_string(chain_.rods));
  mass_ = stackedMassMatrix(chain_);
}

SecondFundamentalForm ConfigurationSurface::secondFundamentalForm(int chart, const Eigen::Vector2d& coords) const {
  if (chart < 0 || chart > 1) throw std::invalid_argument("S^2 has charts 0 and 1, got " + std::to_string(chart));
  using Jet = SecondOrderJet;
  VectorX<Jet> c(2);
  c(0) = Jet::variable(coords(0), 0);
  c(1) = Jet::variable(coords(1), 1);
  const VectorX<Jet> x = spherePointInChart<Jet>(chartAxes(chart), c);
  const HingeMatrix<Jet> hinges = hingePositionsOnSphere<Jet>(chain_, x);

  SecondFundamentalForm form;
  form.chart = chart;
  form.coords = coords;
  for (int i = 0; i < 3; ++i) {
    form.spherePoint(i) = x(i).v;
    form.sphereTangent(i, 0) = x(i).g0;
    form.sphereTangent(i, 1) = x(i).g1;
  }
  for (int k = 0; k < 3; ++k)
    for (int xy = 0; xy < 2; ++xy) {
      const Jet& p = hinges(xy, k);
      const int r = 2 * k + xy;
      form.hinges(r) = p.v;
      form.tangent.row(r) << p.g0, p.g1;
      form.second.row(r) << p.h00, p.h01, p.h11;
    }
  // Spec section 2: g = J^T M J. The tangential part of q_ab is q_l g^lm <q_m, q_ab>_M (an M-orthogonal
  // projection, since M, not the identity, is the ambient inner product).
  const Eigen::Matrix<double, 6, 2> massTangent = mass_ * form.tangent;
  form.metric = form.tangent.transpose() * massTangent;
  const Eigen::Matrix2d inverse = form.metric.inverse();
  form.normal = form.second - form.tangent * (inverse * (massTangent.transpose() * form.second));
  form.gram = form.normal.transpose() * mass_ * form.normal;
  return form;
}

SecondFundamentalForm ConfigurationSurface::secondFundamentalFormAt(const Eigen::Vector3d& spherePoint) const {
  const Eigen::Vector3d x = spherePoint.normalized();
  const int chart = bestChart(x);
  return secondFundamentalForm(chart, coordinatesIn(chart, x));
}

double gaussianCurvature(const SecondFundamentalForm& form) {
  return (form.gram(0, 2) - form.gram(1, 1)) / form.metric.determinant();
}

Eigen::Vector3d chartZeroPhiDirection(double phi, double t) {
  // d/dphi of x = (cos phi cos t, cos phi sin t, sin phi).
  return {-std::sin(phi) * std::cos(t), -std::sin(phi) * std::sin(t), std::cos(phi)};
}

OrthonormalFrameForm orthonormalFrameForm(const SecondFundamentalForm& form, const Eigen::Vector3d& firstDirection) {
  const Eigen::Vector3d x0 = form.sphereTangent.col(0), x1 = form.sphereTangent.col(1);
  // Rates of the tangent vector in the form's chart: its columns x_a are orthogonal (nested spherical
  // coordinates), so each rate is a projection.
  const Eigen::Vector2d r1(x0.dot(firstDirection) / x0.squaredNorm(), x1.dot(firstDirection) / x1.squaredNorm());
  const Eigen::Matrix2d& g = form.metric;
  OrthonormalFrameForm out;
  out.e1 = r1 / std::sqrt(r1.dot(g * r1));
  // e2 = R g e1 / sqrt(det g), R the quarter turn [[0, -1], [1, 0]]: g-unit, g-orthogonal to e1, and (e1, e2)
  // positively oriented in this chart's coordinates. Chart 0's (d/dphi, d/dt) has x . (x_phi x x_t) < 0; turn
  // e2 round if this chart's coordinate orientation is the other one.
  const Eigen::Vector2d ge1 = g * out.e1;
  out.e2 = Eigen::Vector2d(-ge1(1), ge1(0)) / std::sqrt(g.determinant());
  if (determinant3(form.spherePoint, x0, x1) > 0.0) out.e2 = -out.e2;
  // (A, B, C) = (II(e1, e1), II(e1, e2), II(e2, e2)) as combinations of (II_00, II_01, II_11).
  const Eigen::Vector2d& a = out.e1;
  const Eigen::Vector2d& b = out.e2;
  Eigen::Matrix3d T;
  T.col(0) << a(0) * a(0), 2.0 * a(0) * a(1), a(1) * a(1);
  T.col(1) << a(0) * b(0), a(0) * b(1) + a(1) * b(0), a(1) * b(1);
  T.col(2) << b(0) * b(0), 2.0 * b(0) * b(1), b(1) * b(1);
  out.gram = T.transpose() * form.gram * T;
  return out;
}

CurvatureSample ConfigurationSurface::sample(const Eigen::Vector3d& x, double phi, double t,
                                             const Eigen::Vector3d& phiDirection) const {
  // x is a unit vector, (phi, t) its chart 0 coordinates and phiDirection chart 0's d/dphi there.
  const int chart = bestChart(x);
  const SecondFundamentalForm form =
      secondFundamentalForm(chart, chart == 0 ? Eigen::Vector2d(phi, t) : coordinatesIn(chart, x));
  const OrthonormalFrameForm frame = orthonormalFrameForm(form, phiDirection);
  CurvatureSample s;
  s.spherePoint = form.spherePoint;
  s.phi = phi;
  s.t = t;
  s.chart = form.chart;
  s.gaussianCurvature = sl::gaussianCurvature(form);
  s.frameGram = frame.gram;
  s.bending = frame.gram(0, 0) + 2.0 * frame.gram(1, 1) + frame.gram(2, 2);
  const StiffnessExtremes stiffness = stiffnessExtremes(frame.gram);
  s.stiffnessMax = stiffness.max;
  s.stiffnessMin = stiffness.min;
  s.stiffnessAngle = stiffness.angleOfMax;
  s.stiffnessDirection =
      form.sphereTangent * (std::cos(s.stiffnessAngle) * frame.e1 + std::sin(s.stiffnessAngle) * frame.e2);
  s.areaDensity = sl::areaDensity(form);
  return s;
}

CurvatureSample ConfigurationSurface::curvatureAt(const Eigen::Vector3d& spherePoint) const {
  const Eigen::Vector3d x = spherePoint.normalized();
  const Eigen::Vector2d c = coordinatesIn(0, x);
  return sample(x, c(0), c(1), chartZeroPhiDirection(c(0), c(1)));
}

CurvatureSample ConfigurationSurface::curvatureAtCoordinates(double phi, double t) const {
  const double cosPhi = std::cos(phi), sinPhi = std::sin(phi), cosT = std::cos(t), sinT = std::sin(t);
  return sample(Eigen::Vector3d(cosPhi * cosT, cosPhi * sinT, sinPhi), phi, t,
                Eigen::Vector3d(-sinPhi * cosT, -sinPhi * sinT, cosPhi));
}

double ConfigurationSurface::gaussianCurvature(const Eigen::Vector3d& spherePoint) const {
  return sl::gaussianCurvature(secondFundamentalFormAt(spherePoint));
}

double ConfigurationSurface::bending(const Eigen::Vector3d& spherePoint) const {
  return sl::bending(secondFundamentalFormAt(spherePoint));
}

double bending(const SecondFundamentalForm& form) {
  const Eigen::Matrix2d h = form.metric.inverse();
  const double w00 = h(0, 0), w01 = h(0, 1), w11 = h(1, 1);
  // Weights of <II_i, II_j>_M over the pairs (00, 01, 11), the mixed pair standing for both 01 and 10.
  Eigen::Matrix3d W;
  W << w00 * w00, 2 * w00 * w01, w01 * w01,                       //
      2 * w00 * w01, 2 * (w00 * w11 + w01 * w01), 2 * w01 * w11,  //
      w01 * w01, 2 * w01 * w11, w11 * w11;
  return (W.array() * form.gram.array()).sum();
}

double areaDensity(const SecondFundamentalForm& form) {
  // dA = sqrt(det g) dc0 dc1 and dOmega = |x_0 x x_1| dc0 dc1.
  return std::sqrt(form.metric.determinant()) / form.sphereTangent.col(0).cross(form.sphereTangent.col(1)).norm();
}

CurvatureSample curvatureAt(const Chain& chain, const Eigen::Vector3d& spherePoint) {
  return ConfigurationSurface(chain).curvatureAt(spherePoint);
}

CurvatureSample curvatureAtCoordinates(const Chain& chain, double phi, double t) {
  return ConfigurationSurface(chain).curvatureAtCoordinates(phi, t);
}

}  // namespace sl

#include "simulation/published_fields.hpp"

#include <cmath>

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/smooth_functions.hpp"

namespace sl {

Eigen::Vector2d christoffelFdAcceleration(double L, const Eigen::Vector2d& coords, const Eigen::Vector2d& rates) {
  // Spec section 4, geodesicVectorField, line by line.
  constexpr double eps = 1e-5;
  const double phi = coords(0), t = coords(1);
  const Eigen::Matrix2d m = kineticMetricPublished(L, phi, t);
  const Eigen::Matrix2d mPh = kineticMetricPublished(L, phi + eps, t);
  const Eigen::Matrix2d mPl = kineticMetricPublished(L, phi - eps, t);
  const Eigen::Matrix2d mTh = kineticMetricPublished(L, phi, t + eps);
  const Eigen::Matrix2d mTl = kineticMetricPublished(L, phi, t - eps);

  const double E = m(0, 0), F = m(0, 1), G = m(1, 1);
  const double Ep = (mPh(0, 0) - mPl(0, 0)) / (2 * eps), Fp = (mPh(0, 1) - mPl(0, 1)) / (2 * eps);
  const double Gp = (mPh(1, 1) - mPl(1, 1)) / (2 * eps), Et = (mTh(0, 0) - mTl(0, 0)) / (2 * eps);
  const double Ft = (mTh(0, 1) - mTl(0, 1)) / (2 * eps), Gt = (mTh(1, 1) - mTl(1, 1)) / (2 * eps);

  const double D = E * G - F * F;
  const double Ei = G / D, Fi = -F / D, Gi = E / D;  // inverse metric (script E, F, G)

  const double gamPpp = 0.5 * (Ei * Ep + Fi * (2 * Fp - Et));
  const double gamTpp = 0.5 * (Fi * Ep + Gi * (2 * Fp - Et));
  const double gamPtt = 0.5 * (Ei * (2 * Ft - Gp) + Fi * Gt);
  const double gamTtt = 0.5 * (Fi * (2 * Ft - Gp) + Gi * Gt);
  const double gamPpt = 0.5 * (Ei * Et + Fi * Gp);
  const double gamTpt = 0.5 * (Fi * Et + Gi * Gp);

  const double pd = rates(0), td = rates(1);
  return {-(pd * pd * gamPpp + 2 * pd * td * gamPpt + td * td * gamPtt),
          -(pd * pd * gamTpp + 2 * pd * td * gamTpt + td * td * gamTtt)};
}

namespace {
Eigen::Vector2d rotate(const Eigen::Vector2d& unit, const Eigen::Vector2d& v) {  // complex product unit * v
  return {unit.x() * v.x() - unit.y() * v.y(), unit.y() * v.x() + unit.x() * v.y()};
}
}  // namespace

Eigen::Matrix<double, 6, 1> fourRodHinges(double L, double phi, double t) {
  // Outer level: p3 = L - e^(i theta), theta = alpha sin phi; d = |p3| as a sum of squares.
  const double alpha = chainAmplitude(4, L);
  const double theta = alpha * std::sin(phi);
  const double halfSine = std::sin(0.5 * theta);
  const Eigen::Vector2d p3(L - std::cos(theta), -std::sin(theta));
  const double d = std::sqrt((L - 1) * (L - 1) + 4 * L * halfSine * halfSine);
  // Inner 3-chain on base d, in its own frame: last hinge P2 = d - e^(i theta_in), theta_in = alpha_in sin t.
  const double alphaIn = chainAmplitude(3, d);
  const double thetaIn = alphaIn * std::sin(t);
  const double halfSineIn = std::sin(0.5 * thetaIn);
  const Eigen::Vector2d innerP2(d - std::cos(thetaIn), -std::sin(thetaIn));
  const double p2Abs = std::sqrt((d - 1) * (d - 1) + 4 * d * halfSineIn * halfSineIn);
  // Elbow offset nu_in = sign(cos t) sqrt(4 - |p2|^2) = alpha_in cos t sqrt(d sinc(..) sinc(..)): the sinc
  // form (chart.hpp), smooth across the seam cos t = 0.
  const double sinT = std::sin(t);
  const double sincProduct = sinc(0.5 * alphaIn * (1 + sinT)) * sinc(0.5 * alphaIn * (1 - sinT));
  const double nuIn = alphaIn * std::cos(t) * std::sqrt(d * sincProduct);
  const Eigen::Vector2d innerP1 = rotate(innerP2 / p2Abs, Eigen::Vector2d(0.5 * p2Abs, 0.5 * nuIn));
  const Eigen::Vector2d u = p3 / d;  // the inner chain's base runs from 0 to p3
  Eigen::Matrix<double, 6, 1> q;
  q << rotate(u, innerP1), rotate(u, innerP2), p3;
  return q;
}

Eigen::Vector2d embeddedFdAcceleration(double L, const Eigen::Vector2d& coords, const Eigen::Vector2d& rates) {
  // Spec section 5, geodesicVectorFieldEmbedded, line by line (3x3 stencil, eps = 1e-4).
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  constexpr double eps = 1e-4;
  const double phi = coords(0), t = coords(1);
  const Vector6d q00 = fourRodHinges(L, phi, t);
  const Vector6d qpp = fourRodHinges(L, phi + eps, t), qpm = fourRodHinges(L, phi - eps, t);
  const Vector6d qtp = fourRodHinges(L, phi, t + eps), qtm = fourRodHinges(L, phi, t - eps);
  const Vector6d qptPP = fourRodHinges(L, phi + eps, t + eps), qptPM = fourRodHinges(L, phi + eps, t - eps);
  const Vector6d qptMP = fourRodHinges(L, phi - eps, t + eps), qptMM = fourRodHinges(L, phi - eps, t - eps);

  const Vector6d qPhi = (qpp - qpm) / (2 * eps);
  const Vector6d qT = (qtp - qtm) / (2 * eps);
  const Vector6d qPhiPhi = (qpp - 2 * q00 + qpm) / (eps * eps);
  const Vector6d qTT = (qtp - 2 * q00 + qtm) / (eps * eps);
  const Vector6d qPhiT = ((qptPP - qptPM) - (qptMP - qptMM)) / (4 * eps * eps);

  const double pd = rates(0), td = rates(1);
  const Vector6d qddVel = qPhiPhi * (pd * pd) + qPhiT * (2 * pd * td) + qTT * (td * td);

  const double gpp = qPhi.dot(qPhi), gpt = qPhi.dot(qT), gtt = qT.dot(qT);
  const double det = gpp * gtt - gpt * gpt;
  const double bP = -qPhi.dot(qddVel), bT = -qT.dot(qddVel);
  return {(gtt * bP - gpt * bT) / det, (gpp * bT - gpt * bP) / det};
}

}  // namespace sl

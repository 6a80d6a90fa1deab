#include "simulation/published_fields.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/published_metric_levels.hpp"
#include "linkage/smooth_functions.hpp"
#include "simulation/stencil_trig.hpp"

namespace sl {

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

Eigen::Vector2d rotate(const Eigen::Vector2d& unit, const Eigen::Vector2d& v) {  // complex product unit * v
  return {unit.x() * v.x() - unit.y() * v.y(), unit.y() * v.x() + unit.x() * v.y()};
}


// ---- christoffel-fd (spec section 4): the Christoffel algebra on the metric stencil -----------------


// ---- embedded-fd (spec section 5): Psi in two levels, and the normal-acceleration algebra -------------

struct FourRodOuter {  // what Psi^4_L depends on through phi alone
  Eigen::Vector2d p3, u;
  double d, alphaIn;
};

// Outer level: p3 = L - e^(i theta), theta = alpha sin phi; d = |p3| as a sum of squares. alpha_in is set
// by the caller (chainAmplitude(3, d), directly or turned from the stencil centre's).
FourRodOuter fourRodOuter(double L, const Turn& theta, double halfSine) {
  FourRodOuter o;
  o.p3 = Eigen::Vector2d(L - theta.c, -theta.s);
  o.d = std::sqrt((L - 1) * (L - 1) + 4 * L * halfSine * halfSine);
  o.u = o.p3 * (1 / o.d);  // the inner chain's base runs from 0 to p3
  return o;
}

// chainAmplitude(3, d) = 2 atan2(y, x) with (x, y) = (sqrt((d-1)(d+3)), sqrt((3-d)(1+d))) (linkage/chart.cpp).
Eigen::Vector2d innerAmplitudeHalfTurn(double d) {
  const double oneMinusCos = std::max((3.0 - d) * (1.0 + d), 0.0), onePlusCos = std::max((d - 1.0) * (d + 3.0), 0.0);
  return {std::sqrt(onePlusCos), std::sqrt(oneMinusCos)};
}

// cos and sin of an angle from those of its half (which the chart needs as well): double-angle formulas.
Turn doubled(const Turn& half) { return {1 - 2 * half.s * half.s, 2 * half.s * half.c}; }

struct FourRodInnerTrig {  // at t: theta_in = alpha_in sin t, A, B = alpha_in (1 +- sin t) / 2
  Turn t, thetaIn;
  double halfSineIn, sincProduct;  // sin(theta_in / 2), sinc(A) sinc(B)
};

// Inner 3-chain on base d, in its own frame: last hinge P2 = d - e^(i theta_in). Elbow offset
// nu_in = sign(cos t) sqrt(4 - |p2|^2) = alpha_in cos t sqrt(d sinc(A) sinc(B)): the sinc form (chart.hpp),
// smooth across the seam cos t = 0. The elbow P1 = (P2 / |P2|) (|P2| + i nu_in) / 2 = (P2 + i P2 nu_in / |P2|) / 2,
// with nu_in / |P2| = alpha_in cos t sqrt(d sinc(A) sinc(B) / |P2|^2), |P2|^2 = (d-1)^2 + 4d sin^2(theta_in/2)
// (a sum of squares). In two steps, so that a stencil can take the square roots of all its points at once.
struct ElbowRadicand {  // d sinc(A) sinc(B) / |P2|^2 = numerator / denominator
  double numerator, denominator;
};
ElbowRadicand elbowRadicand(const FourRodOuter& o, const FourRodInnerTrig& in) {
  const double d = o.d;
  return {d * in.sincProduct, (d - 1) * (d - 1) + 4 * d * in.halfSineIn * in.halfSineIn};
}

Vector6d fourRodInner(const FourRodOuter& o, const FourRodInnerTrig& in, double rootOfRadicand) {
  const Eigen::Vector2d innerP2(o.d - in.thetaIn.c, -in.thetaIn.s);
  const double nuOverP2 = o.alphaIn * in.t.c * rootOfRadicand;
  const Eigen::Vector2d innerP1 = 0.5 * (innerP2 + nuOverP2 * Eigen::Vector2d(-innerP2.y(), innerP2.x()));
  Vector6d q;
  q.segment<2>(0) = rotate(o.u, innerP1);
  q.segment<2>(2) = rotate(o.u, innerP2);
  q.segment<2>(4) = o.p3;
  return q;
}


}  // namespace

Eigen::Vector2d christoffelFdFromMetrics(const Eigen::Matrix2d& m, const Eigen::Matrix2d& mPh,
                                         const Eigen::Matrix2d& mPl, const Eigen::Matrix2d& mTh,
                                         const Eigen::Matrix2d& mTl, double eps, const Eigen::Vector2d& rates) {
  // Divisions by a common denominator as one reciprocal and products (within an ulp of the quotients).
  const double inv2eps = 1 / (2 * eps);
  const double E = m(0, 0), F = m(0, 1), G = m(1, 1);
  const double Ep = (mPh(0, 0) - mPl(0, 0)) * inv2eps, Fp = (mPh(0, 1) - mPl(0, 1)) * inv2eps;
  const double Gp = (mPh(1, 1) - mPl(1, 1)) * inv2eps, Et = (mTh(0, 0) - mTl(0, 0)) * inv2eps;
  const double Ft = (mTh(0, 1) - mTl(0, 1)) * inv2eps, Gt = (mTh(1, 1) - mTl(1, 1)) * inv2eps;

  const double invD = 1 / (E * G - F * F);
  const double Ei = G * invD, Fi = -F * invD, Gi = E * invD;  // inverse metric (script E, F, G)

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

Eigen::Vector2d embeddedFdFromHinges(const HingeStencil& q, double eps, const Eigen::Vector2d& rates) {
  const Vector6d& q00 = q[0][0];
  const Vector6d &qpp = q[1][0], &qpm = q[2][0], &qtp = q[0][1], &qtm = q[0][2];
  const Vector6d &qptPP = q[1][1], &qptPM = q[1][2], &qptMP = q[2][1], &qptMM = q[2][2];

  const double inv2eps = 1 / (2 * eps), invEps2 = 1 / (eps * eps), inv4eps2 = 1 / (4 * eps * eps);  // as above
  const Vector6d qPhi = (qpp - qpm) * inv2eps;
  const Vector6d qT = (qtp - qtm) * inv2eps;
  const Vector6d qPhiPhi = (qpp - 2 * q00 + qpm) * invEps2;
  const Vector6d qTT = (qtp - 2 * q00 + qtm) * invEps2;
  const Vector6d qPhiT = ((qptPP - qptPM) - (qptMP - qptMM)) * inv4eps2;

  const double pd = rates(0), td = rates(1);
  const Vector6d qddVel = qPhiPhi * (pd * pd) + qPhiT * (2 * pd * td) + qTT * (td * td);

  const double gpp = qPhi.dot(qPhi), gpt = qPhi.dot(qT), gtt = qT.dot(qT);
  const double invDet = 1 / (gpp * gtt - gpt * gpt);
  const double bP = -qPhi.dot(qddVel), bT = -qT.dot(qddVel);
  return {(gtt * bP - gpt * bT) * invDet, (gpp * bT - gpt * bP) * invDet};
}

// ---- christoffel-fd ---------------------------------------------------------------------------------

PublishedChain::PublishedChain(double L)
    : baseLength(L), amplitude(chainAmplitude(4, L)), printedAmplitude(std::acos((L * L - 8) / (2 * L))) {}

Eigen::Vector2d christoffelFdAcceleration(const PublishedChain& chain, const Eigen::Vector2d& coords,
                                          const Eigen::Vector2d& rates) {
  // Spec section 4: metric4 at (phi, t), (phi +- eps, t), (phi, t +- eps). Its outer level (phi only) is
  // computed for the 3 phi values, cos/sin of t for the 3 t values, the inner level at the 5 points.
  constexpr double eps = kChristoffelFdEps;
  const std::array<double, 3> phis = stencilOf(coords(0), eps), ts = stencilOf(coords(1), eps);
  const double L = chain.baseLength;
  const double alpha = chain.printedAmplitude;

  const Turn phiCentre = turnOf(phis[0]);
  const double thetaCentre = alpha * phiCentre.s;
  const Turn thetaCentreTurn = turnOf(thetaCentre);
  std::array<PublishedOuterLevel, 3> outer;
  std::array<Eigen::Vector2d, 3> towardP3;  // e^(i R) = p3 / |p3|, R = arg(L - e^(i theta))
  for (int k = 0; k < 3; ++k) {
    const Turn phi = k == 0 ? phiCentre : turnAt(phis[k], phiCentre, phis[0]);
    const Turn theta = k == 0 ? thetaCentreTurn : turnAt(alpha * phi.s, thetaCentreTurn, thetaCentre);
    outer[k] = publishedOuterLevelExceptAlphaIn(L, alpha, phi.c, theta.c, theta.s);
    towardP3[k] = Eigen::Vector2d(L - theta.c, -theta.s) * (1 / outer[k].d);
  }
  // alpha_in = acos(cos_ai) at the centre, at phi +- eps turned from it by (cos_ai, sin_ai).
  outer[0].alpha_in = std::acos(outer[0].cos_ai);
  for (int k = 1; k < 3; ++k)
    outer[k].alpha_in = angleAt(outer[k].sin_ai, outer[k].cos_ai, outer[0].sin_ai, outer[0].cos_ai, outer[0].alpha_in);

  const Turn tCentre = turnOf(ts[0]);
  const std::array<Turn, 3> t = {tCentre, turnAt(ts[1], tCentre, ts[0]), turnAt(ts[2], tCentre, ts[0])};
  const double thetaInCentre = outer[0].alpha_in * t[0].s;
  const Turn thetaInCentreTurn = turnOf(thetaInCentre);
  auto metricAt = [&](int k, int j) {  // u3 = e^(i (R + theta_in)) = e^(i R) e^(i theta_in)
    const Turn thetaIn =
        k == 0 && j == 0 ? thetaInCentreTurn : turnAt(outer[k].alpha_in * t[j].s, thetaInCentreTurn, thetaInCentre);
    return publishedInnerLevel(outer[k], t[j].c, t[j].s, rotate(towardP3[k], Eigen::Vector2d(thetaIn.c, thetaIn.s)));
  };
  return christoffelFdFromMetrics(metricAt(0, 0), metricAt(1, 0), metricAt(2, 0), metricAt(0, 1), metricAt(0, 2), eps,
                                  rates);
}


// ---- embedded-fd ------------------------------------------------------------------------------------


Eigen::Vector2d embeddedFdAcceleration(const PublishedChain& chain, const Eigen::Vector2d& coords,
                                       const Eigen::Vector2d& rates) {
  // Spec section 5 on its 3x3 stencil: Psi's outer level for the 3 phi values, cos/sin t for the 3 t values,
  // every other angle turned from its value at the centre (cos/sin of theta and theta_in from their halves).
  constexpr double eps = kEmbeddedFdEps;
  const std::array<double, 3> phis = stencilOf(coords(0), eps), ts = stencilOf(coords(1), eps);
  const double L = chain.baseLength;
  const double alpha = chain.amplitude;

  const Turn phiCentre = turnOf(phis[0]);
  const double halfThetaCentre = 0.5 * (alpha * phiCentre.s);
  const Turn halfThetaCentreTurn = turnOf(halfThetaCentre);
  std::array<FourRodOuter, 3> outer;
  std::array<Eigen::Vector2d, 3> amplitudeHalfTurn;
  for (int k = 0; k < 3; ++k) {
    const double theta = alpha * turnAt(phis[k], phiCentre, phis[0]).s;
    const Turn halfTheta = turnAt(0.5 * theta, halfThetaCentreTurn, halfThetaCentre);
    outer[k] = fourRodOuter(L, doubled(halfTheta), halfTheta.s);
    amplitudeHalfTurn[k] = innerAmplitudeHalfTurn(outer[k].d);
  }
  const Eigen::Vector2d& a0 = amplitudeHalfTurn[0];
  const double halfAlphaIn0 = std::atan2(a0.y(), a0.x());
  for (int k = 0; k < 3; ++k)
    outer[k].alphaIn = 2 * angleAt(amplitudeHalfTurn[k].y(), amplitudeHalfTurn[k].x(), a0.y(), a0.x(), halfAlphaIn0);

  const Turn tCentre = turnOf(ts[0]);
  const std::array<Turn, 3> t = {tCentre, turnAt(ts[1], tCentre, ts[0]), turnAt(ts[2], tCentre, ts[0])};
  // theta_in / 2 = beta sin t with beta = alpha_in / 2, turned from the centre's; A, B = beta (1 +- sin t)
  // = beta +- theta_in / 2, so sin A, sin B = sin beta cos(theta_in/2) +- cos beta sin(theta_in/2), with
  // (cos beta, sin beta) = (x, y) / |(x, y)| from chainAmplitude's (x, y) (no sincos). Where that sum cancels
  // (|A| or |B| small, the seam), sincFromSine takes the series instead.
  const double halfThetaIn0 = 0.5 * (outer[0].alphaIn * t[0].s);
  const Turn halfThetaIn0Turn = turnOf(halfThetaIn0);
  std::array<FourRodInnerTrig, 9> inner;  // point (k, j) at 3k + j
  Eigen::Array<double, 9, 1> numerators, denominators;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector2d beta = amplitudeHalfTurn[k] * (1 / amplitudeHalfTurn[k].norm());
    const double alphaIn = outer[k].alphaIn;
    for (int j = 0; j < 3; ++j) {
      const double sinT = t[j].s;
      const Turn halfThetaIn = turnAt(0.5 * (alphaIn * sinT), halfThetaIn0Turn, halfThetaIn0);
      const double sinA = beta.y() * halfThetaIn.c + beta.x() * halfThetaIn.s;
      const double sinB = beta.y() * halfThetaIn.c - beta.x() * halfThetaIn.s;
      const double A = 0.5 * alphaIn * (1 + sinT), B = 0.5 * alphaIn * (1 - sinT);
      inner[3 * k + j] = {t[j], doubled(halfThetaIn), halfThetaIn.s, sincProductFromSines(A, sinA, B, sinB)};
      const ElbowRadicand radicand = elbowRadicand(outer[k], inner[3 * k + j]);
      numerators(3 * k + j) = radicand.numerator;
      denominators(3 * k + j) = radicand.denominator;
    }
  }
  // The 9 divisions and square roots as packed operations: the divider is this field's bottleneck.
  const Eigen::Array<double, 9, 1> roots = (numerators / denominators).sqrt();
  HingeStencil q;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) q[k][j] = fourRodInner(outer[k], inner[3 * k + j], roots(3 * k + j));
  return embeddedFdFromHinges(q, eps, rates);
}


}  // namespace sl

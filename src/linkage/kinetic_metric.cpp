#include "linkage/kinetic_metric.hpp"

#include <cmath>

#include "linkage/chart.hpp"
#include "linkage/published_metric_levels.hpp"
#include "linkage/smooth_functions.hpp"

namespace sl {

namespace {

// d/dx sinc(x) = -x * (sin x - x cos x) / x^3, with the bracket by series near 0.
double sincDerivative(double x) {
  if (std::abs(x) < 0.5) {
    const double x2 = x * x;
    // (sin x - x cos x)/x^3 = sum_k (-1)^k (2k+2) x^(2k) / (2k+3)!
    const double g =
        1.0 / 3 +
        x2 * (-1.0 / 30 +
              x2 * (1.0 / 840 +
                    x2 * (-1.0 / 45360 + x2 * (1.0 / 3991680 + x2 * (-1.0 / 518918400 + x2 * (1.0 / 93405312000.0))))));
    return -x * g;
  }
  return (x * std::cos(x) - std::sin(x)) / (x * x);
}

struct Complex2 {
  double re, im;
};
double imagOfQuotient(Complex2 v, Complex2 p) {  // Im(v / p)
  return (p.re * v.im - p.im * v.re) / (p.re * p.re + p.im * p.im);
}

}  // namespace

Eigen::Matrix2d kineticMetricClosedForm(double L, double phi, double t) {
  // Outer level (spec section 3, "named scalar partials").
  const double alpha = chainAmplitude(4, L);
  const double theta = alpha * std::sin(phi);
  const double cTheta = std::cos(theta), sTheta = std::sin(theta);
  const double halfSine = std::sin(0.5 * theta);
  const double d = std::sqrt((L - 1) * (L - 1) + 4 * L * halfSine * halfSine);  // |L - e^(i theta)|, no cancellation
  const double R = std::atan2(-sTheta, L - cTheta);
  const double dThetaP = alpha * std::cos(phi);
  // 9 - d^2 = 2L(cos theta - cos alpha) = 4L sin((alpha+theta)/2) sin((alpha-theta)/2), with
  // alpha -+ theta = alpha (1 -+ sin phi) = alpha cos^2 phi / (1 +- sin phi): accurate near the poles.
  const double sPhi = std::sin(phi), cPhi2 = std::cos(phi) * std::cos(phi);
  const double alphaMinusTheta = sPhi >= 0 ? alpha * cPhi2 / (1 + sPhi) : alpha * (1 - sPhi);
  const double alphaPlusTheta = sPhi >= 0 ? alpha * (1 + sPhi) : alpha * cPhi2 / (1 - sPhi);
  const double nineMinusD2 = 4 * L * std::sin(0.5 * alphaPlusTheta) * std::sin(0.5 * alphaMinusTheta);
  const double dDP = (L * sTheta / d) * dThetaP;
  const double dRP = ((1 - L * cTheta) / (d * d)) * dThetaP;

  // Inner level.
  const double threeMinusD = nineMinusD2 / (3 + d);
  const double alphaIn = 2 * std::atan2(std::sqrt(threeMinusD * (1 + d)), std::sqrt((d - 1) * (d + 3)));
  const double sinAlphaIn = std::sqrt((d * d - 1) * nineMinusD2) / (2 * d);
  const double dAlphaInD = -(d * d + 3) / (2 * d * d * sinAlphaIn);
  const double ct = std::cos(t), st = std::sin(t);
  const double thetaIn = alphaIn * st;
  const double dThetaInT = alphaIn * ct;
  const double dThetaInP = dAlphaInD * st * dDP;

  // nu_in = cos t * alpha_in * sqrt(d * F), F = sinc(A) sinc(B), A, B = alpha_in (1 +- sin t)/2,
  // with 1 -+ sin t = cos^2 t / (1 +- sin t) taken on the side that does not cancel.
  const double onePlus = st >= 0 ? 1 + st : ct * ct / (1 - st);
  const double oneMinus = st >= 0 ? ct * ct / (1 + st) : 1 - st;
  const double A = 0.5 * alphaIn * onePlus, B = 0.5 * alphaIn * oneMinus;
  const double sA = sinc(A), sB = sinc(B), dsA = sincDerivative(A), dsB = sincDerivative(B);
  const double F = sA * sB;
  const double rootDF = std::sqrt(d * F);
  const double nuIn = ct * alphaIn * rootDF;
  // d/dt: dA/dt = alpha_in cos t / 2 = -dB/dt.
  const double dFT = 0.5 * dThetaInT * (dsA * sB - sA * dsB);
  const double dNuT = alphaIn * (-st * rootDF + ct * d * dFT / (2 * rootDF));
  // d/dd through alpha_in(d) and the explicit d.
  const double dFD = 0.5 * dAlphaInD * (dsA * onePlus * sB + sA * dsB * oneMinus);
  const double dNuD = ct * (dAlphaInD * rootDF + alphaIn * (F + d * dFD) / (2 * rootDF));
  const double dNuP = dNuD * dDP;

  // Hinges and rod directions.
  const Complex2 u4{cTheta, sTheta};
  const Complex2 u3{std::cos(R + thetaIn), std::sin(R + thetaIn)};
  const Complex2 p2{L - cTheta - u3.re, -sTheta - u3.im};
  const double p2Abs = std::hypot(p2.re, p2.im);
  (void)nuIn;

  // Hinge velocities of p2; -i * u * s = (u.im * s, -u.re * s).
  const Complex2 dTP2{u3.im * dThetaInT, -u3.re * dThetaInT};
  const double c1 = dThetaP, c2 = dRP + dThetaInP;
  const Complex2 dPP2{u4.im * c1 + u3.im * c2, -(u4.re * c1 + u3.re * c2)};

  // Omega_a = Im(d_a p2 / p2) - d_a|p2| / nu_in = Im(d_a p2 / p2) + d_a nu_in / |p2|.
  const double omegaT = imagOfQuotient(dTP2, p2) + dNuT / p2Abs;
  const double omegaP = imagOfQuotient(dPP2, p2) + dNuP / p2Abs;

  const double u34 = u3.re * u4.re + u3.im * u4.im;
  Eigen::Matrix2d h;
  h(1, 1) = omegaT * omegaT + dThetaInT * dThetaInT;
  h(0, 0) = omegaP * omegaP + 2 * dThetaP * dThetaP + c2 * c2 + 2 * dThetaP * c2 * u34;
  h(0, 1) = h(1, 0) = omegaT * omegaP + dThetaInT * (dThetaP * u34 + c2);
  return h;
}

Eigen::Matrix2d kineticMetricPublished(double L, double phi, double t) {
  // A line-by-line transcription of the spec's metric4 (JavaScript), kept for the published methods.
  const double alpha = std::acos((L * L - 8) / (2 * L));
  const double cphi = std::cos(phi), sphi = std::sin(phi);
  const double theta = alpha * sphi;
  const double ctheta = std::cos(theta), stheta = std::sin(theta);
  const PublishedOuterLevel outer = publishedOuterLevel(L, alpha, cphi, ctheta, stheta);
  const double R = std::atan2(-stheta, L - ctheta);
  const double ct = std::cos(t), st = std::sin(t);
  const double theta_in = outer.alpha_in * st;
  const double u3_arg = R + theta_in;
  return publishedInnerLevel(outer, ct, st, Eigen::Vector2d(std::cos(u3_arg), std::sin(u3_arg)));
}

Eigen::MatrixXd stackedMassMatrix(const Chain& chain) {
  const AmbientMassMatrix mass = ambientMassMatrix(chain);
  const Eigen::Index size = 2 * chain.hingeCount();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(size, size);
  for (Eigen::Index j = 0; j < mass.diagonal.size(); ++j)
    M.block<2, 2>(2 * j, 2 * j).diagonal().setConstant(mass.diagonal(j));
  for (Eigen::Index j = 0; j < mass.coupling.size(); ++j) {
    M.block<2, 2>(2 * j, 2 * j + 2).diagonal().setConstant(mass.coupling(j));
    M.block<2, 2>(2 * j + 2, 2 * j).diagonal().setConstant(mass.coupling(j));
  }
  return M;
}

Eigen::MatrixXd kineticMetricPullback(const Chain& chain, const std::vector<int>& axes, const Eigen::VectorXd& coords) {
  const Eigen::MatrixXd J = chartJacobian(chain, axes, coords);
  return J.transpose() * stackedMassMatrix(chain) * J;
}

Eigen::MatrixXd kineticMetricCentralDifferences(const Chain& chain, const std::vector<int>& axes,
                                                const Eigen::VectorXd& coords, double eps) {
  const Eigen::Index k = coords.size();
  Eigen::MatrixXd J(2 * chain.hingeCount(), k);
  for (Eigen::Index a = 0; a < k; ++a) {
    const Eigen::VectorXd step = eps * Eigen::VectorXd::Unit(k, a);
    const Eigen::Matrix2Xd plus = hingePositionsInChart<double>(chain, axes, coords + step);
    const Eigen::Matrix2Xd minus = hingePositionsInChart<double>(chain, axes, coords - step);
    J.col(a) = Eigen::Map<const Eigen::VectorXd>((plus - minus).eval().data(), J.rows()) / (2 * eps);
  }
  return J.transpose() * stackedMassMatrix(chain) * J;
}

}  // namespace sl

#include "geometry/stiffness.hpp"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// The root mu >= 0 of F(mu) = near^2/mu^2 + far^2/(mu + gap)^2 = 1 (gap >= 0), or 0 in the "hard case"
// near = 0, |far| <= gap where no positive root exists. F(lo) >= 1 at lo = max(|near|, |far| - gap) and
// F(hi) <= 1 at hi = |(near, far)|. Newton's method runs on psi = F^(-1/2) - 1, which is increasing and close
// to linear (More and Sorensen's secular function; exactly linear when far = 0), so from lo it converges in a
// few steps; a step leaving the bracket [lo, hi] (kept with F(lo) >= 1 >= F(hi)) is replaced by bisection.
// It stops when F = 1 to rounding (a few units in the last place), when a Newton step would change mu by less
// than that, or when the bracket has shrunk to that width (rounding can make F - 1 alternate in sign between
// neighbouring doubles). Typically 2-6 steps; at most 12 for both roots together in 2 x 10^5 random cases
// (Stiffness.SecularIterationsStayFewOnRandomGramMatrices); capped at 100 by the caller.
struct SecularRoot {
  double near, far, gap, lo, hi, mu;
  bool done;

  SecularRoot(double n, double f, double g)
      : near(n), far(f), gap(g), lo(std::max(std::abs(n), std::abs(f) - g)), hi(std::sqrt(n * n + f * f)), mu(lo) {
    done = !(lo > 0.0);
    if (done) mu = 0.0;
  }
  void step() {
    constexpr double kRounding = 1e-15;
    const double r1 = 1.0 / mu, r2 = 1.0 / (mu + gap);
    const double a = near * r1, b = far * r2;
    const double F = a * a + b * b;
    if (std::abs(F - 1.0) <= kRounding) {
      done = true;
      return;
    }
    (F > 1.0 ? lo : hi) = mu;
    if (hi - lo <= kRounding * hi) {
      done = true;
      return;
    }
    const double slope = -2.0 * (a * a * r1 + b * b * r2);         // F'
    const double newton = 2.0 * F * (1.0 - std::sqrt(F)) / slope;  // -psi / psi' = 2 F (1 - sqrt F) / F'
    const bool inside = mu + newton > lo && mu + newton < hi;
    if (inside && std::abs(newton) <= kRounding * mu) done = true;
    mu = inside ? mu + newton : 0.5 * (lo + hi);
  }
};

}  // namespace

double directionalStiffness(const Eigen::Matrix3d& gram, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const Eigen::Vector3d coefficients(c * c, 2.0 * s * c, s * s);  // II(v, v) = c^2 A + 2sc B + s^2 C
  return std::max(coefficients.dot(gram * coefficients), 0.0);
}

StiffnessExtremes stiffnessExtremes(const Eigen::Matrix3d& gram) {
  const double AA = gram(0, 0), AB = gram(0, 1), AC = gram(0, 2), BB = gram(1, 1), BC = gram(1, 2), CC = gram(2, 2);
  // Gram data of P = (A + C)/2, Q = (A - C)/2, R = B.
  const double PP = 0.25 * (AA + 2.0 * AC + CC), QQ = 0.25 * (AA - 2.0 * AC + CC), RR = BB;
  const double PQ = 0.25 * (AA - CC), PR = 0.5 * (AB + BC), QR = 0.5 * (AB - BC);
  // G = [[QQ, QR], [QR, RR]] = g1 u1 u1^T + g2 u2 u2^T with g1 - g2 = gap >= 0.
  // u1 = (cos psi, sin psi) with (cos 2psi, sin 2psi) = (QQ - RR, 2 QR) / gap, by half-angle formulas taken on
  // the side that does not cancel.
  const double gap = std::sqrt((QQ - RR) * (QQ - RR) + 4.0 * QR * QR);
  Eigen::Vector2d u1(1.0, 0.0);
  if (gap > 0.0) {
    const double c2 = (QQ - RR) / gap, s2 = 2.0 * QR / gap;
    if (c2 >= 0.0) {
      u1(0) = std::sqrt(0.5 * (1.0 + c2));
      u1(1) = s2 / (2.0 * u1(0));
    } else {
      u1(1) = std::copysign(std::sqrt(0.5 * (1.0 - c2)), s2);
      u1(0) = s2 / (2.0 * u1(1));
    }
  }
  const Eigen::Vector2d u2(-u1(1), u1(0));
  const Eigen::Vector2d b(PQ, PR);
  const double b1 = b.dot(u1), b2 = b.dot(u2);
  const Eigen::Matrix2d G{{QQ, QR}, {QR, RR}};
  const auto value = [&](const Eigen::Vector2d& w) { return std::max(PP + 2.0 * b.dot(w) + w.dot(G * w), 0.0); };

  StiffnessExtremes out;
  // Maximum: lambda = g1 + mu; minimum: lambda = g2 - nu. The two iterations are independent and run side by
  // side, which lets the processor overlap their divisions.
  SecularRoot maximum(b1, b2, gap), minimum(b2, b1, gap);
  for (int k = 0; k < 100 && !(maximum.done && minimum.done); ++k) {
    if (!maximum.done) maximum.step(), ++out.iterations;
    if (!minimum.done) minimum.step(), ++out.iterations;
  }
  // w = b1/mu u1 + b2/(mu + gap) u2 at the maximum.
  Eigen::Vector2d wMax;
  {
    const double mu = maximum.mu;
    double w2 = b2 / (mu + gap);
    if (!std::isfinite(w2)) w2 = 0.0;  // gap = 0 and mu = 0: b = 0 and S is constant
    w2 = std::clamp(w2, -1.0, 1.0);
    const double w1 = mu > 0.0 ? b1 / mu : std::sqrt(1.0 - w2 * w2);
    wMax = (w1 * u1 + w2 * u2).normalized();
  }
  // w = -b1/(nu + gap) u1 - b2/nu u2 at the minimum.
  Eigen::Vector2d wMin;
  {
    const double nu = minimum.mu;
    double w1 = -b1 / (nu + gap);
    if (!std::isfinite(w1)) w1 = 0.0;
    w1 = std::clamp(w1, -1.0, 1.0);
    const double w2 = nu > 0.0 ? -b2 / nu : std::sqrt(1.0 - w1 * w1);
    wMin = (w1 * u1 + w2 * u2).normalized();
  }
  out.max = value(wMax);
  out.min = std::min(value(wMin), out.max);
  // w = (cos 2a, sin 2a); atan2 lies in (-pi, pi], so a lies in (-pi/2, pi/2].
  out.angleOfMax = 0.5 * std::atan2(wMax.y(), wMax.x());
  out.angleOfMin = 0.5 * std::atan2(wMin.y(), wMin.x());
  return out;
}

}  // namespace sl

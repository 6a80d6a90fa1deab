#pragma once
// metric4 (spec section 3) split at its two levels, so that a stencil can share what depends on phi alone
// (the published christoffel-fd, simulation/published_fields.cpp) while the formula is written once. The
// caller supplies the trigonometric values; kineticMetricPublished (kinetic_metric.hpp) takes them straight
// from std::cos / std::sin / atan2. Inline: the stencil calls them 8 times per evaluation.

#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace sl {

struct PublishedOuterLevel {  // everything of metric4 that depends on phi only
  double L, ctheta, stheta, d, dthetaP, ddP, dRP, cos_ai, sin_ai, alpha_in, dalphainP;
};

// alpha = acos((L^2 - 8) / 2L); cos, sin of theta = alpha sin phi. Everything but alpha_in = acos(cos_ai),
// which a stencil may obtain from a neighbour's (cos_ai, sin_ai, alpha_in) instead.
inline PublishedOuterLevel publishedOuterLevelExceptAlphaIn(double L, double alpha, double cphi, double ctheta,
                                                            double stheta) {
  PublishedOuterLevel o{};
  o.L = L;
  o.ctheta = ctheta;
  o.stheta = stheta;
  const double d = std::sqrt(L * L - 2 * L * ctheta + 1);
  o.d = d;
  o.dthetaP = alpha * cphi;
  o.ddP = (L * stheta / d) * o.dthetaP;
  o.dRP = ((1 - L * ctheta) / (d * d)) * o.dthetaP;
  o.cos_ai = (d * d - 3) / (2 * d);
  o.sin_ai = std::sqrt((d * d - 1) * (9 - d * d)) / (2 * d);
  o.dalphainP = -((d * d + 3) / (2 * d * d * o.sin_ai)) * o.ddP;
  o.alpha_in = std::numeric_limits<double>::quiet_NaN();
  return o;
}

inline PublishedOuterLevel publishedOuterLevel(double L, double alpha, double cphi, double ctheta, double stheta) {
  PublishedOuterLevel o = publishedOuterLevelExceptAlphaIn(L, alpha, cphi, ctheta, stheta);
  o.alpha_in = std::acos(o.cos_ai);
  return o;
}

// The rest of metric4 at (phi, t): cos, sin of t and u3 = e^(i (R + alpha_in sin t)).
inline Eigen::Matrix2d publishedInnerLevel(const PublishedOuterLevel& o, double ct, double st,
                                           const Eigen::Vector2d& u3v) {
  const double L = o.L, ctheta = o.ctheta, stheta = o.stheta, d = o.d;
  const double dthetaP = o.dthetaP, dRP = o.dRP, alpha_in = o.alpha_in, sin_ai = o.sin_ai;
  const double dthetainT = alpha_in * ct;
  const double dthetainP = o.dalphainP * st;

  const double p3[2] = {L - ctheta, -stheta};
  const double u4[2] = {ctheta, stheta};
  const double u3[2] = {u3v.x(), u3v.y()};
  const double p2[2] = {p3[0] - u3[0], p3[1] - u3[1]};
  const double p2_abs = std::hypot(p2[0], p2[1]);
  const double nu_in =
      std::abs(ct) < 1e-6 ? ct * std::sqrt(d * alpha_in * sin_ai) : ct * std::sqrt((4 - p2_abs * p2_abs) / (ct * ct));

  const double dt_p2[2] = {u3[1] * dthetainT, -u3[0] * dthetainT};
  const double c1 = dthetaP, c2 = dRP + dthetainP;
  const double dphi_p2[2] = {u4[1] * c1 + u3[1] * c2, -(u4[0] * c1 + u3[0] * c2)};
  // Omega_a = Im(d_a p2 / p2) - Re(d_a p2 conj(p2)) / (|p2| nu_in) for a = t, phi: each pair of quotients
  // divided at once (packed IEEE division rounds exactly as two scalar ones, in half the divider time).
  const Eigen::Array2d im =
      Eigen::Array2d(p2[0] * dt_p2[1] - p2[1] * dt_p2[0], p2[0] * dphi_p2[1] - p2[1] * dphi_p2[0]) / (p2_abs * p2_abs);
  const Eigen::Array2d re =
      Eigen::Array2d(p2[0] * dt_p2[0] + p2[1] * dt_p2[1], p2[0] * dphi_p2[0] + p2[1] * dphi_p2[1]) / (p2_abs * nu_in);
  const double Omega_t = im(0) - re(0), Omega_phi = im(1) - re(1);
  const double u34_dot = u3[0] * u4[0] + u3[1] * u4[1];

  Eigen::Matrix2d h;
  h(1, 1) = Omega_t * Omega_t + dthetainT * dthetainT;
  h(0, 0) = Omega_phi * Omega_phi + 2 * dthetaP * dthetaP + (dRP + dthetainP) * (dRP + dthetainP) +
            2 * dthetaP * (dRP + dthetainP) * u34_dot;
  h(0, 1) = h(1, 0) = Omega_t * Omega_phi + dthetainT * (dthetaP * u34_dot + dRP + dthetainP);
  return h;
}

}  // namespace sl

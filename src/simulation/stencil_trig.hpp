#pragma once
// Sines, cosines, sinc and atan2 at the points of a finite-difference stencil, from their values at the
// stencil's centre (used by simulation/published_fields.cpp). Independent of the linkage: plain trigonometry.
//
// A stencil evaluates the same angle expression at neighbouring points, so its values differ from the
// centre's by a small turn delta (|delta| ~ eps times a derivative). cos and sin of angle = centre + delta
// then follow from the centre's by angle addition, with cos and sin of delta by their Taylor series, instead
// of one sincos per point. delta = angle - centre is exact (Sterbenz) or off by ulp(delta) ~ 1e-21, and
// the sum c - (c (1 - cos delta) + s sin delta) rounds once, so each value stays within an ulp or two of
// std::cos / std::sin of the same double `angle`: the stencil's differences see the same roundoff as
// evaluating every point directly. No cancellation: the correction is small relative to the centre value
// unless the result itself is ~delta, where its absolute error is an ulp of delta's terms (~1e-19 at 1e-3).

#include <cmath>

namespace sl {

struct Turn {
  double c, s;  // cos and sin of an angle
};

inline Turn turnOf(double angle) { return {std::cos(angle), std::sin(angle)}; }

inline Turn turnAt(double angle, const Turn& centre, double centreAngle) {
  const double delta = angle - centreAngle;
  if (!(std::abs(delta) <= 1e-3)) return turnOf(angle);  // a big step (or NaN): no shortcut
  const double d2 = delta * delta;
  // Taylor series for |delta| <= 1e-3, truncation below 1e-21: the first terms left out are d^6/720 < 1.4e-21
  // (1 - cos) and d^7/5040 < 2e-25 (sin).
  const double oneMinusCos = d2 * (0.5 - d2 * (1.0 / 24));
  const double sinDelta = delta * (1 - d2 * (1.0 / 6) * (1 - d2 * (1.0 / 20)));
  return {centre.c - (centre.c * oneMinusCos + centre.s * sinDelta),
          centre.s - (centre.s * oneMinusCos - centre.c * sinDelta)};
}

// sinc(x) given sin x: its Taylor series on |x| < 0.5 (terms to x^14, which is 4.7e-17 at 0.5; the next,
// x^16/17!, is below 5e-20), where sin x obtained by angle addition may have lost digits to cancellation, else sin x /
// x. Both branches are within an ulp or two of sinc(x) (linkage/smooth_functions.hpp).
inline double sincFromSine(double x, double sinX) {
  if (std::abs(x) >= 0.5) return sinX / x;
  const double x2 = x * x;
  return 1 + x2 * (-1.0 / 6 +
                   x2 * (1.0 / 120 +
                         x2 * (-1.0 / 5040 +
                               x2 * (1.0 / 362880 + x2 * (-1.0 / 39916800 + x2 * (1.0 / 6227020800.0 +
                                                                                  x2 * (-1.0 / 1307674368000.0)))))));
}

// sinc(a) sinc(b) given sin a and sin b: one division for both where neither takes the series.
inline double sincProductFromSines(double a, double sinA, double b, double sinB) {
  if (std::abs(a) >= 0.5 && std::abs(b) >= 0.5) return (sinA * sinB) / (a * b);
  return sincFromSine(a, sinA) * sincFromSine(b, sinB);
}

// The same idea for an angle given as atan2(y, x): its difference from the centre's angle is the argument of
// (x, y) times the conjugate of (x0, y0), an atan of a small ratio, by its series. The cross product's
// rounding (an ulp of x x0) is an ulp of the angle too.
inline double angleAt(double y, double x, double centreY, double centreX, double centreAngle) {
  const double along = centreX * x + centreY * y;  // > 0: the two directions are less than pi/2 apart
  const double ratio = (centreX * y - centreY * x) / along;
  if (!(along > 0 && std::abs(ratio) <= 1e-3)) return std::atan2(y, x);
  const double r2 = ratio * ratio;  // atan r = r - r^3/3 + r^5/5; the next term, r^7/7, is below 1.5e-22
  return centreAngle + ratio * (1 - r2 * (1.0 / 3 - r2 * (1.0 / 5)));
}

}  // namespace sl

#pragma once
// Scalar building blocks that stay smooth and accurate where the chart's textbook formulas divide
// zero by zero: sinc near 0, asin(z)/z near 0, and a square root whose derivative is finite at 0.
// Templated on the scalar so that Eigen's AutoDiffScalar (also nested) flows through unchanged.

#include <cmath>
#include <type_traits>

#include <unsupported/Eigen/AutoDiff>

namespace sl {

// The plain double inside a (possibly nested) AutoDiffScalar, for branching.
inline double valueOf(double x) { return x; }
template <class D>
double valueOf(const Eigen::AutoDiffScalar<D>& x) {
  return valueOf(x.value());
}

// sin(x)/x; the series branch keeps derivatives accurate near 0 as well as the value.
template <class S>
S sinc(const S& x) {
  using std::sin;
  const double v = valueOf(x);
  if (std::abs(v) < 0.1) {
    const S x2 = x * x;
    // 1 - x^2/3! + x^4/5! - x^6/7! + x^8/9! - x^10/11!; next term < 2e-22 at |x| = 0.1.
    return 1.0 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880 + x2 * (-1.0 / 39916800)))));
  }
  return sin(x) / x;
}

// asin(sqrt(z2)) / sqrt(z2) as a function of z2 in [0, 1]: smooth at z2 = 0 (value 1).
template <class S>
S asincOfSquare(const S& z2) {
  using std::asin;
  using std::sqrt;
  if (valueOf(z2) < 1e-3) {
    // Taylor series of asin(z)/z in z^2; the first omitted term is below 1e-19 here.
    return 1.0 + z2 * (1.0 / 6 + z2 * (3.0 / 40 + z2 * (5.0 / 112 + z2 * (35.0 / 1152 + z2 * (63.0 / 2816)))));
  }
  const S z = sqrt(z2);
  return asin(z) / z;
}

// sqrt with a zero derivative at 0 instead of inf*0 = NaN. Used only where the quantity enters the
// result through its square, so the true derivative there is 0 as well.
inline double guardedSqrt(double x) { return std::sqrt(x); }
template <class D>
Eigen::AutoDiffScalar<D> guardedSqrt(const Eigen::AutoDiffScalar<D>& x) {
  using std::sqrt;
  if (valueOf(x) <= 0.0) {
    Eigen::AutoDiffScalar<D> zero = x;
    zero = 0.0 * x;
    return zero;
  }
  return sqrt(x);
}

}  // namespace sl

#pragma once
// A truncated second-order Taylor jet in two variables: value, gradient and Hessian carried together through
// arithmetic (forward-mode AD to second order). The chart Psi (linkage/chart.hpp) is templated on its scalar, so
// hingePositionsInChart<SecondOrderJet> gives the stacked hinges q with their exact first and second
// derivatives q_a, q_ab in one pass: what the Gauss equation needs. Hand-rolled rather than Eigen's
// nested AutoDiffScalar because the curvature grid evaluates it 65,536 times per map and nested AutoDiff
// allocates and repeats work (the cross term is computed once here, twice there).

#include <cmath>

#include <Eigen/Core>

namespace sl {

struct SecondOrderJet {
  double v = 0.0;                          // value
  double g0 = 0.0, g1 = 0.0;               // d/dc0, d/dc1
  double h00 = 0.0, h01 = 0.0, h11 = 0.0;  // second derivatives

  SecondOrderJet() = default;
  SecondOrderJet(double value) : v(value) {}  // NOLINT: constants enter formulas implicitly, like doubles
  SecondOrderJet(double value, double d0, double d1, double dd00, double dd01, double dd11)
      : v(value), g0(d0), g1(d1), h00(dd00), h01(dd01), h11(dd11) {}

  // Coordinate c_i at value x: gradient e_i, Hessian 0.
  static SecondOrderJet variable(double x, int i) { return {x, i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, 0, 0, 0}; }

  SecondOrderJet& operator+=(const SecondOrderJet& b) { return *this = *this + b; }
  SecondOrderJet& operator-=(const SecondOrderJet& b) { return *this = *this - b; }
  SecondOrderJet& operator*=(const SecondOrderJet& b) { return *this = *this * b; }
  SecondOrderJet& operator/=(const SecondOrderJet& b) { return *this = *this / b; }

  friend SecondOrderJet operator+(const SecondOrderJet& a, const SecondOrderJet& b) {
    return {a.v + b.v, a.g0 + b.g0, a.g1 + b.g1, a.h00 + b.h00, a.h01 + b.h01, a.h11 + b.h11};
  }
  friend SecondOrderJet operator-(const SecondOrderJet& a, const SecondOrderJet& b) {
    return {a.v - b.v, a.g0 - b.g0, a.g1 - b.g1, a.h00 - b.h00, a.h01 - b.h01, a.h11 - b.h11};
  }
  friend SecondOrderJet operator-(const SecondOrderJet& a) { return {-a.v, -a.g0, -a.g1, -a.h00, -a.h01, -a.h11}; }
  friend SecondOrderJet operator*(const SecondOrderJet& a, const SecondOrderJet& b) {
    return {a.v * b.v,
            a.v * b.g0 + b.v * a.g0,
            a.v * b.g1 + b.v * a.g1,
            a.v * b.h00 + b.v * a.h00 + 2.0 * a.g0 * b.g0,
            a.v * b.h01 + b.v * a.h01 + a.g0 * b.g1 + a.g1 * b.g0,
            a.v * b.h11 + b.v * a.h11 + 2.0 * a.g1 * b.g1};
  }
  // q = a / b from a = q b differentiated twice.
  friend SecondOrderJet operator/(const SecondOrderJet& a, const SecondOrderJet& b) {
    const double r = 1.0 / b.v;
    SecondOrderJet q;
    q.v = a.v * r;
    q.g0 = (a.g0 - q.v * b.g0) * r;
    q.g1 = (a.g1 - q.v * b.g1) * r;
    q.h00 = (a.h00 - q.v * b.h00 - 2.0 * q.g0 * b.g0) * r;
    q.h01 = (a.h01 - q.v * b.h01 - q.g0 * b.g1 - q.g1 * b.g0) * r;
    q.h11 = (a.h11 - q.v * b.h11 - 2.0 * q.g1 * b.g1) * r;
    return q;
  }
  // Mixed with plain doubles (no derivative work spent on the constant).
  friend SecondOrderJet operator+(const SecondOrderJet& a, double b) {
    return {a.v + b, a.g0, a.g1, a.h00, a.h01, a.h11};
  }
  friend SecondOrderJet operator+(double b, const SecondOrderJet& a) { return a + b; }
  friend SecondOrderJet operator-(const SecondOrderJet& a, double b) {
    return {a.v - b, a.g0, a.g1, a.h00, a.h01, a.h11};
  }
  friend SecondOrderJet operator-(double b, const SecondOrderJet& a) {
    return {b - a.v, -a.g0, -a.g1, -a.h00, -a.h01, -a.h11};
  }
  friend SecondOrderJet operator*(const SecondOrderJet& a, double b) {
    return {a.v * b, a.g0 * b, a.g1 * b, a.h00 * b, a.h01 * b, a.h11 * b};
  }
  friend SecondOrderJet operator*(double b, const SecondOrderJet& a) { return a * b; }
  friend SecondOrderJet operator/(const SecondOrderJet& a, double b) { return a * (1.0 / b); }
  friend SecondOrderJet operator/(double b, const SecondOrderJet& a) { return SecondOrderJet(b) / a; }
};

// f(a) from f(a.v), f'(a.v), f''(a.v): the chain rule to second order.
inline SecondOrderJet chainRule(const SecondOrderJet& a, double f, double f1, double f2) {
  return {f,
          f1 * a.g0,
          f1 * a.g1,
          f1 * a.h00 + f2 * a.g0 * a.g0,
          f1 * a.h01 + f2 * a.g0 * a.g1,
          f1 * a.h11 + f2 * a.g1 * a.g1};
}

// Found by argument-dependent lookup from the chart's templates (using std::sin; sin(x)).
inline double valueOf(const SecondOrderJet& x) { return x.v; }
inline SecondOrderJet sin(const SecondOrderJet& a) {
  const double s = std::sin(a.v), c = std::cos(a.v);
  return chainRule(a, s, c, -s);
}
inline SecondOrderJet cos(const SecondOrderJet& a) {
  const double s = std::sin(a.v), c = std::cos(a.v);
  return chainRule(a, c, -s, -c);
}
// s = sqrt(a) from a = s^2 differentiated twice.
inline SecondOrderJet sqrt(const SecondOrderJet& a) {
  const double s = std::sqrt(a.v), r = 0.5 / s;
  SecondOrderJet out;
  out.v = s;
  out.g0 = a.g0 * r;
  out.g1 = a.g1 * r;
  out.h00 = (a.h00 - 2.0 * out.g0 * out.g0) * r;
  out.h01 = (a.h01 - 2.0 * out.g0 * out.g1) * r;
  out.h11 = (a.h11 - 2.0 * out.g1 * out.g1) * r;
  return out;
}
// As linkage/smooth_functions.hpp's guardedSqrt: derivatives 0 (not inf * 0) at 0, where the quantity only
// enters the result through its square.
inline SecondOrderJet guardedSqrt(const SecondOrderJet& a) {
  if (a.v <= 0.0) return SecondOrderJet(0.0);
  return sqrt(a);
}
inline SecondOrderJet asin(const SecondOrderJet& a) {
  const double f1 = 1.0 / std::sqrt(1.0 - a.v * a.v);
  return chainRule(a, std::asin(a.v), f1, a.v * f1 * f1 * f1);
}

}  // namespace sl

namespace Eigen {
template <>
struct NumTraits<sl::SecondOrderJet> : NumTraits<double> {
  using Real = sl::SecondOrderJet;
  using NonInteger = sl::SecondOrderJet;
  using Nested = sl::SecondOrderJet;
  using Literal = double;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 6,
    AddCost = 6,
    MulCost = 20
  };
};
template <typename BinaryOp>
struct ScalarBinaryOpTraits<sl::SecondOrderJet, double, BinaryOp> {
  using ReturnType = sl::SecondOrderJet;
};
template <typename BinaryOp>
struct ScalarBinaryOpTraits<double, sl::SecondOrderJet, BinaryOp> {
  using ReturnType = sl::SecondOrderJet;
};
}  // namespace Eigen

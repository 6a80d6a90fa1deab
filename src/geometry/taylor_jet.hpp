#pragma once
// Truncated Taylor polynomials in two variables to any order N <= 3: f(c + (u, v)) = sum_{i+j<=N} a_ij u^i v^j.
// Generic and deliberately plain (no sharing with second_order_jet.hpp): the intrinsic route to K needs the
// chart's third derivatives (Brioschi's formula differentiates the metric g = J^T M J twice), and it is kept
// independent of the Gauss-equation route's jet so that the two routes check each other.
// Unary functions are composed as f(a0 + d) = sum_n f^(n)(a0)/n! d^n with d nilpotent of order N + 1.

#include <array>
#include <cmath>

#include <Eigen/Core>

namespace sl {

template <int N>
struct TaylorJet {
  static_assert(N >= 0 && N <= 3, "unary derivative tables go to third order");
  static constexpr int kSize = (N + 1) * (N + 2) / 2;
  // Coefficient of u^i v^j, ordered by total degree.
  static constexpr int index(int i, int j) { return (i + j) * (i + j + 1) / 2 + j; }

  std::array<double, kSize> a{};

  TaylorJet() = default;
  TaylorJet(double value) { a[0] = value; }  // NOLINT: constants enter formulas implicitly, like doubles

  static TaylorJet variable(double x, int which) {
    TaylorJet out(x);
    if (N >= 1) out.a[which == 0 ? index(1, 0) : index(0, 1)] = 1.0;
    return out;
  }
  double coefficient(int i, int j) const { return a[index(i, j)]; }
  // The partial derivative d^(i+j) f / du^i dv^j at the expansion point.
  double partial(int i, int j) const {
    static constexpr double factorial[4] = {1, 1, 2, 6};
    return factorial[i] * factorial[j] * a[index(i, j)];
  }

  friend TaylorJet operator+(TaylorJet x, const TaylorJet& y) {
    for (int k = 0; k < kSize; ++k) x.a[k] += y.a[k];
    return x;
  }
  friend TaylorJet operator-(TaylorJet x, const TaylorJet& y) {
    for (int k = 0; k < kSize; ++k) x.a[k] -= y.a[k];
    return x;
  }
  friend TaylorJet operator-(TaylorJet x) {
    for (double& c : x.a) c = -c;
    return x;
  }
  friend TaylorJet operator*(const TaylorJet& x, const TaylorJet& y) {
    TaylorJet out;
    for (int i1 = 0; i1 <= N; ++i1)
      for (int j1 = 0; i1 + j1 <= N; ++j1)
        for (int i2 = 0; i1 + j1 + i2 <= N; ++i2)
          for (int j2 = 0; i1 + j1 + i2 + j2 <= N; ++j2)
            out.a[index(i1 + i2, j1 + j2)] += x.a[index(i1, j1)] * y.a[index(i2, j2)];
    return out;
  }
  friend TaylorJet operator/(const TaylorJet& x, const TaylorJet& y) { return x * reciprocal(y); }
  friend TaylorJet operator+(const TaylorJet& x, double y) { return x + TaylorJet(y); }
  friend TaylorJet operator+(double y, const TaylorJet& x) { return x + TaylorJet(y); }
  friend TaylorJet operator-(const TaylorJet& x, double y) { return x - TaylorJet(y); }
  friend TaylorJet operator-(double y, const TaylorJet& x) { return TaylorJet(y) - x; }
  friend TaylorJet operator*(TaylorJet x, double y) {
    for (double& c : x.a) c *= y;
    return x;
  }
  friend TaylorJet operator*(double y, const TaylorJet& x) { return x * y; }
  friend TaylorJet operator/(const TaylorJet& x, double y) { return x * (1.0 / y); }
  friend TaylorJet operator/(double y, const TaylorJet& x) { return reciprocal(x) * y; }
  TaylorJet& operator+=(const TaylorJet& y) { return *this = *this + y; }
  TaylorJet& operator-=(const TaylorJet& y) { return *this = *this - y; }
  TaylorJet& operator*=(const TaylorJet& y) { return *this = *this * y; }
  TaylorJet& operator/=(const TaylorJet& y) { return *this = *this / y; }

  // f(x) from f(x0), f'(x0), f''(x0), f'''(x0).
  static TaylorJet compose(const TaylorJet& x, const double (&derivatives)[4]) {
    TaylorJet d = x;
    d.a[0] = 0.0;
    TaylorJet out(derivatives[0]), power(1.0);
    double factorial = 1.0;
    for (int n = 1; n <= N; ++n) {
      power = power * d;
      factorial *= n;
      out = out + power * (derivatives[n] / factorial);
    }
    return out;
  }
  friend TaylorJet reciprocal(const TaylorJet& x) {
    const double r = 1.0 / x.a[0];
    const double f[4] = {r, -r * r, 2 * r * r * r, -6 * r * r * r * r};
    return compose(x, f);
  }
};

// Found by argument-dependent lookup from the chart's templates.
template <int N>
double valueOf(const TaylorJet<N>& x) {
  return x.a[0];
}
template <int N>
TaylorJet<N> sin(const TaylorJet<N>& x) {
  const double s = std::sin(x.a[0]), c = std::cos(x.a[0]);
  const double f[4] = {s, c, -s, -c};
  return TaylorJet<N>::compose(x, f);
}
template <int N>
TaylorJet<N> cos(const TaylorJet<N>& x) {
  const double s = std::sin(x.a[0]), c = std::cos(x.a[0]);
  const double f[4] = {c, -s, -c, s};
  return TaylorJet<N>::compose(x, f);
}
template <int N>
TaylorJet<N> sqrt(const TaylorJet<N>& x) {
  const double s = std::sqrt(x.a[0]), r = 1.0 / x.a[0];
  const double f[4] = {s, 0.5 * s * r, -0.25 * s * r * r, 0.375 * s * r * r * r};
  return TaylorJet<N>::compose(x, f);
}
template <int N>
TaylorJet<N> guardedSqrt(const TaylorJet<N>& x) {
  if (x.a[0] <= 0.0) return TaylorJet<N>(0.0);
  return sqrt(x);
}
template <int N>
TaylorJet<N> asin(const TaylorJet<N>& x) {
  const double v = x.a[0], w = 1.0 / (1.0 - v * v), r = std::sqrt(w);  // r = (1 - v^2)^(-1/2)
  const double f[4] = {std::asin(v), r, v * r * w, (1.0 + 2.0 * v * v) * r * w * w};
  return TaylorJet<N>::compose(x, f);
}

// d/du (which = 0) or d/dv (which = 1) of the polynomial, one order lower.
template <int N>
TaylorJet<N - 1> partialDerivative(const TaylorJet<N>& x, int which) {
  TaylorJet<N - 1> out;
  for (int i = 0; i < N; ++i)
    for (int j = 0; i + j < N; ++j)
      out.a[TaylorJet<N - 1>::index(i, j)] =
          which == 0 ? (i + 1) * x.a[TaylorJet<N>::index(i + 1, j)] : (j + 1) * x.a[TaylorJet<N>::index(i, j + 1)];
  return out;
}

}  // namespace sl

namespace Eigen {
template <int N>
struct NumTraits<sl::TaylorJet<N>> : NumTraits<double> {
  using Real = sl::TaylorJet<N>;
  using NonInteger = sl::TaylorJet<N>;
  using Nested = sl::TaylorJet<N>;
  using Literal = double;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 10,
    AddCost = 10,
    MulCost = 100
  };
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<sl::TaylorJet<N>, double, BinaryOp> {
  using ReturnType = sl::TaylorJet<N>;
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<double, sl::TaylorJet<N>, BinaryOp> {
  using ReturnType = sl::TaylorJet<N>;
};
}  // namespace Eigen

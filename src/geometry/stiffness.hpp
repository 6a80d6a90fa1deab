#pragma once
// Directional stiffness: S(a) = |II(v, v)|^2_M for the g-unit tangent vector
// v = cos(a) e1 + sin(a) e2 of a g-orthonormal frame, with A = II(e1, e1), B = II(e1, e2), C = II(e2, e2).
//
// II(v, v) = P + Q cos 2a + R sin 2a with P = (A + C)/2, Q = (A - C)/2, R = B: as a runs over a half turn,
// II(v, v) runs once round the curvature ellipse, and S is the squared M-distance from the origin to its points.
// With w = (cos 2a, sin 2a):  S = |P|^2 + 2 b.w + w^T G w,  G = Gram(Q, R),  b = (<P,Q>, <P,R>),
// a quadratic on the unit circle. Its exact global maximum and minimum are the two trust-region solutions
// (G - lambda) w = -b with lambda >= the larger eigenvalue of G (maximum) or <= the smaller (minimum); each
// lambda is the single root of a monotone secular equation on a known bracket, found by Newton's method from
// the bracket's lower end (monotone convergence, capped). Nothing is sampled or truncated.

#include <Eigen/Dense>

namespace sl {

struct StiffnessExtremes {
  double max = 0.0;       // max over a of S(a)
  double min = 0.0;       // min over a of S(a); 0 <= min <= max
  double angleOfMax = 0;  // a maximising S, in (-pi/2, pi/2] (S(a) = S(a + pi): a direction, not a vector)
  double angleOfMin = 0;  // a minimising S, in (-pi/2, pi/2]
  int iterations = 0;     // Newton steps spent on both secular equations
};

// gram(i, j) = <X_i, X_j>_M for (X_0, X_1, X_2) = (A, B, C). Where S is constant (max == min) or its extremum
// is attained on two directions, the angle returned is one of them, chosen deterministically.
StiffnessExtremes stiffnessExtremes(const Eigen::Matrix3d& gram);

// S(a) itself, from the same Gram matrix.
double directionalStiffness(const Eigen::Matrix3d& gram, double angle);

}  // namespace sl

#pragma once
// Standard normal numbers from a seed, written out (64-bit Mersenne Twister and Box-Muller) so that the same
// seed gives the same numbers with every standard library (std::normal_distribution's algorithm is not
// specified): clouds of starts and random pushes are part of a scene's identity.

#include <cmath>
#include <random>

#include <Eigen/Dense>

namespace sl {

class NormalDraws {
 public:
  explicit NormalDraws(unsigned long seed) : bits_(seed) {}
  double next() {
    const double u1 = (double(bits_() >> 11) + 0.5) * 0x1.0p-53;  // in (0, 1)
    const double u2 = double(bits_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.141592653589793 * u2);
  }
  Eigen::VectorXd vector(Eigen::Index size) {
    Eigen::VectorXd v(size);
    for (Eigen::Index i = 0; i < size; ++i) v(i) = next();
    return v;
  }

 private:
  std::mt19937_64 bits_;
};

}  // namespace sl

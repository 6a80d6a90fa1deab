// The chain's own rules (spec section 1) at their exact boundaries: n-2 < L < n for a configuration sphere,
// 0 < L <= n-2 only as a slack chain, at least 3 rods, masses finite and non-negative, mass at every hinge.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "linkage/chain.hpp"

namespace sl {
namespace {

Chain withLength(int rods, double baseLength) { return Chain::uniform(rods, baseLength); }

TEST(Chain, TheBaseLengthLiesStrictlyBetweenNMinusTwoAndN) {
  for (int n : {3, 4, 7}) {
    SCOPED_TRACE(n);
    EXPECT_THROW(withLength(n, n).validate(), std::invalid_argument);
    EXPECT_THROW(withLength(n, n).validate(true), std::invalid_argument);
    EXPECT_NO_THROW(withLength(n, std::nextafter(double(n), 0.0)).validate());
    EXPECT_THROW(withLength(n, n - 2).validate(), std::invalid_argument);
    EXPECT_NO_THROW(withLength(n, std::nextafter(double(n - 2), double(n))).validate());
    // A slack chain: n - 2 itself and anything above 0.
    EXPECT_NO_THROW(withLength(n, n - 2).validate(true));
    EXPECT_NO_THROW(withLength(n, 1e-9).validate(true));
    EXPECT_THROW(withLength(n, 0).validate(true), std::invalid_argument);
    EXPECT_THROW(withLength(n, std::numeric_limits<double>::quiet_NaN()).validate(), std::invalid_argument);
  }
}

TEST(Chain, ThreeRodsAtLeast) {
  EXPECT_NO_THROW(withLength(3, 2).validate(true));
  Chain two = withLength(3, 1.5);
  two.rods = 2;
  two.hingeMasses.resize(1);
  two.rodMasses.resize(2);
  EXPECT_THROW(two.validate(true), std::invalid_argument);
}

TEST(Chain, MassesAreFiniteNonNegativeAndEveryHingeCarriesSome) {
  Chain chain = withLength(4, 3);
  chain.hingeMasses(1) = 0;
  EXPECT_THROW(chain.validate(), std::invalid_argument) << "a massless hinge between massless rods";
  chain.rodMasses(2) = 1e-12;
  EXPECT_NO_THROW(chain.validate()) << "a massive rod beside it carries it";
  chain.rodMasses(2) = -1e-12;
  EXPECT_THROW(chain.validate(), std::invalid_argument);
  chain = withLength(4, 3);
  chain.hingeMasses(0) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(chain.validate(), std::invalid_argument);
  chain = withLength(4, 3);
  chain.rodMasses.resize(3);
  EXPECT_THROW(chain.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace sl

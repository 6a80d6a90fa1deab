// Names given on the command line become the registry's kinds, or fail naming the option and the choices.

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "analysis/option_checks.hpp"
#include "contracts/registry.hpp"

namespace sl {
namespace {

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "no error";
}

TEST(OptionChecks, NamesBecomeKindsInTheirOrder) {
  EXPECT_EQ(parseKindsOption("--methods", "method", {"ambient", "christoffel-fd", "ambient"}, kMethods),
            (std::vector<Method>{Method::Ambient, Method::ChristoffelFd, Method::Ambient}));
  EXPECT_TRUE(parseKindsOption("--integrators", "integrator", {}, kIntegrators).empty());
  EXPECT_EQ(parseKindOption("--integrator", "integrator", "bulirsch-stoer", kIntegrators), Integrator::BulirschStoer);
  EXPECT_EQ(kindsOf(kIntegrators), (std::vector<Integrator>{Integrator::Rk4, Integrator::Dopri5, Integrator::Rkf78,
                                                            Integrator::BulirschStoer}));
}

TEST(OptionChecks, AnUnknownNameNamesTheOptionAndListsTheChoices) {
  EXPECT_EQ(errorOf([] {
              parseKindsOption("--methods", "method", {"ambient", "ambiant"}, kMethods);
            }),
            "--methods: unknown method 'ambiant' (expected christoffel-fd, embedded-fd, christoffel, embedded or "
            "ambient)");
  EXPECT_EQ(errorOf([] { parseKindOption("--integrator", "integrator", "euler", kIntegrators); }),
            "--integrator: unknown integrator 'euler' (expected rk4, dopri5, rkf78 or bulirsch-stoer)");
}

TEST(OptionChecks, NumbersMustBePositiveAndFinite) {
  EXPECT_NO_THROW(requirePositive("--steps", {0.1, 1e-300}));
  EXPECT_EQ(errorOf([] {
              requirePositive("--steps", {0.1, 0});
            }),
            "--steps: expected positive finite numbers, found 0");
  EXPECT_THROW(requirePositive("--tolerances", {INFINITY}), std::invalid_argument);
}

}  // namespace
}  // namespace sl

// Which method can move which chain: each rule at its boundary, from both sides.
#include <gtest/gtest.h>

#include <cmath>

#include "contracts/limits.hpp"
#include "linkage/method_rules.hpp"

namespace sl {
namespace {

std::vector<MethodRefusal> refusalsOf(Method method, const Chain* chain, bool byHinges = false, bool jacobi = false) {
  return methodRefusals({method, chain, byHinges, jacobi});
}

using Refusals = std::vector<MethodRefusal>;

TEST(MethodRules, ChartMethodsStopAtTheirRodLimit) {
  const Chain limit = Chain::uniform(limits::kMaxRods, limits::kMaxRods - 1.0);
  const Chain beyond = Chain::uniform(limits::kMaxRods + 1, limits::kMaxRods + 0.0);
  EXPECT_EQ(refusalsOf(Method::Christoffel, &limit), Refusals{});
  EXPECT_EQ(refusalsOf(Method::Embedded, &beyond), Refusals{MethodRefusal::TooManyRodsForCharts});
  EXPECT_EQ(refusalsOf(Method::Ambient, &beyond), Refusals{});
  // While n is unknown, no rule by rod count.
  EXPECT_EQ(refusalsOf(Method::Embedded, nullptr), Refusals{});
}

TEST(MethodRules, SlackChainsAndHingeStartsNeedTheAmbientMethod) {
  const Chain slack = Chain::uniform(5, 3.0), taut = Chain::uniform(5, 3.0 + 1e-12);
  EXPECT_EQ(refusalsOf(Method::Christoffel, &slack), Refusals{MethodRefusal::SlackChainHasNoChart});
  EXPECT_EQ(refusalsOf(Method::Christoffel, &taut), Refusals{});
  EXPECT_EQ(refusalsOf(Method::Christoffel, &taut, true), Refusals{MethodRefusal::HingeStartHasNoChart});
  EXPECT_EQ(refusalsOf(Method::Christoffel, nullptr, true), Refusals{MethodRefusal::HingeStartHasNoChart});
  EXPECT_EQ(refusalsOf(Method::Ambient, &slack, true), Refusals{});
}

TEST(MethodRules, PublishedMethodsNeedTheSpecsChain) {
  const Chain spec = Chain::uniform(4, 3.0);
  EXPECT_EQ(refusalsOf(Method::ChristoffelFd, &spec), Refusals{});
  const Chain five = Chain::uniform(5, 4.0);
  EXPECT_EQ(refusalsOf(Method::EmbeddedFd, &five), Refusals{MethodRefusal::PublishedNeedsFourRods});
  Chain heavy = spec;
  heavy.rodMasses(2) = 1e-300;
  EXPECT_EQ(refusalsOf(Method::EmbeddedFd, &heavy), Refusals{MethodRefusal::PublishedNeedsSpecMasses});
  Chain light = spec;
  light.hingeMasses(0) = std::nextafter(1.0, 0.0);
  EXPECT_EQ(refusalsOf(Method::ChristoffelFd, &light), Refusals{MethodRefusal::PublishedNeedsSpecMasses});
  EXPECT_EQ(refusalsOf(Method::Christoffel, &heavy), Refusals{});
}

TEST(MethodRules, JacobiFieldsNeedTheAmbientMethodASpherePointAndFourRods) {
  const Chain four = Chain::uniform(4, 3.0), three = Chain::uniform(3, 2.5);
  EXPECT_EQ(refusalsOf(Method::Ambient, &four, false, true), Refusals{});
  EXPECT_EQ(refusalsOf(Method::Ambient, &three, false, true), Refusals{MethodRefusal::JacobiNeedsFourRods});
  EXPECT_EQ(refusalsOf(Method::Ambient, &four, true, true), Refusals{MethodRefusal::JacobiNeedsSpherePoint});
  EXPECT_EQ(refusalsOf(Method::Christoffel, &four, true, true),
            (Refusals{MethodRefusal::JacobiNeedsAmbient, MethodRefusal::HingeStartHasNoChart,
                      MethodRefusal::JacobiNeedsSpherePoint}));
}

}  // namespace
}  // namespace sl

// The registry: every kind has exactly one entry, names are unique, and names and kinds convert both ways.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "contracts/registry.hpp"

namespace sl {
namespace {

template <class Table>
void expectComplete(const Table& table, int kindCount) {
  std::set<int> kinds;
  std::set<std::string> names;
  for (const auto& entry : table) {
    kinds.insert(static_cast<int>(entry.kind));
    names.insert(std::string(entry.name));
    EXPECT_FALSE(entry.name.empty());
    EXPECT_EQ(parseKind(table, entry.name), entry.kind) << entry.name;
    EXPECT_EQ(&traitsOf(table, entry.kind), &entry) << entry.name;
  }
  EXPECT_EQ(static_cast<int>(kinds.size()), kindCount) << "every kind once";
  EXPECT_EQ(names.size(), table.size()) << "unique names";
  EXPECT_EQ(*kinds.begin(), 0);
  EXPECT_EQ(*kinds.rbegin(), kindCount - 1);
  EXPECT_FALSE(parseKind(table, "no-such-name"));
  EXPECT_EQ(namesOf(table).size(), table.size());
}

TEST(Registry, TablesAreComplete) {
  expectComplete(kMethods, static_cast<int>(Method::Ambient) + 1);
  expectComplete(kIntegrators, static_cast<int>(Integrator::BulirschStoer) + 1);
  expectComplete(kStopReasons, static_cast<int>(StopReason::ConstraintRankLoss) + 1);
  expectComplete(kPanelKinds, static_cast<int>(PanelKind::Text) + 1);
  expectComplete(kPlotKinds, static_cast<int>(PlotKind::Holonomy) + 1);
  expectComplete(kFamilyKinds, static_cast<int>(FamilyKind::Cloud) + 1);
  expectComplete(kLinkageLayouts, static_cast<int>(LinkageLayout::Overlay) + 1);
  expectComplete(kCameraModes, static_cast<int>(CameraMode::Orbit) + 1);
  expectComplete(kGlBackends, static_cast<int>(GlBackend::OsMesa) + 1);
  expectComplete(kStabilities, static_cast<int>(Stability::Parabolic) + 1);
  expectComplete(kChainSymmetries, static_cast<int>(ChainSymmetry::HalfTurn) + 1);
  expectComplete(kDiscreteSeeds, static_cast<int>(DiscreteSeed::ShootingPath) + 1);
}

// Only a GPU is not llvmpipe: the software backends are the ones whose bytes the reference frames pin.
TEST(Registry, GlBackendProperties) {
  for (const GlBackendTraits& b : kGlBackends) EXPECT_EQ(b.software, b.kind != GlBackend::EglGpu) << b.name;
  EXPECT_EQ(parseKind(kGlBackends, "egl-gpu"), GlBackend::EglGpu);
  EXPECT_EQ(nameOf(GlBackend::OsMesa), "osmesa");
}

// The properties the rest of the program relies on (docs/methods.md).
TEST(Registry, MethodProperties) {
  for (const MethodTraits& m : kMethods) {
    EXPECT_EQ(m.published, m.name.ends_with("-fd")) << m.name;
    EXPECT_TRUE(!m.usesAtlas || m.chartBased) << m.name;
    EXPECT_TRUE(!m.published || !m.usesAtlas) << m.name;
  }
  EXPECT_FALSE(traits(Method::Ambient).chartBased);
  EXPECT_FALSE(traits(Integrator::Rk4).adaptive);
  EXPECT_TRUE(traits(Integrator::Rkf78).adaptive);
  EXPECT_EQ(nameOf(StopReason::PoleFoldBack), "pole-fold-back");
}

}  // namespace
}  // namespace sl

#pragma once
// The yardstick for a run: hinge positions on a fixed grid of times from a different method at its
// tightest setting. The chart-free ambient method checks every intrinsic method; the ambient method
// itself is checked by `embedded` (exact derivatives, chart switching), so no method checks itself.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

#include "contracts/registry.hpp"
#include "contracts/run_config.hpp"
#include "linkage/chain.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

inline constexpr double kReferenceTolerance = 1e-13;

// What the CSVs' reference_method column says when runs were not checked against a reference.
inline constexpr std::string_view kNoReferenceName = "none";

// The method that checks `methodUnderTest`: ambient, or embedded when the method is ambient.
Method referenceMethodFor(Method methodUnderTest);

// The integrator for references: rkf78, order 7(8), the cheapest adaptive integrator at tight tolerances.
constexpr Integrator tightestIntegrator() { return Integrator::Rkf78; }

// RunConfig for the reference of `methodUnderTest`: referenceMethodFor, tightestIntegrator,
// tolerance kReferenceTolerance.
RunConfig referenceConfig(Method methodUnderTest);

struct ReferencePath {
  std::optional<RunConfig> config;  // the reference's run; empty for noReference
  std::vector<double> times;
  std::vector<Eigen::Matrix2Xd> hinges;  // one per time reached
  std::optional<StopInfo> stop;          // set if the reference itself stopped (then the check is void)
};

// No reference: the grid times only. Runs measured against it report their fate and invariants.
ReferencePath noReference(const std::vector<double>& times);

ReferencePath computeReferencePath(const Chain& chain, const InitialState& start, const std::vector<double>& times,
                                   const RunConfig& config);

// The reference's method as the CSVs write it: its name, or kNoReferenceName.
std::string referenceMethodName(const ReferencePath& reference);

}  // namespace sl

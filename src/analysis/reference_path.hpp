#pragma once
// The yardstick for a run: hinge positions on a fixed grid of times from a different method at its
// tightest setting. The chart-free ambient method checks every intrinsic method; the ambient method
// itself is checked by `embedded` (exact derivatives, chart switching), so no method checks itself.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "linkage/chain.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

inline constexpr double kReferenceTolerance = 1e-13;

// The method that checks `methodUnderTest`: ambient, or embedded when the method is ambient.
std::string referenceMethodFor(const std::string& methodUnderTest);

// The integrator for references: rkf78 (order 7(8), the cheapest at tight tolerances), else the last
// adaptive integrator on offer.
std::string tightestIntegrator();

// RunConfig for the reference of `methodUnderTest`: referenceMethodFor, tightestIntegrator,
// tolerance kReferenceTolerance.
RunConfig referenceConfig(const std::string& methodUnderTest);

// 0, interval, 2 interval, ..., and duration itself as the last time.
std::vector<double> gridTimes(double duration, double interval);

struct ReferencePath {
  RunConfig config;
  std::vector<double> times;
  std::vector<Eigen::Matrix2Xd> hinges;  // one per time reached
  std::optional<StopInfo> stop;          // set if the reference itself stopped (then the check is void)
};

// No reference: the grid times only. Runs measured against it report their fate and invariants.
ReferencePath noReference(const std::vector<double>& times);

ReferencePath computeReferencePath(const Chain& chain, const InitialState& start, const std::vector<double>& times,
                                   const RunConfig& config);

// max over hinges of |a_k - b_k|: the position error of one configuration.
double hingeDistance(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b);

}  // namespace sl

#include "cli/geometry_json.hpp"

namespace sl {

namespace {

nlohmann::json extremumJson(const SurfaceExtremum& e) { return {{"value", e.value}, {"phi", e.phi}, {"t", e.t}}; }

}  // namespace

nlohmann::json summaryJson(const CurvatureSummary& s) {
  return {{"L", s.baseLength},
          {"area", s.area},
          {"total_curvature", s.totalCurvature},
          {"gauss_bonnet_error", s.gaussBonnetError},
          {"K_min", extremumJson(s.curvatureMin)},
          {"K_max", extremumJson(s.curvatureMax)},
          {"bending_max", extremumJson(s.bendingMax)}};
}

}  // namespace sl

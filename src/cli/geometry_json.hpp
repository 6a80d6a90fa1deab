#pragma once
// The curvature summary of a 4-rod configuration sphere as JSON, as `linkage geometry --summary` and
// `linkage numbers` print it.

#include <nlohmann/json.hpp>

#include "geometry/curvature_grid.hpp"

namespace sl {

// {"L", "area", "total_curvature", "gauss_bonnet_error", "K_min", "K_max", "bending_max"}; extrema as
// {"value", "phi", "t"}.
nlohmann::json summaryJson(const CurvatureSummary& summary);

}  // namespace sl

#pragma once
// `linkage geometry --holonomy LOOP` and `--sectional POINTS`: the holonomy of a loop of motions (4 rods) and the
// sectional curvature of tangent planes (5 rods and more), as JSON (docs/geometry.md, "Parallel transport and
// holonomy", "Sectional curvature").
#include <string>

#include "scene/scene.hpp"

namespace sl {

struct CurvatureRequest {
  std::string input;   // LOOP or POINTS: JSON text, or a file holding it
  std::string output;  // empty: standard output
  bool quiet = false;
};

// Each writes its JSON whole (or nothing) and returns what the summary line says. A holonomy whose own checks fail
// (inverse/self_check.hpp) is written, with its checks, and then ends the command with exit 3.
std::string runHolonomy(const Scene& scene, const CurvatureRequest& request);
std::string runSectional(const Scene& scene, const CurvatureRequest& request);

}  // namespace sl

#pragma once
// The sphere panel's static surface for 4 rods (view.sphere in the scene): the sphere coloured by the Gaussian
// curvature K or the bending |II|^2 of the kinetic metric, stiffness ellipses and the seams t = +-pi/2, computed once per render
// from the exact geometry of docs/geometry.md (geometry/curvature.hpp); or coloured by the distance from a point
// with its conjugate and cut loci as curves (inverse/distance_map.hpp, on the colour grid's nodes).

#include <memory>

#include "contracts/frame_state.hpp"
#include "contracts/view_settings.hpp"
#include "linkage/chain.hpp"

namespace sl {

// Null when the spec asks for nothing. The chain must have 4 rods when it asks for something (the scene
// loader refuses other chains with the JSON path). The distance colouring is measured from `distancePoint` (a
// point of the configuration sphere; `fromStart`: the first run's start, else one the scene names). The holonomy is
// that of the geodesic polygon through `holonomyCorners` (sphere points, at least 3).
std::shared_ptr<const SphereDecoration> makeSphereDecoration(const Chain& chain, const SphereSurfaceSpec& spec,
                                                             const Eigen::VectorXd& distancePoint = {},
                                                             bool fromStart = true,
                                                             const std::vector<Eigen::VectorXd>& holonomyCorners = {});

// Grid and glyph counts: a colour texture of 128 x 256 cells (1.4 degrees), 72 ellipses.
inline constexpr int kSphereFieldRows = 128;
inline constexpr int kStiffnessEllipses = 72;

}  // namespace sl

#pragma once
// The look of the reference demo: cream sphere, silver chain, charcoal pins, warm grey ink.

#include "contracts/frame_state.hpp"
#include "render/shape_batch.hpp"

namespace sl::palette {

inline constexpr Rgba sphereCream{0.93f, 0.87f, 0.74f, 1};
inline constexpr Rgba sphereGrid{0.55f, 0.47f, 0.38f, 1};
inline constexpr Rgba poleMark{0.22f, 0.22f, 0.26f, 1};
inline constexpr Rgba glass{0.45f, 0.50f, 0.58f, 1};
inline constexpr Rgba silver{0.74f, 0.76f, 0.80f, 1};
inline constexpr Rgba jointSilver{0.62f, 0.64f, 0.68f, 1};
inline constexpr Rgba pinCharcoal{0.20f, 0.21f, 0.24f, 1};
inline constexpr Rgba floorGrey{0.50f, 0.48f, 0.45f, 1};
inline constexpr Rgba ink{0.16f, 0.16f, 0.18f, 1};
inline constexpr Rgba softInk{0.42f, 0.41f, 0.40f, 1};
inline constexpr Rgba gridLight{0.86f, 0.85f, 0.82f, 1};
inline constexpr Rgba stopRed{0.70f, 0.12f, 0.10f, 1};
inline constexpr Rgba nowCursor{0.30f, 0.29f, 0.31f, 0.55f};  // the plots' "now" line at the frame's time
inline constexpr Rgba stoppedGrey{0.60f, 0.60f, 0.60f, 1};     // a stopped chain in the linkage panel
// The distance colouring's loci on viridis: the conjugate locus magenta, the cut locus white (each on a dark halo).
inline constexpr Rgba conjugateLocus{0.88f, 0.22f, 0.62f, 1};
inline constexpr Rgba cutLocus{1.00f, 1.00f, 1.00f, 1};
// The returning vector of a holonomy (view.sphere.holonomy): purple, in neither half of the curvature map.
inline constexpr Rgba returningVector{SphereTransport::kReturningColor.r, SphereTransport::kReturningColor.g,
                                      SphereTransport::kReturningColor.b, 1};

inline Rgba withAlpha(Rgba c, float a) { return {c.r, c.g, c.b, a}; }

}  // namespace sl::palette

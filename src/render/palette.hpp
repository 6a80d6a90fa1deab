#pragma once
// The look of the reference demo: cream sphere, silver chain, charcoal pins, warm grey ink.

#include "contracts/frame_state.hpp"
#include "contracts/registry.hpp"
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

// What is drawn on the frame's background rather than on the sphere or a chain, by view.theme: text, axes and their
// grid, labels and their leaders, the floor and the pins, the marks of a stop in the plots and panels. The light page
// is the look above; the dark one inverts the ink's lightness for dark slides (WCAG contrast on its page: ink 13:1,
// soft ink 5:1, red 5.6:1, as on the light page) and lifts the red and the pins off the dark. What lies on the sphere
// (its marks, paths, balls, arrows) keeps the colours above: the lit sphere is the same object on either page.
struct PageInk {
  Rgba ink, softInk, gridLight, nowCursor, floorGrey, pinCharcoal, stopRed;
};
inline constexpr PageInk kLightPage{ink, softInk, gridLight, nowCursor, floorGrey, pinCharcoal, stopRed};
inline constexpr PageInk kDarkPage{.ink = {0.91f, 0.90f, 0.87f, 1},
                                   .softInk = {0.58f, 0.57f, 0.55f, 1},
                                   .gridLight = {0.20f, 0.21f, 0.23f, 1},
                                   .nowCursor = {0.80f, 0.79f, 0.76f, 0.55f},
                                   .floorGrey = {0.52f, 0.51f, 0.49f, 1},
                                   .pinCharcoal = {0.50f, 0.51f, 0.55f, 1},
                                   .stopRed = {0.96f, 0.42f, 0.36f, 1}};
constexpr const PageInk& pageInk(Theme theme) { return theme == Theme::Dark ? kDarkPage : kLightPage; }

}  // namespace sl::palette

#pragma once
// Where each panel goes. Panels with a rect keep it (fractions of the frame from the top-left);
// the others are laid out automatically: text panels as bands across the top, the first other panel
// as the large left area, the rest stacked in a column on the right; in a portrait frame the first panel
// across the top and the rest in rows below it.

#include <vector>

#include "contracts/view_settings.hpp"
#include "render/sphere_camera.hpp"

namespace sl {

// The panels to draw: settings.panels, or sphere + linkage + text when none are given.
std::vector<PanelSpec> effectivePanels(const ViewSettings& settings);

// `reservedTop` pixels across the top stay free of automatically placed panels (the title line's band).
std::vector<PixelRect> layoutPanels(const std::vector<PanelSpec>& panels, int width, int height,
                                    float reservedTop = 0);

}  // namespace sl

#include "render/panel_layout.hpp"

#include <algorithm>
#include <cmath>

namespace sl {

std::vector<PanelSpec> effectivePanels(const ViewSettings& settings) {
  if (!settings.panels.empty()) return settings.panels;
  PanelSpec sphere, linkage, text;
  sphere.kind = PanelKind::Sphere;
  linkage.kind = PanelKind::Linkage;
  text.kind = PanelKind::Text;
  return {sphere, linkage, text};
}

std::vector<PixelRect> layoutPanels(const std::vector<PanelSpec>& panels, int width, int height, float reservedTop) {
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  // Whole pixels of the frame at 720p's scale (3 pixels at 3840x2160, 2 at 2560x1440, 1 at 1920x1080 and below):
  // panel edges then lie on whole pixels and at the same place of the picture at every size whose ratio to 720p is
  // whole, so a 4K frame box-downscaled to 720p has its panels' contents where the 720p frame has them, not a
  // fraction of a pixel off. (The font's baselines use the same grain: frame_composer.cpp.)
  const float grain = std::floor(std::max(1.0f, std::min(w, h) / 720.0f));
  const auto snap = [grain](float v) { return std::round(std::round(v / grain) * grain); };
  std::vector<PixelRect> rects(panels.size());
  std::vector<std::size_t> bands, others;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    if (panels[i].rect) {
      const auto& r = *panels[i].rect;
      // Whole pixels: panel edges then never split a pixel between two scissor rectangles.
      const float x0 = snap(float(r[0]) * w), y0 = snap(float(r[1]) * h);
      rects[i] = {x0, y0, snap(float(r[0] + r[2]) * w) - x0, snap(float(r[1] + r[3]) * h) - y0};
    } else if (panels[i].kind == PanelKind::Text) {
      bands.push_back(i);
    } else {
      others.push_back(i);
    }
  }
  // Text scales with the shorter side (frame_composer.cpp), so its bands do too: a portrait frame is not a
  // landscape one stretched.
  const float bandHeight = snap(0.14f * std::min(w, h));
  float top = snap(reservedTop);
  for (std::size_t i : bands) {
    rects[i] = {0, top, w, bandHeight};
    top += bandHeight;
  }
  if (others.empty()) return rects;
  const float rest = h - top;
  if (h > w && others.size() > 1) {
    // Portrait: the first panel as a square (at most 55% of the height) across the top, the others in rows
    // below it across the whole width.
    const float mainHeight = snap(std::min(w, 0.55f * rest));
    rects[others[0]] = {0, top, w, mainHeight};
    const float below = rest - mainHeight;
    const float rowCount = static_cast<float>(others.size() - 1);
    for (std::size_t k = 1; k < others.size(); ++k) {
      const float y0 = snap(top + mainHeight + below * float(k - 1) / rowCount);
      const float y1 = snap(top + mainHeight + below * float(k) / rowCount);
      rects[others[k]] = {0, y0, w, y1 - y0};
    }
    return rects;
  }
  const float mainWidth = others.size() == 1 ? w : snap(0.56f * w);
  rects[others[0]] = {0, top, mainWidth, rest};
  const float columnCount = static_cast<float>(others.size() - 1);
  for (std::size_t k = 1; k < others.size(); ++k) {
    const float y0 = snap(top + rest * float(k - 1) / columnCount);
    const float y1 = snap(top + rest * float(k) / columnCount);
    rects[others[k]] = {mainWidth, y0, w - mainWidth, y1 - y0};
  }
  return rects;
}

}  // namespace sl

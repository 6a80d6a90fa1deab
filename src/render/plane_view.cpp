#include "render/plane_view.hpp"

#include <algorithm>

namespace sl::render {

PlaneView fitChainView(int rods, double base, const PixelRect& r) {
  double x0 = 0, x1 = base, y0 = -0.5, y1 = 0.5;
  for (int k = 1; k < rods; ++k) {
    x0 = std::min(x0, std::max(-double(k), base - (rods - k)));
    x1 = std::max(x1, std::min(double(k), base + (rods - k)));
    const double reach = std::min(double(k), double(rods - k));
    y0 = std::min(y0, -reach);
    y1 = std::max(y1, reach);
  }
  const double margin = 0.08;
  const double scale = std::min(r.width * (1 - 2 * margin) / (x1 - x0), r.height * (1 - 2 * margin) / (y1 - y0));
  return {scale, r.x + 0.5 * r.width - scale * 0.5 * (x0 + x1), r.y + 0.5 * r.height + scale * 0.5 * (y0 + y1)};
}

}  // namespace sl::render

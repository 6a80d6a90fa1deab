#include "render/plane_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace sl {

namespace {

bool inDisc(double x, double y, double cx, double radius) {
  return (x - cx) * (x - cx) + y * y <= radius * radius * (1 + 1e-12);
}

// Highest point of the lens {|p| <= a} and {|p - (L, 0)| <= b}: the top of one disc if it lies in
// the other, else where the two circles cross.
double lensHeight(double a, double b, double base) {
  double height = 0;
  if (inDisc(0, a, base, b)) height = std::max(height, a);
  if (inDisc(base, b, 0, a)) height = std::max(height, b);
  const double x = (a * a - b * b + base * base) / (2 * base);
  if (a * a - x * x > 0) height = std::max(height, std::sqrt(a * a - x * x));
  return height;
}

struct Box {
  double x0 = 0, x1 = 0, y0 = -0.3, y1 = 0.3;
};

void holdChain(int rods, double base, Box& box) {
  box.x1 = std::max(box.x1, base);
  for (int k = 1; k < rods; ++k) {  // hinge k: within k of the left pin and n-k of the right one
    const double a = k, b = rods - k;
    box.x0 = std::min(box.x0, inDisc(-a, 0, base, b) ? -a : base - b);
    box.x1 = std::max(box.x1, inDisc(base + b, 0, 0, a) ? base + b : a);
    const double height = lensHeight(a, b, base);
    box.y0 = std::min(box.y0, -height);
    box.y1 = std::max(box.y1, height);
  }
}

PlaneView fitBox(const Box& box, const PixelRect& r) {
  const auto [x0, x1, y0, y1] = box;
  // 8% of each side, and at least 6 pixels: side-by-side chains in small frames never touch their neighbours.
  const double marginX = std::max(0.08 * r.width, 6.0), marginY = std::max(0.08 * r.height, 6.0);
  const double scale = std::max(1e-3, std::min((r.width - 2 * marginX) / (x1 - x0), (r.height - 2 * marginY) / (y1 - y0)));
  const double originY = r.y + 0.5 * r.height + scale * 0.5 * (y0 + y1);
  return {scale, r.x + 0.5 * r.width - scale * 0.5 * (x0 + x1), originY, float(originY - scale * y0)};
}

}  // namespace

PlaneView fitChainView(int rods, double base, const PixelRect& area) {
  Box box;
  holdChain(rods, base, box);
  return fitBox(box, area);
}

// The part of the plane the motion sweeps (FrameState::linkageBox), with room round it for the drawn joints, the
// pins and the floor's hatching: a fraction of its larger side, and at least a third of a rod.
Box sweptBox(const std::array<double, 4>& swept) {
  const auto [x0, x1, y0, y1] = swept;
  const double pad = std::max(1.0 / 3.0, 0.06 * std::max(x1 - x0, y1 - y0));
  return {x0 - pad, x1 + pad, y0 - pad, y1 + pad};
}

PlaneView fitFrameView(const FrameState& frame, const PixelRect& area, float captionHeight) {
  Box box;
  if (frame.linkageBox) {
    box = sweptBox(*frame.linkageBox);
  } else {
    for (const RunFrame& run : frame.runs) holdChain(frame.rods, run.baseLength, box);
    if (frame.runs.empty()) holdChain(frame.rods, frame.rods - 1, box);
  }
  PixelRect chains = area;
  chains.height = std::max(1.0f, area.height - captionHeight);
  return fitBox(box, chains);
}

}  // namespace sl

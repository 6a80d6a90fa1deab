#pragma once
// Small frames and settings shared by the renderer tests.

#include <string>
#include <vector>

#include "render/renderer.hpp"

namespace sl::testing {

constexpr int kWidth = 320, kHeight = 180;
constexpr ImageSize kSmallSize{kWidth, kHeight};

// For 320x180: text band on top, sphere left, linkage and plot stacked on the right.
ViewSettings smallSettings();

struct NamedFrame {
  std::string name;
  FrameState state;
};
// The frames kept under tests/data/frames: several runs, a stopped run, fading paths, 3 view spaces.
std::vector<NamedFrame> referenceFrames();

// Colour of pixel (x, y) as 0..255 channels.
struct Rgb8 {
  int r, g, b;
};
Rgb8 pixel(const Image& image, int x, int y);

}  // namespace sl::testing

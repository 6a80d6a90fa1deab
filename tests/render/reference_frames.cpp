#include "reference_frames.hpp"

#include "fixtures/synthetic_frame.hpp"

namespace sl::testing {

ViewSettings smallSettings() {
  ViewSettings s;
  s.pathFadeSeconds = 4;
  PanelSpec text{PanelKind::Text, std::array<double, 4>{0, 0, 1, 0.15}, 0};
  PanelSpec sphere{PanelKind::Sphere, std::array<double, 4>{0, 0.15, 0.5, 0.85}, 0};
  PanelSpec linkage{PanelKind::Linkage, std::array<double, 4>{0.5, 0.15, 0.5, 0.4}, 0};
  PanelSpec plot{PanelKind::Plot, std::array<double, 4>{0.5, 0.55, 0.5, 0.45}, 1};
  s.panels = {text, sphere, linkage, plot};
  s.linkageLayout = LinkageLayout::SideBySide;
  return s;
}

std::vector<NamedFrame> referenceFrames() {
  SyntheticOptions stopping;
  stopping.stopSecondRun = true;
  SyntheticOptions ball;
  ball.viewSpace = ViewSpace::Ball;
  SyntheticOptions circle;
  circle.viewSpace = ViewSpace::Circle;
  circle.runs = 1;
  return {{"sphere_t2", syntheticFrame(2.0, 120)},
          {"stopped_t7", syntheticFrame(7.0, 420, stopping)},
          {"ball_t4", syntheticFrame(4.0, 240, ball)},
          {"circle_t4", syntheticFrame(4.0, 240, circle)}};
}

Rgb8 pixel(const Image& image, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 3;
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

}  // namespace sl::testing

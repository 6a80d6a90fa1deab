#include "render/frame_composer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "contracts/limits.hpp"
#include "render/panel_layout.hpp"
#include "render/panels.hpp"

namespace sl {
namespace {


ImageSize checkedSize(ImageSize size) {
  const auto inside = [](int side) { return side >= limits::kMinImageSide && side <= limits::kMaxImageSide; };
  if (!inside(size.width) || !inside(size.height))
    throw std::invalid_argument("frame size " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                                " outside " + std::to_string(limits::kMinImageSide) + ".." +
                                std::to_string(limits::kMaxImageSide));
  return size;
}

// Small, Normal and Title text scale with the frame's shorter side (15, 18 and 24 px at 1280x720 and at
// 720x1280), so portrait frames get the text of the landscape frame of the same width.
std::array<float, 3> textHeights(ImageSize size) {
  const float side = static_cast<float>(std::min(size.width, size.height));
  return {std::max(10.0f, 0.021f * side), std::max(10.0f, 0.025f * side), std::max(11.0f, 0.034f * side)};
}

}  // namespace

FrameComposer::FrameComposer(const ViewSettings& view, ImageSize size)
    : view_(view),
      size_(checkedSize(size)),
      panels_(effectivePanels(view)),
      font_(kFramesFontPath, textHeights(size_), int(std::floor(markUnit(frameUnit(size_))))),
      rects_(layoutPanels(panels_, size_.width, size_.height, titleLineShown() ? titleLineHeight(font_) : 0)) {}

bool FrameComposer::titleLineShown() const {
  return view_.titleLine &&
         std::none_of(panels_.begin(), panels_.end(), [](const PanelSpec& p) { return p.kind == PanelKind::Text; });
}

DrawList FrameComposer::compose(const FrameState& frame) const {
  DrawList list;
  list.size = size_;
  list.background = view_.background;
  list.antialias = view_.antialias;
  list.sphereIsStatic = frame.cameraDirection || view_.camera.orbitDegreesPerSecond == 0;
  list.viewSpace = frame.viewSpace;
  list.sphereDecoration = frame.sphereDecoration;
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    PanelDrawing drawing;
    drawing.rect = rects_[i];
    const PanelContext context{frame, view_, font_, rects_[i], frameUnit(size_)};
    switch (panels_[i].kind) {
      case PanelKind::Linkage:
        drawLinkagePanel(context, drawing.shapes);
        break;
      case PanelKind::Sphere:
        drawing.sphere = drawSpherePanel(context, drawing.shapes);
        break;
      case PanelKind::Plot:
        drawPlotPanel(context, panels_[i].plotIndex, drawing.shapes);
        break;
      case PanelKind::Text:
        drawTextPanel(context, drawing.shapes);
        break;
    }
    list.panels.push_back(std::move(drawing));
  }
  if (titleLineShown()) {  // every frame says what it shows and when, text panel or not
    PanelDrawing drawing;
    drawing.rect = {0, 0, float(size_.width), float(size_.height)};
    drawTitleLine(PanelContext{frame, view_, font_, drawing.rect, frameUnit(size_)}, drawing.shapes);
    list.panels.push_back(std::move(drawing));
  }
  return list;
}

}  // namespace sl

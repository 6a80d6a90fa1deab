#pragma once
// The CPU part of the renderer: lays out the panels once, keeps the glyph atlas, and turns each FrameState
// into a DrawList. No OpenGL here.

#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/image.hpp"
#include "contracts/view_settings.hpp"
#include "render/draw_list.hpp"
#include "render/font_atlas.hpp"

namespace sl {

class FrameComposer {
 public:
  // Throws std::invalid_argument for a size outside contracts/limits.hpp, std::runtime_error if the font
  // cannot be read.
  FrameComposer(const ViewSettings& view, ImageSize size);

  DrawList compose(const FrameState& frame) const;

  const FontAtlas& font() const { return font_; }
  const std::vector<PanelSpec>& panels() const { return panels_; }
  const std::vector<PixelRect>& rects() const { return rects_; }

 private:
  // Without a text panel the title and the time go across the top (unless view.title_line is off), in a band
  // the automatic layout keeps free.
  bool titleLineShown() const;

  ViewSettings view_;
  ImageSize size_;
  std::vector<PanelSpec> panels_;
  FontAtlas font_;
  std::vector<PixelRect> rects_;
};

}  // namespace sl

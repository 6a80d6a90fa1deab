#pragma once
// The linkage panel's view: plane coordinates (rod lengths, y up) to pixels, fixed per scene (from the part of
// the plane the whole motion sweeps, or from n and L alone) so the picture never jumps as the chain moves.

#include "contracts/frame_state.hpp"
#include "render/shape_batch.hpp"
#include "render/sphere_camera.hpp"

namespace sl {

struct PlaneView {
  double scale, originX, originY;
  float boxBottom = 0;  // the pixel row below which no configuration of the fitted chains reaches (captions go there)
  P2 operator()(double x, double y) const { return {float(originX + scale * x), float(originY - scale * y)}; }
  P2 operator()(const Vec2& p) const { return (*this)(p.x, p.y); }
};

// Fits the box holding every configuration of the chain (hinge k lies within k of the left pin and
// within n-k of the right one) into `area`, with a margin.
PlaneView fitChainView(int rods, double baseLength, const PixelRect& area);

// The view of a frame's linkage panel: one box holding the part of the plane the whole motion sweeps
// (FrameState::linkageBox) or, without it, every configuration of every run's chain (runs may differ in L), so that
// all runs are drawn at one scale, the chains fill the panel and the picture never jumps.
// `captionHeight` pixels at the area's foot are kept for a caption (side-by-side runs are named underneath).
PlaneView fitFrameView(const FrameState& frame, const PixelRect& area, float captionHeight = 0);

}  // namespace sl

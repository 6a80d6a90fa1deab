#pragma once
// The camera of the sphere panel: a perspective view of the unit sphere from
// CameraSpec::viewDirection, orbiting about the vertical (z) axis. Projection happens on the CPU (the
// shapes are drawn in pixels); the shaders get the same basis to cast per-pixel rays, so both agree.

#include "contracts/frame_state.hpp"
#include "contracts/view_settings.hpp"
#include "render/shape_batch.hpp"

namespace sl {

struct PixelRect {
  float x = 0, y = 0, width = 0, height = 0;  // pixels, y down
};

class SphereCamera {
 public:
  // The camera frames a sphere of radius `fitRadius` about the origin in `panel`.
  SphereCamera(const CameraSpec& spec, double time, const PixelRect& panel, double fitRadius = 1.0);

  P2 project(const Vec3& p) const;              // pixel position
  double pixelsPerUnitAt(const Vec3& p) const;  // scale of a small object at p
  bool inFront(const Vec3& p) const;            // in front of the eye plane
  Vec3 eye() const { return eye_; }
  // The eye's distance from the centre as the camera chose it (from the panel and the field of view alone, exactly
  // the same for every direction; |eye()| may differ from it in the last bits).
  double distance() const { return distance_; }
  // The sphere's outline on the screen: a circle about centre() of this radius in pixels (the eye looks at the
  // centre; the sight lines tangent to the unit sphere make the half angle asin(1 / |eye|)).
  double outlineRadius() const;

  // Shader uniforms: eye, forward * focal, right, up (world), panel centre (pixels).
  const Vec3& forward() const { return forward_; }
  const Vec3& right() const { return right_; }
  const Vec3& up() const { return up_; }
  double focal() const { return focal_; }
  P2 centre() const { return centre_; }

 private:
  Vec3 eye_, forward_, right_, up_;
  double focal_ = 1, distance_ = 1;
  P2 centre_;
};

// The camera of a frame: the direction the frames stage planned for it (FrameState::cameraDirection, a directed
// camera), not orbiting; else the scene's.
CameraSpec cameraOfFrame(const CameraSpec& spec, const FrameState& frame);

}  // namespace sl

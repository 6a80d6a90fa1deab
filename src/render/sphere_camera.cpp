#include "render/sphere_camera.hpp"

#include <algorithm>
#include <cmath>

#include "contracts/limits.hpp"
#include "contracts/vec3_algebra.hpp"

namespace sl {

SphereCamera::SphereCamera(const CameraSpec& spec, double time, const PixelRect& panel, double fitRadius) {
  const double pi = std::acos(-1.0);
  Vec3 direction = spec.viewDirection;
  if (!(dot(direction, direction) > 1e-12)) direction = CameraSpec{}.viewDirection;  // a hand-built zero: the default
  direction = normalized(direction);
  const double orbit = spec.orbitDegreesPerSecond * time * pi / 180.0;
  const double c = std::cos(orbit), s = std::sin(orbit);
  direction = {c * direction.x - s * direction.y, s * direction.x + c * direction.y, direction.z};

  const double shortSide = std::min(panel.width, panel.height);
  // The scene loader refuses other angles; the clamp keeps a hand-built ViewSettings drawable.
  const double fov =
      std::clamp(spec.fieldOfViewDegrees, limits::kMinFieldOfViewDegrees, limits::kMaxFieldOfViewDegrees) * pi / 180.0;
  focal_ = 0.5 * shortSide / std::tan(0.5 * fov);
  // Silhouette radius in pixels of a sphere of radius R at distance D is f R / sqrt(D^2 - R^2):
  // choose D so the sphere fills 88% of the short side.
  const double silhouette = 0.44 * shortSide;
  const double distance = fitRadius * std::sqrt(1.0 + (focal_ / silhouette) * (focal_ / silhouette));
  distance_ = distance;
  eye_ = distance * direction;
  forward_ = -1.0 * direction;
  const Vec3 vertical = std::abs(direction.z) > 0.999 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  right_ = normalized(cross(forward_, vertical));
  up_ = cross(right_, forward_);
  centre_ = {panel.x + 0.5f * panel.width, panel.y + 0.5f * panel.height};
}

CameraSpec cameraOfFrame(const CameraSpec& spec, const FrameState& frame) {
  if (!frame.cameraDirection) return spec;
  CameraSpec directed = spec;
  directed.viewDirection = *frame.cameraDirection;
  directed.orbitDegreesPerSecond = 0;
  return directed;
}

P2 SphereCamera::project(const Vec3& p) const {
  const Vec3 v = p - eye_;
  const double depth = std::max(dot(v, forward_), 1e-6);
  return {static_cast<float>(centre_.x + focal_ * dot(v, right_) / depth),
          static_cast<float>(centre_.y - focal_ * dot(v, up_) / depth)};
}

double SphereCamera::pixelsPerUnitAt(const Vec3& p) const { return focal_ / std::max(dot(p - eye_, forward_), 1e-6); }

bool SphereCamera::inFront(const Vec3& p) const { return dot(p - eye_, forward_) > 1e-3; }

double SphereCamera::outlineRadius() const {
  const double d2 = dot(eye_, eye_);
  return focal_ / std::sqrt(std::max(d2 - 1.0, 1e-12));
}

}  // namespace sl

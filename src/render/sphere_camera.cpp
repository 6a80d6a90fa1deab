#include "render/sphere_camera.hpp"

#include <algorithm>
#include <cmath>

#include "contracts/limits.hpp"

namespace sl {
namespace {

V3 operator*(double s, const V3& v) { return {s * v.x, s * v.y, s * v.z}; }
V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(const V3& a, const V3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 normalized(const V3& v) { return (1.0 / std::sqrt(dot(v, v))) * v; }

}  // namespace

SphereCamera::SphereCamera(const CameraSpec& spec, double time, const PixelRect& panel, double fitRadius) {
  const double pi = std::acos(-1.0);
  V3 direction{spec.viewDirection.x, spec.viewDirection.y, spec.viewDirection.z};
  if (!(dot(direction, direction) > 1e-12)) {  // a hand-built zero direction: the default view
    const Vec3 fallback = CameraSpec{}.viewDirection;
    direction = {fallback.x, fallback.y, fallback.z};
  }
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
  const V3 vertical = std::abs(direction.z) > 0.999 ? V3{0, 1, 0} : V3{0, 0, 1};
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

P2 SphereCamera::project(const V3& p) const {
  const V3 v = p - eye_;
  const double depth = std::max(dot(v, forward_), 1e-6);
  return {static_cast<float>(centre_.x + focal_ * dot(v, right_) / depth),
          static_cast<float>(centre_.y - focal_ * dot(v, up_) / depth)};
}

double SphereCamera::pixelsPerUnitAt(const V3& p) const { return focal_ / std::max(dot(p - eye_, forward_), 1e-6); }

bool SphereCamera::inFront(const V3& p) const { return dot(p - eye_, forward_) > 1e-3; }

double SphereCamera::outlineRadius() const {
  const double d2 = dot(eye_, eye_);
  return focal_ / std::sqrt(std::max(d2 - 1.0, 1e-12));
}

}  // namespace sl

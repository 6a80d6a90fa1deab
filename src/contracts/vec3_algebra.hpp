#pragma once
// The few operations on a space point that the frames stage (the directed camera) and the renderer (the sphere's
// camera and grid) need, written once. The numerical stages use Eigen; these stay on the plain Vec3 that the
// frame state carries, so that neither the camera plan nor the renderer converts to draw.

#include <cmath>

#include "contracts/values.hpp"

namespace sl {

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, const Vec3& v) { return {s * v.x, s * v.y, s * v.z}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline Vec3 normalized(const Vec3& v) { return (1.0 / std::sqrt(dot(v, v))) * v; }

}  // namespace sl

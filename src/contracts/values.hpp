#pragma once
// The value vocabulary every stage shares: plane and space points, colours. Plain aggregates, no behaviour but
// exact equality.

namespace sl {

struct Vec2 {
  double x = 0, y = 0;
};
struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Vec3&, const Vec3&) = default;  // exact (a NaN equals nothing)
};
struct ColorRGB {
  float r = 0, g = 0, b = 0;  // each 0..1
  friend bool operator==(const ColorRGB&, const ColorRGB&) = default;  // exact
};

}  // namespace sl

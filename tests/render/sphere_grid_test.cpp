// The sphere's chart grid as lines (render/sphere_grid.hpp): the same picture at every frame size, a sparser grid on
// a small ball, and a pole cap only where the pole faces the camera.

#include <gtest/gtest.h>

#include <cmath>

#include "render/draw_list.hpp"
#include "render/sphere_grid.hpp"

namespace sl {
namespace {

const double kPi = std::acos(-1.0);

SphereCamera cameraFor(ImageSize size, Vec3 direction = {1, 0.3, 0.4}) {
  CameraSpec spec;
  spec.viewDirection = direction;
  return SphereCamera(spec, 0, PixelRect{0, 0, float(size.width), float(size.height)});
}

// Covered area of the ribbons (two triangles a quad; each quad's area at its half width, without the margin),
// in pixels: length times width summed over the strips.
double ribbonArea(const ShapeBatch& batch) {
  double area = 0;
  const auto& v = batch.vertices();
  for (std::size_t q = 0; q + 5 < v.size(); q += 6) {
    if (v[q].kind != 0) continue;
    // Quad corners a(-), b(-), b(+), a(+) as two triangles (a-, b-, b+), (a-, b+, a+): the axis runs between the
    // mid points of the two ends.
    const double ax = 0.5 * (v[q].x + v[q + 5].x), ay = 0.5 * (v[q].y + v[q + 5].y);
    const double bx = 0.5 * (v[q + 1].x + v[q + 2].x), by = 0.5 * (v[q + 1].y + v[q + 2].y);
    area += std::hypot(bx - ax, by - ay) * 2 * v[q].size;
  }
  return area;
}

TEST(SphereGrid, StepFollowsTheBallsRadiusInFrameUnits) {
  EXPECT_DOUBLE_EQ(sphereGridStep(280, 1.0f), 15 * kPi / 180);   // 1280x720, one sphere panel
  EXPECT_DOUBLE_EQ(sphereGridStep(70, 0.25f), 15 * kPi / 180);   // the same ball at 320x180
  EXPECT_DOUBLE_EQ(sphereGridStep(840, 3.0f), 15 * kPi / 180);   // and at 3840x2160
  EXPECT_DOUBLE_EQ(sphereGridStep(60, 1.0f), 30 * kPi / 180);    // a small ball in a crowded layout
  EXPECT_DOUBLE_EQ(sphereGridStep(20, 1.0f), 45 * kPi / 180);
  // Lines never closer than kMinGridSpacingUnits at the ball's centre, unless the sparsest step is reached.
  for (double radius = 10; radius < 400; radius += 7) {
    const double step = sphereGridStep(radius, 1.0f);
    if (step < 45 * kPi / 180) {
      EXPECT_GE(radius * step, kMinGridSpacingUnits) << radius;
    }
  }
}

TEST(SphereGrid, RibbonsCoverTheSameShareOfTheBallAtEverySize) {
  // Covered area over the ball's area: the same at 320x180, 1280x720 and 3840x2160 (widths and chords in frame
  // units), within 2% (the polylines' chords are chosen per size).
  double shares[3];
  const ImageSize sizes[3] = {{320, 180}, {1280, 720}, {3840, 2160}};
  for (int k = 0; k < 3; ++k) {
    const SphereCamera camera = cameraFor(sizes[k]);
    const double radius = sphereOutlinePixels(camera);
    ShapeBatch batch;
    drawSphereGrid(batch, camera, frameUnit(sizes[k]), sphereGridStep(radius, frameUnit(sizes[k])));
    shares[k] = ribbonArea(batch) / (kPi * radius * radius);
  }
  EXPECT_GT(shares[1], 0.02);
  EXPECT_LT(shares[1], 0.06);
  EXPECT_NEAR(shares[0] / shares[1], 1.0, 0.02);
  EXPECT_NEAR(shares[2] / shares[1], 1.0, 0.02);
}

TEST(SphereGrid, OnlyAPoleFacingTheCameraGetsACap) {
  for (const double z : {1.0, -1.0}) {
    const SphereCamera camera = cameraFor({1280, 720}, {0, 0.01, z});  // above one pole, the other hidden
    ShapeBatch batch;
    drawSphereGrid(batch, camera, 1.0f, 15 * kPi / 180);
    int caps = 0;
    for (const ShapeVertex& v : batch.vertices())
      if (v.kind == 1) {
        ++caps;
        EXPECT_LT(std::hypot(v.x - camera.centre().x, v.y - camera.centre().y), 40.0);  // about the visible pole
      }
    EXPECT_EQ(caps, 6) << z;  // one square
  }
  // Seen along the equator both poles lie on the limb, where the parallels' caps would be cut to nothing.
  ShapeBatch side;
  drawSphereGrid(side, cameraFor({1280, 720}, {1, 0, 0}), 1.0f, 15 * kPi / 180);
  for (const ShapeVertex& v : side.vertices()) EXPECT_EQ(v.kind, 0.0f);
}

}  // namespace
}  // namespace sl

// Geometry of the panels, checked against independent routes: the linkage view holds every
// configuration the chart Psi can produce, the automatic layout tiles the frame, and the sphere camera's
// projection agrees with its own per-pixel rays.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "linkage/chart.hpp"
#include "render/panel_layout.hpp"
#include "render/plane_view.hpp"
#include "render/sphere_camera.hpp"

namespace sl {
namespace {

TEST(LinkageView, EveryConfigurationFitsInsideThePanel) {
  std::mt19937 random(3);
  std::normal_distribution<double> gaussian;
  const PixelRect panel{100, 50, 400, 300};
  for (int rods : {3, 4, 5, 6}) {
    for (double base : {rods - 1.9, rods - 1.0, rods - 0.1}) {
      const Chain chain = Chain::uniform(rods, base);
      const PlaneView view = fitChainView(rods, base, panel);
      for (int sample = 0; sample < 400; ++sample) {
        Eigen::VectorXd x(rods - 1);
        for (int i = 0; i < x.size(); ++i) x(i) = gaussian(random);
        const Eigen::Matrix2Xd hinges = hingePositionsAt(chain, x.normalized());
        for (int k = 0; k < hinges.cols(); ++k) {
          const P2 p = view(hinges(0, k), hinges(1, k));
          ASSERT_TRUE(p.x >= panel.x && p.x <= panel.x + panel.width && p.y >= panel.y && p.y <= panel.y + panel.height)
              << "n = " << rods << ", L = " << base << ", hinge " << k + 1;
        }
      }
    }
  }
}

TEST(LinkageView, IsTightForFourRods) {
  const PixelRect panel{0, 0, 400, 300};
  const PlaneView view = fitChainView(4, 3.0, panel);
  // n = 4, L = 3: hinges stay within x in [0, 3]; the highest, hinge 2, sits where the circles of
  // radius 2 about both pins cross, y = sqrt(4 - 1.5^2). The height limits: 2y fills 84% of 300 px.
  const double height = 2 * std::sqrt(4 - 1.5 * 1.5);
  EXPECT_NEAR(view.scale * height, 300 * 0.84, 1e-9);
  EXPECT_NEAR(view(1.5, 0).x, 200, 1e-3);  // centred
}

// Portrait frames stack: the first panel across the top (square, at most 55% of the height below the text
// band), the rest in full-width rows below; the text band scales with the shorter side.
TEST(PanelLayout, PortraitFramesStackThePanels) {
  std::vector<PanelSpec> panels(4);
  panels[0].kind = PanelKind::Text;
  panels[1].kind = PanelKind::Sphere;
  panels[2].kind = PanelKind::Linkage;
  panels[3].kind = PanelKind::Plot;
  const auto rects = layoutPanels(panels, 1080, 1920);
  EXPECT_FLOAT_EQ(rects[0].height, std::round(0.14f * 1080));
  EXPECT_FLOAT_EQ(rects[1].width, 1080);
  EXPECT_FLOAT_EQ(rects[1].height, std::round(0.55f * (1920 - rects[0].height)));
  EXPECT_FLOAT_EQ(rects[1].y, rects[0].height);
  for (int i : {2, 3}) {
    EXPECT_FLOAT_EQ(rects[i].x, 0);
    EXPECT_FLOAT_EQ(rects[i].width, 1080);
  }
  EXPECT_FLOAT_EQ(rects[2].y, rects[1].y + rects[1].height);
  EXPECT_FLOAT_EQ(rects[3].y + rects[3].height, 1920);
  // The same panels in landscape keep the side-by-side layout.
  const auto wide = layoutPanels(panels, 1920, 1080);
  EXPECT_LT(wide[1].width, 1920);
  EXPECT_FLOAT_EQ(wide[2].x, wide[1].width);
}

TEST(PanelLayout, AutomaticLayoutTilesTheFrame) {
  std::vector<PanelSpec> panels(4);
  panels[0].kind = PanelKind::Text;
  panels[1].kind = PanelKind::Sphere;
  panels[2].kind = PanelKind::Linkage;
  panels[3].kind = PanelKind::Plot;
  const auto rects = layoutPanels(panels, 1280, 720);
  double area = 0;
  for (const auto& r : rects) {
    area += double(r.width) * r.height;
    EXPECT_GE(r.x, 0);
    EXPECT_GE(r.y, 0);
    EXPECT_LE(r.x + r.width, 1280);
    EXPECT_LE(r.y + r.height, 720);
  }
  EXPECT_DOUBLE_EQ(area, 1280.0 * 720.0);  // no gaps, no overlaps (all inside, areas add up)
  EXPECT_EQ(rects[0].y, 0);                // the text band on top
  EXPECT_EQ(rects[1].x, 0);                // the sphere on the left
}

// A reserved band across the top (the title line's) stays free of automatically placed panels, which still tile
// the rest of the frame; explicit rects are the scene's own.
TEST(PanelLayout, AReservedTopBandStaysFree) {
  std::vector<PanelSpec> panels(3);
  panels[0].kind = PanelKind::Sphere;
  panels[1].kind = PanelKind::Linkage;
  panels[2].kind = PanelKind::Plot;
  for (auto [w, h] : {std::pair{1280, 720}, std::pair{720, 1280}}) {
    const auto rects = layoutPanels(panels, w, h, 24.4f);
    double area = 0;
    for (const auto& r : rects) {
      EXPECT_GE(r.y, 24);
      EXPECT_LE(r.y + r.height, h);
      area += double(r.width) * r.height;
    }
    EXPECT_DOUBLE_EQ(area, double(w) * (h - 24));
  }
}

// The automatic landscape split, as the shipped scenes without rects see it: the first panel takes 56% of the
// width (rounded to a pixel), the others share the column to its right, one above the other.
TEST(PanelLayout, TheDefaultLandscapeSplitGivesTheFirstPanel56PercentOfTheWidth) {
  std::vector<PanelSpec> panels(3);
  panels[0].kind = PanelKind::Sphere;
  panels[1].kind = PanelKind::Linkage;
  panels[2].kind = PanelKind::Plot;
  const auto two = layoutPanels({panels[0], panels[1]}, 1280, 720);
  EXPECT_EQ(two[0].x, 0);
  EXPECT_EQ(two[0].width, 717);  // round(0.56 * 1280)
  EXPECT_EQ(two[0].height, 720);
  EXPECT_EQ(two[1].x, 717);
  EXPECT_EQ(two[1].width, 1280 - 717);
  EXPECT_EQ(two[1].height, 720);
  const auto three = layoutPanels(panels, 320, 180);
  EXPECT_EQ(three[0].width, 179);  // round(0.56 * 320)
  EXPECT_EQ(three[1].y, 0);
  EXPECT_EQ(three[1].height, 90);
  EXPECT_EQ(three[2].y, 90);
  EXPECT_EQ(three[2].height, 90);
  EXPECT_EQ(layoutPanels({panels[0]}, 1280, 720)[0].width, 1280) << "a single panel takes the whole frame";
}

TEST(PanelLayout, ExplicitRectsAreKept) {
  std::vector<PanelSpec> panels(1);
  panels[0].rect = std::array<double, 4>{0.25, 0.5, 0.5, 0.5};
  const auto rects = layoutPanels(panels, 200, 100);
  EXPECT_EQ(rects[0].x, 50);
  EXPECT_EQ(rects[0].y, 50);
  EXPECT_EQ(rects[0].width, 100);
  EXPECT_EQ(rects[0].height, 50);
}

// The CPU projection (used for shapes) and the per-pixel ray (used by the shaders, written out here
// with the same uniforms) must agree: the ray through a projected point passes through the point.
TEST(SphereCamera, ProjectionAgreesWithPixelRays) {
  CameraSpec spec;
  spec.orbitDegreesPerSecond = 10;
  const SphereCamera camera(spec, 4.0, PixelRect{10, 20, 600, 400});
  for (Vec3 p : {Vec3{1, 0, 0}, Vec3{0.3, -0.8, 0.52}, Vec3{0, 0, 1}, Vec3{-0.2, 0.1, -0.4}}) {
    const P2 pixel = camera.project(p);
    const Vec3 f = camera.forward(), r = camera.right(), u = camera.up(), e = camera.eye();
    const double fx = camera.focal(), dx = pixel.x - camera.centre().x, dy = pixel.y - camera.centre().y;
    Vec3 ray{f.x * fx + r.x * dx - u.x * dy, f.y * fx + r.y * dx - u.y * dy, f.z * fx + r.z * dx - u.z * dy};
    const Vec3 toPoint{p.x - e.x, p.y - e.y, p.z - e.z};
    const double rayNorm = std::sqrt(ray.x * ray.x + ray.y * ray.y + ray.z * ray.z);
    const double pointNorm = std::sqrt(toPoint.x * toPoint.x + toPoint.y * toPoint.y + toPoint.z * toPoint.z);
    const double cosine = (ray.x * toPoint.x + ray.y * toPoint.y + ray.z * toPoint.z) / (rayNorm * pointNorm);
    EXPECT_NEAR(cosine, 1.0, 1e-9);
  }
  // The unit sphere fills 88% of the short side: its silhouette radius is 0.44 * 400 pixels.
  const double distance =
      std::sqrt(camera.eye().x * camera.eye().x + camera.eye().y * camera.eye().y + camera.eye().z * camera.eye().z);
  EXPECT_NEAR(camera.focal() / std::sqrt(distance * distance - 1), 0.44 * 400, 1e-6);
}

}  // namespace
}  // namespace sl

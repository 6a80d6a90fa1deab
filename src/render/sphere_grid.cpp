#include "render/sphere_grid.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "contracts/vec3_algebra.hpp"
#include "render/palette.hpp"

namespace sl {
namespace {

// Pixels a joined section of a grid line may stray from the points it replaces (on top of sphereGridPiece's 0.05).
constexpr float kGridMergeTolerance = 0.05f;

Vec3 chartPoint(double phi, double t) {
  return {std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)};
}

}  // namespace

double sphereOutlinePixels(const SphereCamera& camera) {
  const double d = camera.distance();
  return camera.focal() / std::sqrt(std::max(d * d - 1, 1e-6));
}

double sphereGridStep(double radiusPixels, float unit) {
  const double pi = std::acos(-1.0);
  const double radiusUnits = radiusPixels / std::max(double(unit), 1e-6);
  for (const double degrees : {15.0, 30.0})
    if (radiusUnits * degrees * pi / 180.0 >= kMinGridSpacingUnits) return degrees * pi / 180.0;
  return 45.0 * pi / 180.0;
}

double sphereGridPiece(double radiusPixels) {
  // Chords at most 0.05 px from the circle they stand for: R (1 - cos(a / 2)) ~ R a^2 / 8.
  return std::min(std::sqrt(0.4 / std::max(radiusPixels, 1.0)), std::acos(-1.0) / 30.0);  // at most 6 degrees
}

SphereGridLines::SphereGridLines(double step, double piece) : step_(step), piece_(piece) {
  const double pi = std::acos(-1.0);
  const auto add = [&](auto&& at, double from, double to, float halfWidth, auto&& alphaAt) {
    Line line;
    line.halfWidth = halfWidth;
    const int pieces = std::max(1, int(std::ceil((to - from) / piece)));
    for (int i = 0; i <= pieces; ++i) {
      line.points.push_back(at(from + (to - from) * i / pieces));
      line.alpha.push_back(float(0.75 * alphaAt(line.points.back())));
    }
    lines_.push_back(std::move(line));
  };
  const auto always = [](const Vec3&) { return 1.0; };
  // Parallels phi = k * step up to the last one short of the poles.
  const int parallels = int(std::floor(0.5 * pi / step - 1e-9));
  for (int k = -parallels; k <= parallels; ++k)
    add([&](double t) { return chartPoint(k * step, t); }, -pi, pi, k == 0 ? 0.9f : 0.55f, always);
  // Meridians t = j * step, faded out between |z| = 0.92 and 0.985 where they crowd at the poles.
  const auto fade = [](const Vec3& p) {
    const double s = std::clamp((std::abs(p.z) - 0.92) / (0.985 - 0.92), 0.0, 1.0);
    return 1.0 - s * s * (3 - 2 * s);
  };
  const double reach = std::asin(0.985);
  const int half = int(std::lround(pi / step));
  for (int j = -half + 1; j <= half; ++j)
    add([&](double phi) { return chartPoint(phi, j * step); }, -reach, reach, j == 0 ? 0.9f : 0.55f, fade);
}

std::size_t SphereGridLines::draw(ShapeBatch& batch, const SphereCamera& camera, float unit) const {
  const std::size_t first = batch.vertices().size();
  const Vec3 eye = camera.eye();
  const double distance = camera.distance();
  const Vec3 towardsEye{eye.x / distance, eye.y / distance, eye.z / distance};
  // A point is in front where dot(p, towardsEye) >= 1 / D (the limb); a line runs a little past it so that its
  // end is cut by the outline's anti-aliasing (sphere_grid.frag), not by the polyline.
  const double past = 1.0 / distance - 0.02;
  std::vector<PolylinePoint> run;
  const auto flush = [&] {
    // Most lines bend far less on screen than the chord length allows for (a meridian seen edge-on is straight):
    // sections that stay within kGridMergeTolerance of a longer chord are joined, fewer quads for the same line.
    mergeStraightRuns(run, kGridMergeTolerance);
    if (run.size() >= 2) batch.polyline(run);
    run.clear();
  };
  for (const Line& line : lines_) {
    for (std::size_t i = 0; i < line.points.size(); ++i) {
      const Vec3& p = line.points[i];
      if (dot(p, towardsEye) < past) {
        flush();
        continue;
      }
      Rgba color = palette::sphereGrid;
      color.a = line.alpha[i];
      run.push_back({camera.project(p), line.halfWidth * unit, color, {}});
    }
    flush();
  }
  const std::size_t ribbons = batch.vertices().size() - first;
  // The chart's poles: squares about the caps (0.035 of the radius on the surface, at most about 10 frame units;
  // sphere_grid.frag measures them), with room for their anti-aliased edge where the limb foreshortens them.
  for (const double z : {-1.0, 1.0}) {
    const Vec3 pole{0, 0, z};
    if (dot(pole, towardsEye) < past - 0.05) continue;
    batch.disc(camera.project(pole), float(0.035 * camera.pixelsPerUnitAt(pole)) + 8.0f, palette::poleMark);
  }
  return ribbons;
}

void drawSphereGrid(ShapeBatch& batch, const SphereCamera& camera, float unit, double step) {
  SphereGridLines(step, sphereGridPiece(sphereOutlinePixels(camera))).draw(batch, camera, unit);
}

}  // namespace sl

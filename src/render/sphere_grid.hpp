#pragma once
// The (phi, t) chart grid of the opaque configuration sphere as lines: the parallels phi = k * step and meridians
// t = j * step on the side facing the camera, projected to pixels, and a cap at each chart pole (where t is
// undefined). The GL part draws them with shaders/sphere_grid.frag over the cached plain ball, lit and cut by the
// sphere's outline per pixel; the coloured sphere draws the same grid analytically in shaders/sphere.frag.
//
// Everything is in units of the frame (render::frameUnit, pixels per 720 px of the shorter side), so that a frame at
// any size shows the same grid: line half widths 0.55 units (0.9 for the equator and the meridian t = 0), caps of
// radius 7 sqrt(2) units at most, and the number of lines chosen from the ball's radius in frame units: lines every
// 15 degrees while they lie at least kMinGridSpacingUnits apart at the ball's centre, else every 30, else 45 (a small
// ball in a crowded layout gets a sparser grid, never a net). Lines thinner than a pixel (at small sizes) are
// fainter, not wider (bandCoverage), so a box-downscaled large frame and a small frame cover as much of the ball.

#include <vector>

#include "render/shape_batch.hpp"
#include "render/sphere_camera.hpp"

namespace sl {

// Frame units between neighbouring grid lines at the ball's centre below which the grid gets sparser.
inline constexpr double kMinGridSpacingUnits = 24.0;

// Radians between grid lines (in phi and in t) for a ball of `radiusPixels` in a frame of `unit` pixels per unit.
double sphereGridStep(double radiusPixels, float unit);

// The ball's outline radius in pixels as `camera` sees the unit sphere.
double sphereOutlinePixels(const SphereCamera& camera);

// Radians along a grid line between polyline points, for a ball of `radiusPixels`: chords within 0.05 px.
double sphereGridPiece(double radiusPixels);

// The grid's lines on the unit sphere (world points, widths in frame units, shares of the line colour), computed
// once for a step and a chord length; drawn for each camera by projecting the visible points.
class SphereGridLines {
 public:
  SphereGridLines(double step, double piece);
  // Ribbons along the visible parts of the lines, then squares about the visible poles (drawSphereGrid). Returns
  // how many of the vertices added are the ribbons' (the renderer shades the two parts with two programs).
  std::size_t draw(ShapeBatch& batch, const SphereCamera& camera, float unit) const;
  double step() const { return step_; }
  double piece() const { return piece_; }

 private:
  struct Line {
    std::vector<Vec3> points;
    std::vector<float> alpha;
    float halfWidth;
  };
  double step_, piece_;
  std::vector<Line> lines_;
};

// Ribbons along the visible grid lines (vKind 0, colour palette::sphereGrid, alpha the share of the line colour:
// 0.75, faded near the poles for meridians) followed by discs at the visible poles (kind 1, palette::poleMark).
void drawSphereGrid(ShapeBatch& batch, const SphereCamera& camera, float unit, double step);

}  // namespace sl

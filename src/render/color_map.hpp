#pragma once
// Colour maps for scalar fields and their colour bars. A diverging scale (signed quantities such as the
// Gaussian curvature) is centred at zero and stretches each sign over its own half of the map, so a small
// negative region stays as readable as a large positive one; the bar says so. A sequential scale (bending) is
// viridis: ordered in lightness and readable with the common colour-vision deficiencies.

#include <cstdint>
#include <string>
#include <vector>

#include "contracts/frame_state.hpp"
#include "render/font_atlas.hpp"
#include "render/palette.hpp"
#include "render/shape_batch.hpp"
#include "render/sphere_camera.hpp"

namespace sl {

struct ColorScale {
  double min = 0, max = 1;
  bool diverging = false;

  // Where a value sits on the map, 0..1 (clamped). Diverging: [min, 0] -> [0, 1/2], [0, max] -> [1/2, 1].
  double position(double value) const;
  // The value at a position of the map (the inverse of position inside the data's range).
  double valueAt(double position) const;
  Rgba colorAt(double position) const;
  // The positions the data covers: [position(min), position(max)].
  double lowest() const { return position(min); }
  double highest() const { return position(max); }
};

ColorScale scaleOf(const SphereField& field);

// RGBA8 texels of a field, row-major as the field (rows = phi, columns = t), for the sphere's texture.
std::vector<std::uint8_t> fieldTexels(const SphereField& field);

// Round tick values in [lo, hi] as matplotlib's MaxNLocator picks them: the multiples of the smallest step
// {1, 2, 2.5, 5} x 10^k of which at most maxTicks lie in the range.
std::vector<double> niceTicks(double lo, double hi, int maxTicks);
// A tick value with the decimals its step needs and a true minus sign (U+2212): -0.25 -> "−0.25", 20 -> "20".
std::string tickLabel(double value, double step);

// A vertical colour bar in `area` (its full height; the bar itself is a narrow strip at the area's right),
// with ticks and their values on its left, `label` above and `note` (if any) below. A two-slope (diverging) scale
// marks zero across the bar with a longer tick labelled "scale changes at 0" where the area is wide enough (and
// leaves `note` out then), else "0" with the note. In the page's ink: the bar stands beside the sphere.
void drawColorBar(const ColorScale& scale, const std::string& label, const std::string& note, const PixelRect& area,
                  const FontAtlas& font, const palette::PageInk& page, ShapeBatch& batch);

}  // namespace sl

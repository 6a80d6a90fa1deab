#include "render/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "render/palette.hpp"

namespace sl::render {
namespace {

using Stops = std::array<Rgba, 9>;

// ColorBrewer RdBu (reversed: blue negative, red positive), white at the middle.
constexpr Stops kDiverging{{{0.129f, 0.400f, 0.675f, 1},
                            {0.263f, 0.576f, 0.765f, 1},
                            {0.573f, 0.773f, 0.871f, 1},
                            {0.820f, 0.898f, 0.941f, 1},
                            {0.969f, 0.969f, 0.969f, 1},
                            {0.992f, 0.859f, 0.780f, 1},
                            {0.957f, 0.647f, 0.510f, 1},
                            {0.839f, 0.376f, 0.302f, 1},
                            {0.698f, 0.094f, 0.169f, 1}}};
// viridis at nine evenly spaced positions.
constexpr Stops kSequential{{{0.267f, 0.005f, 0.329f, 1},
                             {0.278f, 0.175f, 0.483f, 1},
                             {0.229f, 0.322f, 0.546f, 1},
                             {0.173f, 0.449f, 0.558f, 1},
                             {0.128f, 0.567f, 0.551f, 1},
                             {0.153f, 0.683f, 0.502f, 1},
                             {0.369f, 0.788f, 0.383f, 1},
                             {0.678f, 0.864f, 0.190f, 1},
                             {0.993f, 0.906f, 0.144f, 1}}};

Rgba interpolate(const Stops& stops, double position) {
  const double x = std::clamp(position, 0.0, 1.0) * (stops.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), stops.size() - 2);
  const float f = static_cast<float>(x - i);
  const Rgba& a = stops[i];
  const Rgba& b = stops[i + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), 1};
}

std::string tickLabel(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return std::string(text) == "-0" ? "0" : text;
}

}  // namespace

double ColorScale::position(double value) const {
  if (!std::isfinite(value)) return 0.5;
  if (!diverging) return max > min ? std::clamp((value - min) / (max - min), 0.0, 1.0) : 0.5;
  if (value < 0) return min < 0 ? 0.5 - 0.5 * std::min(value / min, 1.0) : 0.5;
  return max > 0 ? 0.5 + 0.5 * std::min(value / max, 1.0) : 0.5;
}

double ColorScale::valueAt(double p) const {
  if (!diverging) return min + p * (max - min);
  return p < 0.5 ? (0.5 - p) / 0.5 * min : (p - 0.5) / 0.5 * max;
}

Rgba ColorScale::colorAt(double p) const { return interpolate(diverging ? kDiverging : kSequential, p); }

ColorScale scaleOf(const SphereField& field) { return {field.min, field.max, field.diverging}; }

std::vector<std::uint8_t> fieldTexels(const SphereField& field) {
  const ColorScale scale = scaleOf(field);
  std::vector<std::uint8_t> texels;
  texels.reserve(field.values.size() * 4);
  const auto byte = [](float c) { return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255)); };
  for (float value : field.values) {
    const Rgba c = scale.colorAt(scale.position(value));
    for (float channel : {c.r, c.g, c.b, 1.0f}) texels.push_back(byte(channel));
  }
  return texels;
}

void drawColorBar(const ColorScale& scale, const std::string& label, const std::string& note, const PixelRect& area,
                  const FontAtlas& font, ShapeBatch& batch) {
  const float line = font.lineHeight(TextSize::Small);
  const float barWidth = std::max(6.0f, 0.018f * area.height);
  const float x1 = area.x + area.width;
  const float x0 = x1 - barWidth;
  const float top = area.y + 2.2f * line;
  // The note, word-wrapped onto at most two lines under the bar.
  const std::vector<std::string> noteLines = font.wrapped(note, TextSize::Small, area.width, 2);
  const float bottom = area.y + area.height - (noteLines.empty() ? 0.6f : 0.8f + float(noteLines.size())) * line;
  if (bottom - top < 4 * line) return;  // too small to read: leave it out rather than draw it illegibly
  // The bar covers the positions the data reaches, highest at the top.
  const double lo = scale.lowest(), hi = scale.highest();
  const auto yOf = [&](double position) {
    return float(bottom - (position - lo) / std::max(hi - lo, 1e-12) * (bottom - top));
  };
  constexpr int kSteps = 96;
  for (int k = 0; k < kSteps; ++k) {
    const double p0 = lo + (hi - lo) * k / kSteps, p1 = lo + (hi - lo) * (k + 1) / kSteps;
    batch.rect(x0, yOf(p1), x1, yOf(p0) + 0.5f, scale.colorAt(0.5 * (p0 + p1)));
  }
  const float edge = std::max(1.0f, 0.0012f * area.height);
  const Rgba ink = palette::ink;
  batch.rect(x0 - edge, top - edge, x1 + edge, top, ink);
  batch.rect(x0 - edge, bottom, x1 + edge, bottom + edge, ink);
  batch.rect(x0 - edge, top, x0, bottom, ink);
  batch.rect(x1, top, x1 + edge, bottom, ink);

  // Ticks: the ends and the middle of each sign's half (and zero) on a diverging scale, five even steps otherwise.
  std::vector<double> positions;
  if (scale.diverging) {
    for (double p : {0.0, 0.25, 0.5, 0.75, 1.0})
      if (p >= lo - 1e-9 && p <= hi + 1e-9) positions.push_back(p);
  } else {
    for (int k = 0; k <= 4; ++k) positions.push_back(lo + (hi - lo) * k / 4);
  }
  const float tick = 0.6f * barWidth;
  const float ascent = font.ascent(TextSize::Small);
  for (double p : positions) {
    const float y = yOf(p);
    batch.rect(x0 - tick, y - 0.5f * edge, x0, y + 0.5f * edge, ink);
    const std::string text = tickLabel(scale.valueAt(p));
    font.draw(batch, text, TextSize::Small, x0 - tick - 0.3f * line - font.width(text, TextSize::Small),
              y + 0.4f * ascent, ink);
  }
  // Label and note right-aligned to the bar, shortened with an ellipsis where the strip is narrower than they are.
  const std::string title = font.fitted(label, TextSize::Small, area.width);
  font.draw(batch, title, TextSize::Small, x1 - font.width(title, TextSize::Small), area.y + 0.4f * line + ascent, ink);
  float noteBaseline = bottom + 0.4f * line + ascent;
  for (const std::string& text : noteLines) {
    font.draw(batch, text, TextSize::Small, x1 - font.width(text, TextSize::Small), noteBaseline, palette::softInk);
    noteBaseline += line;
  }
}

}  // namespace sl::render

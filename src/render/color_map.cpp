#include "render/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "render/frame_words.hpp"
#include "render/palette.hpp"

namespace sl {
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

}  // namespace

std::vector<double> niceTicks(double lo, double hi, int maxTicks) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || maxTicks < 1) return {};
  // The smallest step of the form {1, 2, 2.5, 5} x 10^k with at most maxTicks multiples in [lo, hi].
  const double raw = (hi - lo) / maxTicks;
  double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (int guard = 0; guard < 4; ++guard, decade *= 10) {
    for (double mantissa : {1.0, 2.0, 2.5, 5.0, 10.0}) {
      const double step = mantissa * decade;
      const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
      if (last - first + 1 > maxTicks) continue;
      std::vector<double> ticks;
      for (double k = first; k <= last; ++k) ticks.push_back(k * step == 0 ? 0.0 : k * step);
      return ticks;
    }
  }
  return {};
}

std::string tickLabel(double value, double step) {
  // As many decimals as the step needs (0.25: two, 0.5: one, 20: none); a true minus sign (U+2212).
  int decimals = 0;
  for (double scaled = std::abs(step); decimals < 12 && std::abs(scaled - std::round(scaled)) > 1e-6 * scaled;
       scaled *= 10)
    ++decimals;
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(value));
  const bool zero = std::strtod(text, nullptr) == 0;
  return (value < 0 && !zero ? "\u2212" : "") + std::string(text);
}

namespace {

// The step between consecutive ticks, for their labels' decimals (one tick alone: its own magnitude).
double tickStep(const std::vector<double>& ticks) {
  double step = 0;
  for (std::size_t i = 1; i < ticks.size(); ++i)
    step = step == 0 ? ticks[i] - ticks[i - 1] : std::min(step, ticks[i] - ticks[i - 1]);
  if (step > 0) return step;
  return ticks.empty() || ticks[0] == 0 ? 1.0 : std::pow(10.0, std::floor(std::log10(std::abs(ticks[0]))));
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
                  const FontAtlas& font, const palette::PageInk& page, ShapeBatch& batch) {
  const float line = font.lineHeight(TextSize::Small);
  const float barWidth = std::max(6.0f, 0.018f * area.height);
  const float x1 = area.x + area.width;
  const float x0 = x1 - barWidth;
  const float top = area.y + 2.2f * line;
  const float tick = 0.6f * barWidth;
  // A two-slope scale says where its slope changes: the zero tick, drawn longer, is labelled "scale changes at 0"
  // where the strip has room for it (the note under the bar is then left out); else "0", and the note stays.
  const bool broken = scale.diverging && scale.min < 0 && scale.max > 0;
  const float zeroLabelRoom = x0 - 1.6f * tick - 0.3f * line - area.x;
  std::string breakWords;
  for (const std::string& form : scaleBreakWords())
    if (breakWords.empty() && font.width(form + " " + tickLabel(0, 1), TextSize::Small) <= zeroLabelRoom)
      breakWords = form + " ";
  const bool breakNoted = broken && !breakWords.empty();
  // The note, word-wrapped onto at most two lines under the bar.
  const std::vector<std::string> noteLines =
      breakNoted ? std::vector<std::string>{} : font.wrapped(note, TextSize::Small, area.width, 2);
  const float bottom = area.y + area.height - (noteLines.empty() ? 0.6f : 0.8f + float(noteLines.size())) * line;
  if (bottom - top < 4 * line) return;  // too small to read: leave it out rather than draw it illegibly
  // The bar covers the positions the data reaches, highest at the top.
  const double lo = scale.lowest(), hi = scale.highest();
  const auto yOf = [&](double position) {
    return float(bottom - (position - lo) / std::max(hi - lo, 1e-12) * (bottom - top));
  };
  // One band per pixel row (at least 96): no visible steps at any frame size.
  const int kSteps = std::max(96, int(std::ceil(bottom - top)));
  for (int k = 0; k < kSteps; ++k) {
    const double p0 = lo + (hi - lo) * k / kSteps, p1 = lo + (hi - lo) * (k + 1) / kSteps;
    batch.rect(x0, yOf(p1), x1, yOf(p0) + 0.5f, scale.colorAt(0.5 * (p0 + p1)));
  }
  const float edge = std::max(1.0f, 0.0012f * area.height);
  const Rgba ink = page.ink;
  batch.rect(x0 - edge, top - edge, x1 + edge, top, ink);
  batch.rect(x0 - edge, bottom, x1 + edge, bottom + edge, ink);
  batch.rect(x0 - edge, top, x0, bottom, ink);
  batch.rect(x1, top, x1 + edge, bottom, ink);

  // Ticks at round values (niceTicks), as many as the bar's height has room for; on a two-slope (diverging) scale
  // each sign's half gets its own, and zero, where the slope changes, is marked across the bar.
  const float roomPerTick = 1.8f * line;
  std::vector<double> values;
  if (scale.diverging) {
    const float half = 0.5f * (bottom - top) / float(std::max(hi - lo, 1e-12));  // a half's height in pixels
    const int each = std::clamp(int(half / roomPerTick), 1, 4);
    if (scale.min < 0) values = niceTicks(scale.min, 0, each);
    for (double v : niceTicks(0, scale.max, each))
      if (values.empty() || v > values.back()) values.push_back(v);
    if (scale.min < 0 && scale.max > 0) {
      const float y = yOf(0.5);
      batch.rect(x0, y - 0.5f * edge, x1, y + 0.5f * edge, ink);  // across the bar; its tick is drawn longer below
    }
  } else {
    values = niceTicks(scale.min, scale.max, std::clamp(int((bottom - top) / roomPerTick), 2, 6));
  }
  // The labels' decimals per sign, from the steps of that sign's ticks.
  std::vector<double> negative, positive;
  for (double v : values) (v < 0 ? negative : positive).push_back(v);
  const double negativeStep = tickStep(negative), positiveStep = tickStep(positive);
  const float ascent = font.ascent(TextSize::Small);
  for (double v : values) {
    const float y = yOf(scale.position(v));
    const float length = scale.diverging && v == 0 ? 1.6f * tick : tick;
    batch.rect(x0 - length, y - 0.5f * edge, x0, y + 0.5f * edge, ink);
    const std::string text = tickLabel(v, v < 0 ? negativeStep : positiveStep);
    const float textX = x0 - length - 0.3f * line - font.width(text, TextSize::Small);
    font.draw(batch, text, TextSize::Small, textX, y + 0.4f * ascent, ink);
    if (breakNoted && v == 0)  // the note's words before the zero, as the note under the bar is written
      font.draw(batch, breakWords, TextSize::Small, textX - font.width(breakWords, TextSize::Small), y + 0.4f * ascent,
                page.softInk);
  }
  // Label and note right-aligned to the bar, shortened with an ellipsis where the strip is narrower than they are.
  const std::string title = font.fitted(label, TextSize::Small, area.width);
  font.draw(batch, title, TextSize::Small, x1 - font.width(title, TextSize::Small), area.y + 0.4f * line + ascent, ink);
  float noteBaseline = bottom + 0.4f * line + ascent;
  for (const std::string& text : noteLines) {
    font.draw(batch, text, TextSize::Small, x1 - font.width(text, TextSize::Small), noteBaseline, page.softInk);
    noteBaseline += line;
  }
}

}  // namespace sl

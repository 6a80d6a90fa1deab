// The plot panel: time series on linear or log axes with labelled ticks. On a log axis values that are
// non-finite or not positive are skipped (the line breaks there); on a linear axis non-finite ones.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "render/palette.hpp"
#include "render/panels.hpp"

namespace sl::render {
namespace {

struct Axis {
  double lo, hi;
  bool log;
  std::vector<double> ticks;  // in data units
};

bool drawable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

// 1, 2 or 5 times a power of ten, about `count` steps over the span.
double niceStep(double span, int count) {
  const double raw = span / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10 * power;
}

Axis linearAxis(double lo, double hi, int count) {
  if (!(hi > lo)) {
    const double pad = std::max(std::abs(lo) * 0.1, 1.0);
    lo -= pad;
    hi += pad;
  }
  const double step = niceStep(hi - lo, count);
  Axis axis{std::floor(lo / step) * step, std::ceil(hi / step) * step, false, {}};
  for (double t = axis.lo; t <= axis.hi + 1e-9 * step; t += step)
    axis.ticks.push_back(std::abs(t) < 1e-12 * step ? 0 : t);
  return axis;
}

// Exactly [lo, hi] (the animation's time span), with ticks at nice steps inside it.
Axis spanAxis(double lo, double hi, int count) {
  if (!(hi > lo)) hi = lo + 1;
  const double step = niceStep(hi - lo, count);
  Axis axis{lo, hi, false, {}};
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
    axis.ticks.push_back(std::abs(t) < 1e-12 * step ? 0 : t);
  return axis;
}

Axis logAxis(double lo, double hi) {
  double a = std::floor(std::log10(lo)), b = std::ceil(std::log10(hi));
  if (b <= a) b = a + 1;
  Axis axis{std::pow(10.0, a), std::pow(10.0, b), true, {}};
  const int stride = std::max(1, int(std::ceil((b - a) / 6)));
  for (double e = a; e <= b; e += stride) axis.ticks.push_back(std::pow(10.0, e));
  return axis;
}

double unit(const Axis& axis, double v) {
  return axis.log ? (std::log10(v) - std::log10(axis.lo)) / (std::log10(axis.hi) - std::log10(axis.lo))
                  : (v - axis.lo) / (axis.hi - axis.lo);
}

std::string superscript(int exponent) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string text = exponent < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(exponent))) text += digits[c - '0'];
  return text;
}

std::string tickLabel(const Axis& axis, double v) {
  if (axis.log) return "10" + superscript(int(std::lround(std::log10(v))));
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

Axis valueAxis(const PlotFrame& plot) {
  if (plot.valueRange) {  // the whole animation's: the axis stays still from the first frame to the last
    const auto [lo, hi] = *plot.valueRange;
    if (plot.logY ? lo > 0 && hi >= lo : hi >= lo) return plot.logY ? logAxis(lo, hi) : linearAxis(lo, hi, 4);
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& series : plot.series)
    for (double v : series.values)
      if (drawable(v, plot.logY)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) return plot.logY ? logAxis(1e-16, 1) : linearAxis(0, 1, 4);
  return plot.logY ? logAxis(lo, hi) : linearAxis(lo, hi, 4);
}

struct PlotArea {
  float x0, y0, x1, y1;  // pixels
  P2 at(double u, double v) const {
    return {float(x0 + u * (x1 - x0)), float(y1 - std::clamp(v, -0.02, 1.02) * (y1 - y0))};
  }
};

void drawAxes(const PanelContext& c, const PlotArea& area, const Axis& x, const Axis& y, ShapeBatch& batch) {
  const float small = c.font.ascent(TextSize::Small);
  for (double v : y.ticks) {
    const P2 left = area.at(0, unit(y, v)), right = area.at(1, unit(y, v));
    batch.capsule(left, right, 0.5f, palette::gridLight);
    const std::string label = tickLabel(y, v);
    c.font.draw(batch, label, TextSize::Small, left.x - 6 - c.font.width(label, TextSize::Small),
                left.y + 0.45f * small, palette::softInk);
  }
  for (double t : x.ticks) {
    const P2 bottom = area.at(unit(x, t), 0), top = area.at(unit(x, t), 1);
    batch.capsule(bottom, top, 0.5f, palette::gridLight);
    const std::string label = tickLabel(x, t);
    c.font.draw(batch, label, TextSize::Small, bottom.x - 0.5f * c.font.width(label, TextSize::Small),
                bottom.y + 6 + small, palette::softInk);
  }
  const P2 corner = area.at(0, 0);
  batch.capsule(corner, area.at(1, 0), 0.7f, palette::softInk);
  batch.capsule(corner, area.at(0, 1), 0.7f, palette::softInk);
}

// Line half width: 1.1 px up to about 720-pixel frames, then growing with the text (3.4 px at 3840x2160), so
// curves keep their weight beside the labels at every frame size.
float seriesHalfWidth(const FontAtlas& font) { return std::max(1.1f, 0.075f * font.lineHeight(TextSize::Small)); }

// Where the run behind a line stopped: a red cross on the line's last drawable value up to the stop time, or on the
// time axis when it has none (a log axis and exact zeros, say).
void drawStop(const PlotSeries& series, const Axis& x, const Axis& y, const PlotArea& area, float halfWidth,
              ShapeBatch& batch) {
  if (!std::isfinite(series.stopTime) || series.stopTime < x.lo || series.stopTime > x.hi) return;
  P2 at = area.at(unit(x, series.stopTime), 0);
  const std::size_t count = std::min(series.times.size(), series.values.size());
  for (std::size_t i = count; i-- > 0;) {
    if (series.times[i] > series.stopTime || !drawable(series.values[i], y.log)) continue;
    at = area.at(unit(x, series.times[i]), unit(y, series.values[i]));
    break;
  }
  const float arm = std::max(3.5f, 3.2f * halfWidth), width = std::max(0.9f, 0.8f * halfWidth);
  batch.capsule({at.x - arm, at.y - arm}, {at.x + arm, at.y + arm}, width, palette::stopRed);
  batch.capsule({at.x - arm, at.y + arm}, {at.x + arm, at.y - arm}, width, palette::stopRed);
}

void drawSeries(const PlotSeries& series, const Axis& x, const Axis& y, const PlotArea& area, float halfWidth,
                ShapeBatch& batch) {
  std::vector<PolylinePoint> points;
  const std::size_t count = std::min(series.times.size(), series.values.size());
  for (std::size_t i = 0; i < count; ++i) {
    const double t = series.times[i], v = series.values[i];
    if (!drawable(v, y.log) || !std::isfinite(t) || t < x.lo || t > x.hi) {
      batch.polyline(points);
      points.clear();
      continue;
    }
    points.push_back({area.at(unit(x, t), unit(y, v)), halfWidth, toRgba(series.color), {}});
  }
  if (points.size() == 1) batch.disc(points[0].at, std::max(1.6f, 1.45f * halfWidth), points[0].color);
  batch.polyline(points);
  drawStop(series, x, y, area, halfWidth, batch);
  // Marked times (a Jacobi field's zeros): a ring on the time axis and a faint line up through the plot.
  for (const double t : series.markTimes) {
    if (!std::isfinite(t) || t < x.lo || t > x.hi) continue;
    const P2 foot = area.at(unit(x, t), 0), top = area.at(unit(x, t), 1);
    batch.capsule(foot, top, 0.6f, toRgba(series.color, 0.45f));
    batch.disc(foot, 3.2f, toRgba(series.color));
    batch.disc(foot, 1.6f, palette::withAlpha(palette::gridLight, 1.0f));
  }
}

// In the corner the data leaves emptiest over the whole animation (PlotFrame::legendCorner), on a veil of the
// background colour: lines that run under it stay faintly visible, and the labels stay readable.
void drawLegend(const PanelContext& c, const PlotFrame& plot, const PlotArea& area, ShapeBatch& batch) {
  if (plot.series.empty()) return;
  const float line = c.font.lineHeight(TextSize::Small), ascent = c.font.ascent(TextSize::Small);
  float widest = 0;
  for (const auto& series : plot.series) widest = std::max(widest, c.font.width(series.label, TextSize::Small));
  const float height = line * float(plot.series.size()) + 0.35f * ascent;
  const bool onRight = plot.legendCorner == LegendCorner::TopRight || plot.legendCorner == LegendCorner::BottomRight;
  const bool onTop = plot.legendCorner == LegendCorner::TopRight || plot.legendCorner == LegendCorner::TopLeft;
  const float right = onRight ? area.x1 - 8 : area.x0 + 8 + widest + 22 + 6, left = right - widest - 22;
  const float top = onTop ? area.y0 + 2 : area.y1 - 2 - height;
  const ColorRGB veil = c.settings.background;
  batch.rect(left - 6, top, right + 6, top + height, {veil.r, veil.g, veil.b, 0.85f});
  float y = top + line - 2;
  for (const auto& series : plot.series) {
    const float x = right - c.font.width(series.label, TextSize::Small);
    batch.capsule({x - 22, y - 0.35f * ascent}, {x - 6, y - 0.35f * ascent}, std::max(1.3f, 1.1f * seriesHalfWidth(c.font)),
                  toRgba(series.color));
    c.font.draw(batch, series.label, TextSize::Small, x, y, palette::ink);
    y += line;
  }
}

}  // namespace

void drawPlotPanel(const PanelContext& c, int plotIndex, ShapeBatch& batch) {
  const auto& plots = c.frame.plots;
  PlotFrame empty;
  empty.title = "(no plot data)";
  const PlotFrame& plot = plotIndex >= 0 && plotIndex < int(plots.size()) ? plots[plotIndex] : empty;
  const float line = c.font.lineHeight(TextSize::Small);
  const Axis y = valueAxis(plot);
  const Axis x = spanAxis(plot.timeMin, plot.timeMax, 5);
  float labelWidth = 0;
  for (double v : y.ticks) labelWidth = std::max(labelWidth, c.font.width(tickLabel(y, v), TextSize::Small));
  const PlotArea area{c.rect.x + labelWidth + 14, c.rect.y + 1.9f * line, c.rect.x + c.rect.width - 16,
                      c.rect.y + c.rect.height - 2.4f * line};
  if (area.x1 - area.x0 < 10 || area.y1 - area.y0 < 10) return;  // too small to draw anything useful
  c.font.draw(batch, c.font.fitted(plot.title, TextSize::Normal, c.rect.x + c.rect.width - area.x0 - 4), TextSize::Normal,
              area.x0, c.rect.y + 1.3f * line, palette::ink);
  // The axis name beyond its end, level with the axis: clear of every tick label below it.
  c.font.draw(batch, "t", TextSize::Small, area.x1 + 4, area.y1 + 0.35f * c.font.ascent(TextSize::Small),
              palette::softInk);
  drawAxes(c, area, x, y, batch);
  bool anyDrawn = false;
  for (const auto& series : plot.series) {
    drawSeries(series, x, y, area, seriesHalfWidth(c.font), batch);
    for (double v : series.values) anyDrawn = anyDrawn || drawable(v, plot.logY);
  }
  if (!anyDrawn && !plot.emptyNote.empty()) {  // a plot that stays empty says why
    const std::string note = c.font.fitted(plot.emptyNote, TextSize::Small, area.x1 - area.x0 - 8);
    c.font.draw(batch, note, TextSize::Small, 0.5f * (area.x0 + area.x1 - c.font.width(note, TextSize::Small)),
                0.5f * (area.y0 + area.y1), palette::softInk);
  }
  drawLegend(c, plot, area, batch);
}

}  // namespace sl::render

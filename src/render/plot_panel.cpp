// The plot panel: time series on linear or log axes with labelled ticks. On a log axis values that are
// non-finite or not positive are skipped (the line breaks there); on a linear axis non-finite ones.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <cstdio>
#include <limits>

#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panels.hpp"

namespace sl {
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
  // Room for one step only (a narrow plot): the span's two ends, so the axis still has a scale.
  if (axis.ticks.size() < 2) axis.ticks = {lo, hi};
  return axis;
}

// Decades from below lo to above hi, a labelled tick every `stride` decades so that at most `maxTicks` show.
Axis logAxis(double lo, double hi, int maxTicks) {
  double a = std::floor(std::log10(lo)), b = std::ceil(std::log10(hi));
  if (b <= a) b = a + 1;
  Axis axis{std::pow(10.0, a), std::pow(10.0, b), true, {}};
  const int stride = std::max(1, int(std::ceil((b - a) / std::max(1, maxTicks - 1))));
  for (double e = a; e <= b; e += stride) axis.ticks.push_back(std::pow(10.0, e));
  return axis;
}

double unit(const Axis& axis, double v) {
  return axis.log ? (std::log10(v) - std::log10(axis.lo)) / (std::log10(axis.hi) - std::log10(axis.lo))
                  : (v - axis.lo) / (axis.hi - axis.lo);
}

std::string tickLabel(const Axis& axis, double v) {
  if (axis.log) return "10" + superscript(int(std::lround(std::log10(v))));
  return typesetNumber("%g", v);
}

// The y axis with at most `maxTicks` labelled ticks (what the plot's height has room for).
Axis valueAxis(const PlotFrame& plot, int maxTicks) {
  const int steps = std::clamp(maxTicks - 1, 1, 4);
  if (plot.valueRange) {  // the whole animation's: the axis stays still from the first frame to the last
    const auto [lo, hi] = *plot.valueRange;
    if (plot.logY ? lo > 0 && hi >= lo : hi >= lo)
      return plot.logY ? logAxis(lo, hi, maxTicks) : linearAxis(lo, hi, steps);
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& series : plot.series)
    for (double v : series.values)
      if (drawable(v, plot.logY)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) return plot.logY ? logAxis(1e-16, 1, maxTicks) : linearAxis(0, 1, steps);
  return plot.logY ? logAxis(lo, hi, maxTicks) : linearAxis(lo, hi, steps);
}

struct PlotArea {
  float x0, y0, x1, y1;  // pixels
  P2 at(double u, double v) const {
    return {float(x0 + u * (x1 - x0)), float(y1 - std::clamp(v, -0.02, 1.02) * (y1 - y0))};
  }
};

// At most this many samples per pixel column of the plot area are drawn: more would not show.
constexpr double kSamplesPerColumn = 4;

// The samples of a series that are drawn: all of them while the plot's width can show them, else every
// stride-th (a power of two, the smallest that fits) and the last one, so a line costs what the plot's width
// shows, not what the frame's index is. Depends on the sample count and the width alone: a frame is drawn
// alike whichever frames were drawn before it.
class DrawnSamples {
 public:
  DrawnSamples(const PlotSeries& series, const PlotArea& area) : count_(std::min(series.times.size(), series.values.size())) {
    const double room = std::max(2.0, kSamplesPerColumn * std::ceil(std::max(0.0f, area.x1 - area.x0)));
    size_ = count_;
    while (double(size_) > room) {
      stride_ *= 2;
      size_ = (count_ - 1) / stride_ + 1 + ((count_ - 1) % stride_ != 0 ? 1 : 0);  // with the last sample
    }
  }
  std::size_t size() const { return size_; }
  // The series index of drawn sample i.
  std::size_t operator[](std::size_t i) const { return std::min(i * stride_, count_ - 1); }

 private:
  std::size_t count_, stride_ = 1, size_ = 0;
};

void drawAxes(const PanelContext& c, const PlotArea& area, const Axis& x, const Axis& y, ShapeBatch& batch) {
  const float small = c.font.ascent(TextSize::Small);
  for (double v : y.ticks) {
    const P2 left = area.at(0, unit(y, v)), right = area.at(1, unit(y, v));
    batch.capsule(left, right, 0.5f * c.unit, c.page().gridLight);
    const std::string label = tickLabel(y, v);
    c.font.draw(batch, label, TextSize::Small, left.x - 0.5f * small - c.font.width(label, TextSize::Small),
                left.y + 0.45f * small, c.page().softInk);
  }
  for (double t : x.ticks) {
    const P2 bottom = area.at(unit(x, t), 0), top = area.at(unit(x, t), 1);
    batch.capsule(bottom, top, 0.5f * c.unit, c.page().gridLight);
    const std::string label = tickLabel(x, t);
    c.font.draw(batch, label, TextSize::Small, bottom.x - 0.5f * c.font.width(label, TextSize::Small),
                bottom.y + 0.5f * small + small, c.page().softInk);
  }
  const P2 corner = area.at(0, 0);
  batch.capsule(corner, area.at(1, 0), 0.7f * c.unit, c.page().softInk);
  batch.capsule(corner, area.at(0, 1), 0.7f * c.unit, c.page().softInk);
}

// Line half width: 1.1 px up to about 720-pixel frames, then growing with the text (3.4 px at 3840x2160), so
// curves keep their weight beside the labels at every frame size.
float seriesHalfWidth(const FontAtlas& font) { return std::max(1.1f, 0.075f * font.lineHeight(TextSize::Small)); }

// Labels put in the plot area (event times), kept apart: a label that would overlap one already placed is
// left out.
class PlacedLabels {
 public:
  bool free(float x0, float y0, float x1, float y1) const {
    for (const auto& b : boxes_)
      if (x0 < b[2] && b[0] < x1 && y0 < b[3] && b[1] < y1) return false;
    return true;
  }
  void add(float x0, float y0, float x1, float y1) { boxes_.push_back({x0, y0, x1, y1}); }

 private:
  std::vector<std::array<float, 4>> boxes_;
};

// `text` in small type beside the point (right of it, or left when the area's edge is near), above its
// baseline `y`, unless it would overlap a label already placed.
void labelEvent(const PanelContext& c, const PlotArea& area, const std::string& text, P2 at, float gap, Rgba color,
                PlacedLabels& placed, ShapeBatch& batch) {
  const float width = c.font.width(text, TextSize::Small), ascent = c.font.ascent(TextSize::Small);
  float x = at.x + gap;
  if (x + width > area.x1) x = at.x - gap - width;
  if (x < area.x0) return;
  const float y = std::clamp(at.y + 0.4f * ascent, area.y0 + ascent, area.y1 - 0.2f * ascent);
  if (!placed.free(x, y - ascent, x + width, y + 0.2f * ascent)) return;
  placed.add(x, y - ascent, x + width, y + 0.2f * ascent);
  c.font.draw(batch, text, TextSize::Small, x, y, color);
}

// Where the run behind a line stopped: a red cross on the line's last drawable value up to the stop time, labelled
// with that time; none when the line has no such value (a log axis and exact zeros, say): a cross anywhere else
// would mark a value the run never had.
void drawStop(const PanelContext& c, const PlotSeries& series, const DrawnSamples& drawn, const Axis& x,
              const Axis& y, const PlotArea& area, float halfWidth, PlacedLabels& placed, ShapeBatch& batch) {
  if (!std::isfinite(series.stopTime) || series.stopTime < x.lo || series.stopTime > x.hi) return;
  std::optional<P2> last;
  for (std::size_t j = drawn.size(); j-- > 0;) {
    const std::size_t i = drawn[j];
    if (series.times[i] > series.stopTime || !drawable(series.values[i], y.log)) continue;
    last = area.at(unit(x, series.times[i]), unit(y, series.values[i]));
    break;
  }
  if (!last) return;
  P2 at = *last;
  const float arm = std::max(3.5f, 3.2f * halfWidth), width = std::max(0.9f, 0.8f * halfWidth);
  // Inside the plot area, clear of the tick labels round it (a stop at t = 0 sits in the corner).
  at.x = std::clamp(at.x, area.x0 + arm + 1, std::max(area.x0 + arm + 1, area.x1 - arm - 1));
  at.y = std::clamp(at.y, area.y0 + arm + 1, std::max(area.y0 + arm + 1, area.y1 - arm - 1));
  batch.capsule({at.x - arm, at.y - arm}, {at.x + arm, at.y + arm}, width, c.page().stopRed);
  batch.capsule({at.x - arm, at.y + arm}, {at.x + arm, at.y - arm}, width, c.page().stopRed);
  // The time above the cross, ending at its right arm; at the area's top, right of the cross (the line has ended
  // there), else below it; never on its left, where the line comes in (comparison.json, frame 593, had it there on
  // the line). No room: no label (a second run stopping at the same place and time says the same).
  const std::string text = "stop " + timeWords(series.stopTime);
  const float textWidth = c.font.width(text, TextSize::Small), ascent = c.font.ascent(TextSize::Small);
  const float gap = 0.4f * ascent, middle = at.y + 0.4f * ascent;
  const std::array<P2, 3> places{P2{at.x + arm - textWidth, at.y - arm - gap},           // above
                                 P2{at.x + arm + gap, middle},                           // right
                                 P2{at.x + arm - textWidth, at.y + arm + gap + ascent}};  // below
  for (const P2& p : places) {  // p: the text's left end on its baseline
    if (p.x < area.x0 || p.x + textWidth > area.x1 || p.y - ascent < area.y0 || p.y > area.y1) continue;
    if (!placed.free(p.x, p.y - ascent, p.x + textWidth, p.y + 0.2f * ascent)) continue;
    placed.add(p.x, p.y - ascent, p.x + textWidth, p.y + 0.2f * ascent);
    c.font.draw(batch, text, TextSize::Small, p.x, p.y, c.page().stopRed);
    return;
  }
}

// `halfWidth`: this line's (nested, runStyleWidth); `stopHalfWidth`: the stop cross's, the same for every line.
void drawSeries(const PanelContext& c, const PlotSeries& series, const Axis& x, const Axis& y, const PlotArea& area,
                float halfWidth, float stopHalfWidth, PlacedLabels& placed, ShapeBatch& batch) {
  std::vector<PolylinePoint> points;
  const DrawnSamples drawn(series, area);
  for (std::size_t j = 0; j < drawn.size(); ++j) {
    const std::size_t i = drawn[j];
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
  drawStop(c, series, drawn, x, y, area, stopHalfWidth, placed, batch);
  // Marked times (a Jacobi field's zeros): a ring on the time axis and a faint line up through the plot, its time
  // written at the line's top.
  for (const double t : series.markTimes) {
    if (!std::isfinite(t) || t < x.lo || t > x.hi) continue;
    const P2 foot = area.at(unit(x, t), 0), top = area.at(unit(x, t), 1);
    // Sized by the stop cross's width, which grows with the text: the same marks at every frame size.
    batch.capsule(foot, top, 0.45f * stopHalfWidth, toRgba(series.color, 0.45f));
    batch.disc(foot, 2.4f * stopHalfWidth, toRgba(series.color));
    batch.disc(foot, 1.2f * stopHalfWidth, palette::withAlpha(c.page().gridLight, 1.0f));
    const float ascent = c.font.ascent(TextSize::Small);
    labelEvent(c, area, timeWords(t), {top.x, top.y + 0.6f * ascent}, 0.4f * ascent, toRgba(series.color), placed,
               batch);
  }
}

// Series k of `count`: its line's half width. Each later series is narrower (runStyleWidth), so a line exactly
// under another still shows along both of its edges; the legend's swatches show the same strokes.
float seriesWidth(const FontAtlas& font, std::size_t k, std::size_t count) {
  return std::max(0.8f, 1.4f * seriesHalfWidth(font) * runStyleWidth(k, count));
}

// The legend as a row of swatches and names, laid out from `x` to `right` on the baseline `y`, wrapping onto
// further rows `lineStep` apart; draws only if `batch` is given. Returns the baseline of its last row, or NaN when
// it needs more than `maxRows` rows.
float layLegend(const PanelContext& c, const PlotFrame& plot, float x, float right, float y, float lineStep,
                int maxRows, ShapeBatch* batch) {
  const float ascent = c.font.ascent(TextSize::Small), swatch = 1.6f * ascent, gap = 0.9f * ascent;
  const float left = x;
  int rows = 1;
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& series = plot.series[k];
    const float width = swatch + 0.4f * ascent + c.font.width(series.label, TextSize::Small);
    if (x > left && x + width > right) {
      if (++rows > maxRows) return std::numeric_limits<float>::quiet_NaN();
      x = left;
      y += lineStep;
    }
    if (x + width > right) return std::numeric_limits<float>::quiet_NaN();  // one name alone is too wide
    if (batch) {
      const float mid = y - 0.35f * ascent, half = seriesWidth(c.font, k, plot.series.size());
      batch->capsule({x + half, mid}, {x + swatch - half, mid}, half, toRgba(series.color));
      c.font.draw(*batch, series.label, TextSize::Small, x + swatch + 0.4f * ascent, y, c.page().ink);
    }
    x += width + gap;
  }
  return y;
}

// The width of the widest time label (the duration's, as a linear axis labels it).
float timeLabelWidth(const PanelContext& c, const PlotFrame& plot) {
  return c.font.width(tickLabel(Axis{plot.timeMin, plot.timeMax, false, {}}, plot.timeMax), TextSize::Small);
}

// The line of a plot whose values all lie within roundoff, centred where the plot area would be, with the legend.
void drawRoundoffNote(const PanelContext& c, const PlotFrame& plot, const PlotLayout& layout, ShapeBatch& batch) {
  const float line = c.font.lineHeight(TextSize::Small), ascent = c.font.ascent(TextSize::Small);
  const float left = c.rect.x + 0.5f * ascent, right = c.rect.x + c.rect.width - 0.5f * ascent;
  const float top = layout.legendBottom + 0.3f * line, bottom = c.rect.y + c.rect.height;
  // The longest form that wraps into the lines there is room for, every word whole; the shortest, cut, if none does.
  const std::size_t lines = std::size_t(std::clamp((bottom - top) / line, 1.0f, 2.0f));
  const std::vector<std::string> note = wrappedFittedForm(c.font, roundoffNotes(plot), TextSize::Small, right - left, lines);
  float y = 0.5f * (top + bottom) - 0.5f * line * (float(note.size()) - 1) + 0.4f * ascent;
  for (const std::string& text : note) {
    c.font.draw(batch, text, TextSize::Small, 0.5f * (left + right - c.font.width(text, TextSize::Small)), y,
                c.page().ink);
    y += line;
  }
  if (layout.legendShown)
    layLegend(c, plot, layout.legendX, layout.legendRight, layout.legendBaseline, line, layout.legendRows, &batch);
}

}  // namespace

// Layout, top to bottom: the title, the legend (outside the plot area, so it never covers data), the plot area
// with its y tick labels on the left, the x tick labels and the axis name "t" below and right. Every margin follows
// the text size, so the plot keeps its proportions from 320x180 to 3840x2160. A panel shorter than about eight
// lines of small text is drawn compact: the title in small text with the legend beside it if it fits (the runs'
// colours are also in the text panel), fewer ticks.
PlotLayout layoutPlot(const PanelContext& c, const PlotFrame& plot, const std::vector<std::string>& titles) {
  const float line = c.font.lineHeight(TextSize::Small), ascent = c.font.ascent(TextSize::Small);
  const bool compact = c.rect.height < 8 * line;
  PlotLayout layout;
  layout.titleSize = compact ? TextSize::Small : TextSize::Normal;
  const float pad = 0.5f * ascent, right = c.rect.x + c.rect.width - pad;
  layout.titleBaseline = c.rect.y + pad + c.font.ascent(layout.titleSize);
  layout.title = fittedForm(c.font, titles, layout.titleSize, c.rect.width - 2 * pad);  // a shorter form, no cut

  // The legend beside the title when both fit in one row, else in rows of its own below it (at most two in a
  // full-size panel, none in a compact one).
  layout.legendX = c.rect.x + pad + c.font.width(layout.title, layout.titleSize) + 2 * ascent;
  layout.legendRight = right;
  layout.legendRows = 1;
  layout.legendBaseline = layout.legendBottom = layout.titleBaseline;
  // A legend of one series named as the plot's title begins (the holonomy's "∫K dA swept") only repeats it: none.
  const bool legendRepeatsTitle = plot.series.size() == 1 && layout.title.rfind(plot.series.front().label, 0) == 0;
  const bool legendWanted = !plot.series.empty() && !legendRepeatsTitle;
  layout.legendShown =
      legendWanted && !std::isnan(layLegend(c, plot, layout.legendX, right, layout.titleBaseline, line, 1, nullptr));
  if (!layout.legendShown && !compact && legendWanted) {
    layout.legendX = c.rect.x + pad;
    layout.legendRows = 2;
    layout.legendBaseline = layout.titleBaseline + 1.15f * line;
    const float last = layLegend(c, plot, layout.legendX, right, layout.legendBaseline, line, 2, nullptr);
    layout.legendShown = !std::isnan(last);
    if (layout.legendShown) layout.legendBottom = last;
  }

  // The plot area; room on the left for the y labels, on the right for the last x label's half and the axis name.
  const float bottomRoom = (compact ? 1.35f : 2.2f) * line;
  layout.areaY0 = layout.legendBottom + 0.6f * line;
  layout.valueLabelShown = !compact && !plot.roundoff;
  layout.valueLabelBaseline = layout.areaY0 + ascent;
  if (layout.valueLabelShown) layout.areaY0 += 1.1f * line + 0.6f * ascent;  // clear of the top tick's label
  layout.areaY1 = c.rect.y + c.rect.height - bottomRoom;
  layout.yTicks = std::max(2, int((layout.areaY1 - layout.areaY0) / (1.25f * line)) + 1);
  const Axis y = valueAxis(plot, layout.yTicks);
  float labelWidth = 0;
  for (double v : y.ticks) labelWidth = std::max(labelWidth, c.font.width(tickLabel(y, v), TextSize::Small));
  const float rightRoom = std::max(0.5f * timeLabelWidth(c, plot), c.font.width("t", TextSize::Small) + 0.6f * ascent) + pad;
  layout.areaX0 = c.rect.x + pad + labelWidth + 0.6f * ascent;
  layout.areaX1 = c.rect.x + c.rect.width - rightRoom;
  layout.areaShown = layout.areaX1 - layout.areaX0 >= 2 * ascent && layout.areaY1 - layout.areaY0 >= ascent;
  return layout;
}

PlotLayout layoutPlot(const PanelContext& c, const PlotFrame& plot) { return layoutPlot(c, plot, plotTitles(plot)); }

void drawPlotPanel(const PanelContext& c, int plotIndex, ShapeBatch& batch) {
  const auto& plots = c.frame.plots;
  const bool exists = plotIndex >= 0 && plotIndex < int(plots.size());
  const PlotFrame empty;
  const PlotFrame& plot = exists ? plots[plotIndex] : empty;
  const float line = c.font.lineHeight(TextSize::Small), ascent = c.font.ascent(TextSize::Small);
  const PlotLayout layout =
      layoutPlot(c, plot, exists ? plotTitles(plot) : std::vector<std::string>{"(no plot data)", "(no data)"});
  c.font.draw(batch, layout.title, layout.titleSize, c.rect.x + 0.5f * ascent, layout.titleBaseline, c.page().ink);
  if (plot.roundoff) {  // nothing but roundoff to show: one line says so, in place of the axes
    drawRoundoffNote(c, plot, layout, batch);
    return;
  }
  if (!layout.areaShown) return;  // no room for a plot: the title only
  const PlotArea area{layout.areaX0, layout.areaY0, layout.areaX1, layout.areaY1};
  const Axis y = valueAxis(plot, layout.yTicks);
  // The x axis runs over the whole animation; its labels need about three and a half label widths each.
  const int xSteps =
      std::clamp(int((area.x1 - area.x0) / (3.5f * std::max(timeLabelWidth(c, plot), ascent))), 1, 5);
  const Axis x = spanAxis(plot.timeMin, plot.timeMax, xSteps);
  // The axis name beyond its end, level with the axis: clear of every tick label below it.
  c.font.draw(batch, "t", TextSize::Small, area.x1 + 0.4f * ascent, area.y1 + 0.35f * ascent, c.page().softInk);
  drawAxes(c, area, x, y, batch);
  if (layout.valueLabelShown)
    c.font.draw(batch, c.font.fitted(valueAxisWords(plot.kind), TextSize::Small, c.rect.x + c.rect.width - area.x0),
                TextSize::Small, c.rect.x + 0.5f * ascent, layout.valueLabelBaseline, c.page().softInk);
  // Now: a line across the plot at the frame's time, which relates the plot to the other panels.
  if (c.frame.time >= x.lo && c.frame.time <= x.hi) {
    const float at = area.at(unit(x, c.frame.time), 0).x;
    batch.capsule({at, area.y0}, {at, area.y1}, 0.5f * seriesHalfWidth(c.font), c.page().nowCursor);
  }
  bool anyDrawn = false;
  PlacedLabels placed;
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& series = plot.series[k];
    drawSeries(c, series, x, y, area, seriesWidth(c.font, k, plot.series.size()), seriesHalfWidth(c.font), placed,
               batch);
    const DrawnSamples drawn(series, area);
    for (std::size_t j = 0; j < drawn.size() && !anyDrawn; ++j) anyDrawn = drawable(series.values[drawn[j]], plot.logY);
  }
  const std::string emptyNote = emptyPlotNote(plot);
  if (!anyDrawn && !emptyNote.empty()) {  // a plot that stays empty says why, in as many lines as fit
    const std::size_t room = std::size_t(std::max(1.0f, (area.y1 - area.y0) / line - 0.5f));
    const std::vector<std::string> note =
        c.font.wrapped(emptyNote, TextSize::Small, area.x1 - area.x0 - ascent, std::min<std::size_t>(room, 3));
    float y = 0.5f * (area.y0 + area.y1) - 0.5f * line * (float(note.size()) - 1) + 0.4f * ascent;
    for (const std::string& text : note) {
      c.font.draw(batch, text, TextSize::Small, 0.5f * (area.x0 + area.x1 - c.font.width(text, TextSize::Small)), y,
                  c.page().softInk);
      y += line;
    }
  }
  if (layout.legendShown)
    layLegend(c, plot, layout.legendX, layout.legendRight, layout.legendBaseline, line, layout.legendRows, &batch);
}

}  // namespace sl

// The text panel: title, simulation time, each run's name and method in its colour, and why a run
// stopped once it has.

#include <cstdio>

#include "render/palette.hpp"
#include "render/panels.hpp"

namespace sl::render {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string runLine(const RunFrame& run) {
  std::string line = run.name + "  (" + run.method + ")";
  if (!run.members.empty()) line += "  + " + std::to_string(run.members.size()) + " members";
  // Conjugate points reached so far (runs with Jacobi fields), the latest few.
  if (!run.conjugateTimes.empty()) {
    line += "  conjugate at t =";
    const std::size_t first = run.conjugateTimes.size() > 3 ? run.conjugateTimes.size() - 3 : 0;
    if (first > 0) line += " ...";
    for (std::size_t i = first; i < run.conjugateTimes.size(); ++i)
      line += (i > first ? ", " : " ") + format("%.4f", run.conjugateTimes[i]);
  }
  return line;
}

}  // namespace

void drawTextPanel(const PanelContext& c, ShapeBatch& batch) {
  const float pad = 0.02f * c.rect.width;
  const float titleLine = c.font.lineHeight(TextSize::Title);
  const float line = c.font.lineHeight(TextSize::Normal);
  float y = c.rect.y + 0.35f * line + c.font.ascent(TextSize::Title);
  const std::string time = "t = " + format("%.2f", c.frame.time) + " / " + format("%.2f", c.frame.duration);
  const float timeWidth = c.font.width(time, TextSize::Normal);
  // The title gives way to the time: shortened with an ellipsis rather than running under it.
  c.font.draw(batch, c.font.fitted(c.frame.title, TextSize::Title, c.rect.width - timeWidth - 4 * pad), TextSize::Title,
              c.rect.x + pad, y, palette::ink);
  c.font.draw(batch, time, TextSize::Normal, c.rect.x + c.rect.width - pad - timeWidth, y, palette::ink);

  // Runs flow left to right, wrapping to the next line.
  y += 0.15f * titleLine + line;
  float x = c.rect.x + pad;
  const float swatch = 0.3f * c.font.ascent(TextSize::Normal);
  for (std::size_t k = 0; k < c.frame.runs.size(); ++k) {
    const RunFrame& run = c.frame.runs[k];
    std::string text = runLine(run);
    std::string stop = run.stopped ? "  stopped at t = " + format("%.3g", run.stopTime) + ": " + run.stopReason : "";
    const float width = 2.5f * swatch + c.font.width(text + stop, TextSize::Normal) + 2 * pad;
    if (x > c.rect.x + pad && x + width > c.rect.x + c.rect.width) {
      x = c.rect.x + pad;
      y += line;
    }
    // The swatch shows the run's colour and its line style: a stroke as thick as its path on the sphere.
    const float mid = y - 0.35f * c.font.ascent(TextSize::Normal);
    const float half = swatch * runStyleWidth(k, c.frame.runs.size());
    batch.capsule({x + half, mid}, {x + 2.0f * swatch - half, mid}, half, toRgba(run.color), true, 0.4f);
    float end = c.font.draw(batch, text, TextSize::Normal, x + 2.5f * swatch, y, palette::ink);
    if (run.stopped) end = c.font.draw(batch, stop, TextSize::Normal, end, y, palette::stopRed);
    x = end + 2 * pad;
  }
}

void drawTitleLine(const PanelContext& c, ShapeBatch& batch) {
  const float pad = 0.015f * c.rect.width;
  const float line = c.font.lineHeight(TextSize::Normal);
  const float y = c.rect.y + 0.3f * line + c.font.ascent(TextSize::Normal);
  const std::string time = "t = " + format("%.2f", c.frame.time) + " / " + format("%.2f", c.frame.duration);
  const float timeWidth = c.font.width(time, TextSize::Normal);
  const std::string title = c.font.fitted(c.frame.title, TextSize::Normal, c.rect.width - timeWidth - 4 * pad);
  // On a veil of the background, so that a panel reaching up under the line never makes it unreadable.
  const float titleWidth = c.font.width(title, TextSize::Normal);
  const ColorRGB& b = c.settings.background;
  const Rgba veil{b.r, b.g, b.b, 0.75f};
  batch.rect(c.rect.x + 0.5f * pad, c.rect.y, c.rect.x + 1.5f * pad + titleWidth, c.rect.y + 1.3f * line, veil);
  batch.rect(c.rect.x + c.rect.width - 1.5f * pad - timeWidth, c.rect.y, c.rect.x + c.rect.width - 0.5f * pad,
             c.rect.y + 1.3f * line, veil);
  c.font.draw(batch, title, TextSize::Normal, c.rect.x + pad, y, palette::ink);
  c.font.draw(batch, time, TextSize::Normal, c.rect.x + c.rect.width - pad - timeWidth, y, palette::ink);
}

}  // namespace sl::render

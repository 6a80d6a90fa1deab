// The text panel: title, simulation time, each run's name in its colour (and its method where the runs differ by
// method), and why a run stopped once it has, in one line per run.

#include <cmath>
#include <cstdio>

#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panels.hpp"

namespace sl {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// Whether the runs differ by method: only then does a run's row name its method (else it is noise).
bool methodsDiffer(const FrameState& frame) {
  for (const RunFrame& run : frame.runs)
    if (run.method != frame.runs.front().method) return true;
  return false;
}

std::string runLine(const RunFrame& run, bool withMethod) {
  std::string line = withMethod ? run.name + "  (" + methodWords(run.method) + ")" : run.name;
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

// A run's swatch before its text at baseline y: its colour and its line style, a stroke as thick as its path on
// the sphere (runStyleWidth).
void drawSwatch(const PanelContext& c, std::size_t k, TextSize size, float x, float y, ShapeBatch& batch) {
  const float swatch = 0.3f * c.font.ascent(size);
  const float mid = y - 0.35f * c.font.ascent(size);
  const float half = swatch * runStyleWidth(k, c.frame.runs.size());
  batch.capsule({x + half, mid}, {x + 2.0f * swatch - half, mid}, half, toRgba(c.frame.runs[k].color), true, 0.4f);
}

// How much of a stop the run rows say: its reason only; with the watchdog's reading against its limit; and with a
// line of its own saying what the reason means.
enum class StopDetail { Reason, Measured, Explained };

// "stopped at t = 5.2: reason", with the watchdog's reading unless only the reason is asked for.
std::string stopSentence(const RunFrame& run, StopDetail detail) {
  std::string stop = "stopped at t = " + timeWords(run.stopTime) + ": " + stopReasonWords(run.stopReason);
  const std::string reading = stopReadingWords(run);
  if (detail != StopDetail::Reason && !reading.empty()) stop += " (" + reading + ")";
  return stop;
}

// The runs, each its swatch, name, method and (once stopped) why, as much of it as `detail` says, flowing left to
// right from the baseline after `top` and wrapping. Draws into `batch` if given; returns the bottom of the last
// row either way.
float flowRuns(const PanelContext& c, TextSize size, StopDetail detail, float pad, float top, ShapeBatch* batch) {
  const float line = c.font.lineHeight(size);
  const float swatch = 0.3f * c.font.ascent(size);
  float x = c.rect.x + pad, y = top + line;
  for (std::size_t k = 0; k < c.frame.runs.size(); ++k) {
    const RunFrame& run = c.frame.runs[k];
    const std::string text = runLine(run, methodsDiffer(c.frame));
    // One stop line per run: on the run's row, or, explained, on a line of its own below the rows.
    const bool ownLine = detail == StopDetail::Explained && run.stopped;
    std::string stop = run.stopped && !ownLine ? "  " + stopSentence(run, detail) : "";
    const float width = 2.5f * swatch + c.font.width(text + stop, size) + 2 * pad;
    if (width > c.rect.width) return INFINITY;  // one run alone is wider than the panel: this size does not fit
    if (x > c.rect.x + pad && x + width > c.rect.x + c.rect.width) {
      x = c.rect.x + pad;
      y += line;
    }
    if (batch) {
      drawSwatch(c, k, size, x, y, *batch);
      float end = c.font.draw(*batch, text, size, x + 2.5f * swatch, y, c.page().ink);
      if (run.stopped) c.font.draw(*batch, stop, size, end, y, c.page().stopRed);
    }
    x += width;
  }
  // Below the runs, what each stop means: per stopped run, in small text, wrapped onto two lines at most (one cut
  // short with an ellipsis lost the explanation: seam.json).
  for (const RunFrame& run : c.frame.runs) {
    if (detail != StopDetail::Explained || !run.stopped) continue;
    const std::string why = run.name + " " + stopSentence(run, detail) + " \u2014 " + stopMeaningWords(run.stopReason);
    for (const std::string& part : c.font.wrapped(why, TextSize::Small, c.rect.width - 2 * pad, 2)) {
      y += c.font.lineHeight(TextSize::Small);
      if (batch) c.font.draw(*batch, part, TextSize::Small, c.rect.x + pad, y, c.page().stopRed);
    }
  }
  return y + (line - c.font.ascent(size));
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
  c.font.draw(batch, shownTitle(c.font, c.frame, TextSize::Title, c.rect.width - timeWidth - 4 * pad), TextSize::Title,
              c.rect.x + pad, y, c.page().ink);
  c.font.draw(batch, time, TextSize::Normal, c.rect.x + c.rect.width - pad - timeWidth, y, c.page().ink);

  // Runs flow left to right, wrapping to the next line, in normal text or, if that overflows the panel, small
  // text; when even that overflows (small frames, many runs) they share one row, each its name fitted to an
  // equal part and, once stopped, the stop time (the reason needs the room of a larger frame).
  const float firstRow = y + 0.15f * titleLine;
  const float bottom = c.rect.y + c.rect.height;
  // A stop is said as fully as the panel has room for: explained, then with its reading, then by its reason.
  // A polygon's holonomy (view.sphere.holonomy) takes a line under the runs: the sphere panel leaves its caption to it.
  const SphereDecoration* decoration = c.frame.sphereDecoration.get();
  const bool holonomy = decoration && decoration->transport;
  const float holonomyLine = holonomy ? c.font.lineHeight(TextSize::Small) : 0.0f;
  for (const TextSize size : {TextSize::Normal, TextSize::Small}) {
    for (const StopDetail detail : {StopDetail::Explained, StopDetail::Measured, StopDetail::Reason}) {
      if (flowRuns(c, size, detail, pad, firstRow, nullptr) + holonomyLine <= bottom) {
        const float end = flowRuns(c, size, detail, pad, firstRow, &batch);
        if (holonomy)
          c.font.draw(batch,
                      fittedForm(c.font, transportCaptions(*decoration->transport, c.frame.time, c.frame.duration),
                                 TextSize::Small, c.rect.width - 2 * pad),
                      TextSize::Small, c.rect.x + pad, end + holonomyLine, c.page().ink);
        return;
      }
    }
  }
  const auto& runs = c.frame.runs;
  if (runs.empty()) return;
  const float share = (c.rect.width - pad) / float(runs.size());
  // Within the band: its descenders too (they were cut at 320x180).
  const float rowY = std::min(firstRow + c.font.lineHeight(TextSize::Small),
                              bottom - (c.font.lineHeight(TextSize::Small) - c.font.ascent(TextSize::Small)));
  const float swatch = 0.3f * c.font.ascent(TextSize::Small);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const RunFrame& run = runs[k];
    const float x = c.rect.x + pad + share * float(k);
    // Once stopped: "stopped t=5" where it fits in 60% of the share, else "t=5" whole (the red says it stopped).
    const std::string full = " stopped t=" + timeWords(run.stopTime), brief = " t=" + timeWords(run.stopTime);
    const float room = share - 2.5f * swatch - pad;
    const std::string stopText =
        !run.stopped ? "" : c.font.width(full, TextSize::Small) <= 0.6f * room ? full : brief;
    const std::string name = c.font.fitted(run.name, TextSize::Small, room - c.font.width(stopText, TextSize::Small));
    drawSwatch(c, k, TextSize::Small, x, rowY, batch);
    const float end = c.font.draw(batch, name, TextSize::Small, x + 2.5f * swatch, rowY, c.page().ink);
    if (!stopText.empty()) c.font.draw(batch, stopText, TextSize::Small, end, rowY, c.page().stopRed);
  }
}

void drawTitleLine(const PanelContext& c, ShapeBatch& batch) {
  const float pad = 0.015f * c.rect.width;
  const float line = c.font.lineHeight(TextSize::Normal);
  const float y = c.rect.y + 0.3f * line + c.font.ascent(TextSize::Normal);
  const std::string time = "t = " + format("%.2f", c.frame.time) + " / " + format("%.2f", c.frame.duration);
  const float timeWidth = c.font.width(time, TextSize::Normal);
  const std::string title = shownTitle(c.font, c.frame, TextSize::Normal, c.rect.width - timeWidth - 4 * pad);
  // On a veil of the background, so that a panel reaching up under the line never makes it unreadable.
  const float titleWidth = c.font.width(title, TextSize::Normal);
  const ColorRGB& b = c.settings.background;
  const Rgba veil{b.r, b.g, b.b, 0.75f};
  const float band = titleLineHeight(c.font);
  batch.rect(c.rect.x + 0.5f * pad, c.rect.y, c.rect.x + 1.5f * pad + titleWidth, c.rect.y + band, veil);
  batch.rect(c.rect.x + c.rect.width - 1.5f * pad - timeWidth, c.rect.y, c.rect.x + c.rect.width - 0.5f * pad,
             c.rect.y + band, veil);
  c.font.draw(batch, title, TextSize::Normal, c.rect.x + pad, y, c.page().ink);
  c.font.draw(batch, time, TextSize::Normal, c.rect.x + c.rect.width - pad - timeWidth, y, c.page().ink);
}

}  // namespace sl

#include "render/frame_words.hpp"

#include <cctype>
#include <cstdio>

#include "contracts/stop_reading.hpp"

namespace sl {

std::string methodWords(Method method) { return nameOf(method); }

std::string stopReasonWords(StopReason reason) { return nameOf(reason); }

std::string stopMeaningWords(StopReason reason) {
  // The registry's sentence is ASCII (help texts, docs); a frame typesets its "+-pi".
  std::string meaning(traits(reason).meaning);
  for (std::size_t at; (at = meaning.find("+-pi")) != std::string::npos;) meaning.replace(at, 4, "\u00b1\u03c0");
  return meaning;
}

namespace {

// Hyphens used as minus signs (before a digit, after a start, a space, "e" or "(") become U+2212.
std::string withMinusSigns(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool minus = text[i] == '-' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])) &&
                       (i == 0 || text[i - 1] == ' ' || text[i - 1] == 'e' || text[i - 1] == '(');
    out += minus ? "\u2212" : std::string(1, text[i]);
  }
  return out;
}

}  // namespace

std::string typesetNumber(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return withMinusSigns(text);
}

std::string stopReadingWords(const RunFrame& run) {
  return withMinusSigns(stopReading(run.stopReason, run.stopMeasured, run.stopLimit));
}

std::vector<std::string> plotTitles(const PlotFrame& plot) {
  switch (plot.kind) {  // every kind, no default: the compiler names a kind left out
    case PlotKind::Divergence:
      return {"divergence from " + plot.referenceRun + " (max hinge distance)", "divergence from " + plot.referenceRun,
              "divergence"};
    case PlotKind::EnergyError:
      return {"relative energy error |E \u2212 E\u2080| / E\u2080", "energy error |E \u2212 E\u2080| / E\u2080",
              "energy error"};
    case PlotKind::Jacobi:
      return {"Jacobi field across the motion |J\u22a5| (zeros: conjugate points)",
              "Jacobi field |J\u22a5| (zeros: conjugate points)", "Jacobi field |J\u22a5|", "|J\u22a5|"};
    case PlotKind::Spread:
      return {"spread of the family (largest hinge distance from the run)", "spread of the family", "spread"};
  }
  return {""};
}

std::string emptyPlotNote(const PlotFrame& plot) {
  switch (plot.emptiness) {  // every case, no default
    case PlotEmptiness::HasValues:
      return "";
    case PlotEmptiness::RunsStopped: {
      std::string why;
      for (const EarlyStop& stop : plot.earlyStops) {
        char time[32];
        std::snprintf(time, sizeof time, "%.3g", stop.time);
        why += (why.empty() ? "" : "; ") + ("\"" + stop.run + "\" stopped at t = " + time + " (" +
                                            stopReasonWords(stop.reason) + ")");
      }
      return "nothing to plot: " + why;
    }
    case PlotEmptiness::ZeroOnLogAxis:
      return "nothing to plot: every value is 0 (a log axis cannot show it)";
    case PlotEmptiness::NothingToPlot:
      return "nothing to plot";
  }
  return "";
}

std::vector<std::string> fieldCaptions(SphereColoring coloring) {
  switch (coloring) {  // every colouring, no default
    case SphereColoring::None:
      return {""};
    case SphereColoring::Curvature:
      return {"K, Gaussian curvature", "K, curvature", "K"};
    case SphereColoring::Bending:
      return {"|II|\u00b2, bending", "|II|\u00b2"};
  }
  return {""};
}

std::vector<std::string> ellipseCaptions() {
  return {"ellipses: stiffness |II(v,v)|\u00b2 over directions v, half-axes ~ \u221amax, \u221amin",
          "ellipses: stiffness |II(v,v)|\u00b2 over directions v", "ellipses: stiffness"};
}

std::string fittedForm(const FontAtlas& font, const std::vector<std::string>& forms, TextSize size, float width) {
  for (const std::string& form : forms)
    if (font.width(form, size) <= width) return form;
  return forms.empty() ? "" : font.fitted(forms.back(), size, width);
}

}  // namespace sl

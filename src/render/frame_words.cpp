#include "render/frame_words.hpp"

#include <cmath>

#include <cctype>
#include <algorithm>
#include <cstdio>
#include <sstream>

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

std::string superscript(int exponent) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string text = exponent < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(exponent))) text += digits[c - '0'];
  return text;
}

std::string typesetPowerOfTen(double value) {
  if (!(value > 0) || !std::isfinite(value)) return "0";
  int exponent = int(std::floor(std::log10(value)));
  long digit = std::lround(value / std::pow(10.0, exponent));
  if (digit >= 10) digit = 1, ++exponent;
  return (digit == 1 ? std::string() : std::to_string(digit) + "×") + "10" + superscript(exponent);
}

std::string stopReadingWords(const RunFrame& run) {
  return withMinusSigns(stopReading(run.stopReason, run.stopMeasured, run.stopLimit));
}

std::vector<std::string> plotTitles(const PlotFrame& plot) {
  switch (plot.kind) {  // every kind, no default: the compiler names a kind left out
    case PlotKind::Divergence:
      return {"divergence from " + plot.referenceRun + ": max hinge distance", "divergence from " + plot.referenceRun,
              "divergence"};
    case PlotKind::EnergyError:
      return {"relative energy error |E \u2212 E\u2080| / E\u2080", "energy error |E \u2212 E\u2080| / E\u2080",
              "energy error"};
    case PlotKind::Jacobi:
      return {"Jacobi field across the motion |J\u22a5| (zeros: conjugate points)",
              "Jacobi field |J\u22a5| (zeros: conjugate points)", "Jacobi field |J\u22a5|", "|J\u22a5|"};
    case PlotKind::Spread:
      return {"spread of the family (largest hinge distance from the run)", "spread of the family", "spread"};
    case PlotKind::Sectional:
      return {"curvature of the planes through the velocity: largest and smallest K(v, \u00b7)",
              "curvature of the planes through the velocity", "curvature through the velocity", "K(v, \u00b7)"};
    case PlotKind::Holonomy:
      return {"\u222bK dA swept by the sides so far: at the end, the holonomy", "\u222bK dA swept by the sides so far",
              "\u222bK dA swept", "holonomy"};
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
        why += (why.empty() ? "" : "; ") + ("\"" + stop.run + "\" stopped at t = " + timeWords(stop.time) + " (" +
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

std::vector<std::string> roundoffNotes(const PlotFrame& plot) {
  if (!plot.roundoff) return {};
  const PlotFrame::RoundoffOnly& r = *plot.roundoff;
  const std::string level = r.largest > 0 ? "to " + typesetPowerOfTen(r.largest) : "exactly";
  switch (plot.kind) {  // every kind, no default
    case PlotKind::EnergyError: {
      const std::string conserved = "energy conserved " + level;
      const std::string whole = conserved + (r.runs > 1 ? " by every run" : " over the run");
      if (!r.byTolerance) return {whole, conserved};
      return {whole + ", as its integrator's tolerance allows", conserved + ", as the tolerance allows", conserved};
    }
    case PlotKind::Divergence:
      return {"the runs agree " + level + " (largest hinge distance)", "the runs agree " + level};
    case PlotKind::Jacobi:
    case PlotKind::Spread:
    case PlotKind::Sectional:
    case PlotKind::Holonomy:
      return {};
  }
  return {};
}

std::string valueAxisWords(PlotKind kind) {
  switch (kind) {  // every kind, no default
    case PlotKind::Divergence:
    case PlotKind::Spread:
      return "hinge distance (rod lengths)";
    case PlotKind::Jacobi:
      return "|J⊥| (metric units)";
    case PlotKind::EnergyError:
      return "|E − E₀| / E₀ (no unit)";
    case PlotKind::Sectional:
      return "sectional curvature K";
    case PlotKind::Holonomy:
      return "angle (rad)";
  }
  return "";
}

std::vector<std::string> fieldCaptions(SphereColoring coloring, bool fromStart) {
  switch (coloring) {  // every colouring, no default
    case SphereColoring::None:
      return {""};
    case SphereColoring::Curvature:
      return {"K, Gaussian curvature", "K, curvature", "K"};
    case SphereColoring::Bending:
      return {"|II|\u00b2, bending", "|II|\u00b2"};
    case SphereColoring::Distance:  // the kinetic length: seconds of a unit-speed motion
      if (fromStart)
        return {"distance from the start (s at unit speed)", "distance from the start (s)", "distance (s)", "dist. (s)", "d (s)"};
      return {"distance from the marked shape (s at unit speed)", "distance from the mark (s)", "distance (s)", "dist. (s)",
              "d (s)"};
  }
  return {""};
}

std::string curveName(SphereCurveKind kind) {
  switch (kind) {  // every kind, no default
    case SphereCurveKind::ConjugateLocus:
      return "conjugate locus";
    case SphereCurveKind::CutLocus:
      return "cut locus";
    case SphereCurveKind::ClosedGeodesic:
      return "closed geodesic";
  }
  return "";
}

std::vector<std::string> twoSlopeNotes() { return {"each sign on its own scale", "two scales"}; }

std::vector<std::string> injectivityNotes(double radius, bool fromStart) {
  // As the scene's title gives it (5 digits, title placeholders) where there is room, else 3.
  char full[32], brief[32];
  std::snprintf(full, sizeof full, "%.5g", radius);
  std::snprintf(brief, sizeof brief, "%.3g", radius);
  const std::string from = std::string("from the ") + (fromStart ? "start" : "marked shape") + "; injectivity radius ";
  return {from + full, from + brief, std::string("injectivity radius ") + brief, std::string("inj. radius ") + brief,
          std::string("inj. ") + brief};
}

std::vector<std::string> familyCaptions(std::size_t members) {
  const std::string n = std::to_string(members);
  return {"large ball: the run; thin paths and small dots: its " + n + " members; dark curve: their wavefront",
          "ball: the run; lines and dots: its " + n + " members; dark curve: wavefront",
          "ball: run; dots: " + n + " members; dark: wavefront"};
}

std::vector<std::string> ellipseCaptions() {
  return {"ellipses: stiffness |II(v,v)|\u00b2 over directions v, half-axes ~ \u221amax, \u221amin",
          "ellipses: stiffness |II(v,v)|\u00b2 over directions v", "ellipses: stiffness"};
}

// Gauss-Bonnet said once the vector is back; on the way, what the sides have swept so far (the holonomy plot's
// value at this time).
std::vector<std::string> transportCaptions(const SphereTransport& transport, double time, double duration) {
  auto fixed = [](double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return withMinusSigns(text);
  };
  const std::size_t m = transport.corners.size();
  const std::string polygon = m == 3 ? "triangle" : m == 4 ? "quadrilateral" : std::to_string(m) + "-gon";
  const double reached = SphereTransport::carriedFraction(time, duration);
  if (reached < 1.0) {
    const std::string swept = fixed(transport.sweptAt(reached), 3);
    return {"arrows: each side of the " + polygon +
                " carries on the vector the side before brings; \u222bK dA swept "
                "so far = " +
                swept + " rad",
            "arrows: a vector carried round the " + polygon + "; \u222bK dA swept so far = " + swept + " rad",
            "\u222bK dA swept so far = " + swept + " rad", "swept " + swept + " rad"};
  }
  const std::string excess = m == 3 ? "angle sum \u2212 \u03c0" : "angle sum \u2212 " + std::to_string(m - 2) + "\u03c0";
  const std::string h = fixed(transport.holonomy, 3), degrees = fixed(transport.holonomy * 180 / M_PI, 1) + "\u00b0";
  const std::string e = fixed(transport.angleExcess, 3), k = fixed(transport.enclosedCurvature, 3);
  return {"arrows: a vector carried round the " + polygon + " comes back turned: " + excess + " = " + e +
              " = \u222bK dA = " + k + " = holonomy " + h + " rad (" + degrees + ")",
          excess + " = " + e + " = \u222bK dA = " + k + " = holonomy " + h + " rad (" + degrees + ")",
          excess + " = \u222bK dA = holonomy = " + h + " rad (" + degrees + ")", "holonomy " + h + " rad (" + degrees + ")",
          "holonomy " + degrees};
}

std::vector<std::string> chartPoleLabels(bool north) {
  if (north) return {"chart pole \u03c6 = 90\u00b0", "\u03c6 = 90\u00b0", "N"};
  return {"chart pole \u03c6 = \u221290\u00b0", "\u03c6 = \u221290\u00b0", "S"};
}

std::vector<std::string> seamLabels() { return {"seam t = \u00b1\u03c0/2", "seam"}; }

std::vector<std::string> scaleBreakWords() { return {"scale changes at", "scale break at"}; }

std::string fittedForm(const FontAtlas& font, const std::vector<std::string>& forms, TextSize size, float width) {
  for (const std::string& form : forms)
    if (font.width(form, size) <= width) return form;
  return forms.empty() ? "" : font.fitted(forms.back(), size, width);
}

std::string shownTitle(const FontAtlas& font, const FrameState& frame, TextSize size, float width) {
  std::vector<std::string> forms{frame.title};
  if (!frame.shortTitle.empty()) forms.push_back(frame.shortTitle);
  return fittedForm(font, forms, size, width);
}

std::string fittedWrappedForm(const FontAtlas& font, const std::vector<std::string>& forms, TextSize size, float width,
                              std::size_t lines) {
  const auto wordsIn = [](const std::string& text) {
    std::istringstream in(text);
    std::size_t count = 0;
    for (std::string word; in >> word;) ++count;
    return count;
  };
  for (const std::string& form : forms) {
    // Fits when wrapping into one line more than allowed needs no more, and every word is there uncut.
    const std::vector<std::string> wrapped = font.wrapped(form, size, width, lines + 1);
    std::size_t kept = 0;
    bool cut = false;
    for (const std::string& line : wrapped) {
      kept += wordsIn(line);
      cut = cut || line.find("\u2026") != std::string::npos;
    }
    if (wrapped.size() <= lines && !cut && kept == wordsIn(form)) return form;
  }
  return "";
}

std::vector<std::string> wrappedFittedForm(const FontAtlas& font, const std::vector<std::string>& forms, TextSize size,
                                           float width, std::size_t lines) {
  std::string shown = fittedWrappedForm(font, forms, size, width, lines);
  if (shown.empty() && !forms.empty()) shown = forms.back();
  return font.wrapped(shown, size, width, lines);
}

std::string timeWords(double t) {
  std::string text = typesetNumber("%.2f", t);
  // Hundredths without trailing zeros: 3.50 -> 3.5, 3.00 -> 3 (typesetNumber always writes the two decimals).
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text == "\u22120" ? "0" : text;
}

}  // namespace sl

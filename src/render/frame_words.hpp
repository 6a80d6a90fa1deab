#pragma once
// The words a frame shows, made from the FrameState's kinds and numbers here at the rendering edge, and nowhere
// else: a run's method, why it stopped, a plot's title and why it stays empty, the captions of the sphere's
// colour bar and stiffness ellipses. Symbols are typeset (|J⊥|, E₀, √, ±π, the minus sign U+2212 in numbers).
// Titles and captions come in forms, longest first: a small frame shows the longest that fits (fittedForm),
// never a word cut in the middle. Each switches on every kind without a default, so a kind added to
// contracts/registry.hpp is named by the compiler here.

#include <string>
#include <vector>

#include "contracts/frame_state.hpp"
#include "render/font_atlas.hpp"

namespace sl {

std::string methodWords(Method method);              // e.g. "christoffel-fd"
std::string stopReasonWords(StopReason reason);      // e.g. "pole-fold-back"
std::string stopMeaningWords(StopReason reason);     // what the reason means, in a sentence
std::string stopReadingWords(const RunFrame& run);   // e.g. "energy drift 2.13 > limit 1"; empty without a reading
std::string emptyPlotNote(const PlotFrame& plot);    // why the plot stays empty; empty if it does not
// What a plot whose values lie within roundoff says, in forms, longest first ("energy conserved to 3×10⁻¹⁵ over the
// run" down to "energy conserved to 3×10⁻¹⁵": a small frame cut the longest); empty where there is no note.
std::vector<std::string> roundoffNotes(const PlotFrame& plot);
std::string valueAxisWords(PlotKind kind);           // what the y axis shows, in what unit

// Forms, longest first.
std::vector<std::string> plotTitles(const PlotFrame& plot);       // e.g. "relative energy error |E − E₀| / E₀"
// The colour bar's, e.g. "K, Gaussian curvature"; the distance's from the start or from a point the scene names.
std::vector<std::string> fieldCaptions(SphereColoring coloring, bool fromStart = true);
std::vector<std::string> ellipseCaptions();            // the line explaining the stiffness ellipses
// Under a polygon's transported vector (view.sphere.holonomy): Gauss-Bonnet's three figures, e.g. "a vector carried
// round the triangle comes back turned: angle sum − π = 0.330 = ∫K dA = 0.330 = holonomy 0.330 rad (18.9°)", then
// shorter, down to "holonomy 0.330 rad".
std::vector<std::string> transportCaptions(const SphereTransport& transport, double time, double duration);
// A family's key: "large ball: the run; thin paths and small dots: its 32 members; dark curve: their wavefront",
// then shorter, down to "ball: run; dots: 32 members; dark: wavefront" (320x180 cut the longest at "its 32…").
std::vector<std::string> familyCaptions(std::size_t members);
std::vector<std::string> chartPoleLabels(bool north);  // "chart pole φ = 90°", "φ = 90°", "N" (south: −90°, "S")
std::vector<std::string> seamLabels();                 // "seam t = ±π/2", "seam"
std::vector<std::string> scaleBreakWords();  // "scale changes at", "scale break at": before a two-slope bar's zero
std::string curveName(SphereCurveKind kind);  // a curve's label on the sphere, e.g. "cut locus"
// Below the distance's colour bar: from where, and the injectivity radius, longest first, e.g. "from the start;
// injectivity radius 2.09", then "injectivity radius 2.09", "inj. radius 2.09", "inj. 2.09".
std::vector<std::string> injectivityNotes(double radius, bool fromStart);
// Below a two-slope (diverging) colour bar: "each sign on its own scale", then "two scales".
std::vector<std::string> twoSlopeNotes();

// The first of `forms` no wider than `width`; if none is, the last shortened at a word with an ellipsis.
std::string fittedForm(const FontAtlas& font, const std::vector<std::string>& forms, TextSize size, float width);
// The scene's title as a frame of that width shows it: whole, else the scene's short title, else cut at a word.
std::string shownTitle(const FontAtlas& font, const FrameState& frame, TextSize size, float width);
// The longest form that word-wraps into at most `lines` lines of that width without cutting a word; "" if none.
std::string fittedWrappedForm(const FontAtlas& font, const std::vector<std::string>& forms, TextSize size, float width,
                              std::size_t lines);
// The lines of that form, wrapped; where no form fits whole, the shortest, wrapped and cut.
std::vector<std::string> wrappedFittedForm(const FontAtlas& font, const std::vector<std::string>& forms, TextSize size,
                                           float width, std::size_t lines);

// A number as printf's `pattern` writes it, with a true minus sign (U+2212) for the sign and the exponent's.
std::string typesetNumber(const char* pattern, double value);
std::string superscript(int exponent);   // "⁻¹⁵"
std::string typesetPowerOfTen(double value);  // "3×10⁻¹⁵": a positive value to one significant digit
// A moment of the motion (a stop, a conjugate point) to the frame clock's hundredths, trailing zeros dropped:
// "19.74", "3.34", "0" (the clock says "t = 19.77 / 20.00": a stop at 19.74 read "19.7" beside it).
std::string timeWords(double t);

}  // namespace sl

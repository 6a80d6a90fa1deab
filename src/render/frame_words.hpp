#pragma once
// The words a frame shows, made from the FrameState's kinds and numbers here at the rendering edge, and nowhere
// else: a run's method, why it stopped, a plot's title and why it stays empty, the captions of the sphere's
// colour bar and stiffness ellipses. Each switches on every kind without a default, so a kind added to
// contracts/registry.hpp is named by the compiler here.

#include <string>

#include "contracts/frame_state.hpp"

namespace sl {

std::string methodWords(Method method);              // e.g. "christoffel-fd"
std::string stopReasonWords(StopReason reason);      // e.g. "pole-fold-back"
std::string stopMeaningWords(StopReason reason);     // what the reason means, in a sentence
std::string stopReadingWords(const RunFrame& run);   // e.g. "energy drift 2.13 > limit 1"; empty without a reading
std::string plotTitle(const PlotFrame& plot);        // e.g. "relative energy error |E - E0| / E0"
std::string emptyPlotNote(const PlotFrame& plot);    // why the plot stays empty; empty if it does not
std::string fieldCaption(SphereColoring coloring);   // the colour bar's, e.g. "K, Gaussian curvature"
std::string ellipseCaption();                        // the line explaining the stiffness ellipses

}  // namespace sl

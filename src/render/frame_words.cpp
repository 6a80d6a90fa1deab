#include "render/frame_words.hpp"

#include <cstdio>

#include "contracts/stop_reading.hpp"

namespace sl {

std::string methodWords(Method method) { return nameOf(method); }

std::string stopReasonWords(StopReason reason) { return nameOf(reason); }

std::string stopMeaningWords(StopReason reason) { return std::string(traits(reason).meaning); }

std::string stopReadingWords(const RunFrame& run) {
  return stopReading(run.stopReason, run.stopMeasured, run.stopLimit);
}

std::string plotTitle(const PlotFrame& plot) {
  switch (plot.kind) {  // every kind, no default: the compiler names a kind left out
    case PlotKind::Divergence:
      return "divergence from " + plot.referenceRun + " (max hinge distance)";
    case PlotKind::EnergyError:
      return "relative energy error |E - E0| / E0";
    case PlotKind::Jacobi:
      return "Jacobi field across the motion |J_perp| (zeros: conjugate points)";
    case PlotKind::Spread:
      return "spread of the family (largest hinge distance from the run)";
  }
  return "";
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

std::string fieldCaption(SphereColoring coloring) {
  switch (coloring) {  // every colouring, no default; the symbol first: it survives fitting
    case SphereColoring::None:
      return "";
    case SphereColoring::Curvature:
      return "K, Gaussian curvature";
    case SphereColoring::Bending:
      return "|II|\u00b2, bending";
  }
  return "";
}

std::string ellipseCaption() {
  return "ellipses: stiffness |II(v,v)|\u00b2 over directions v, half-axes ~ sqrt(max), sqrt(min)";
}

}  // namespace sl

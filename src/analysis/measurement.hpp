#pragma once
// One run measured against its reference: the errors, invariants, work and fate of a single point of a
// work-precision chart or a single cell of a stability map.

#include <string>

#include "analysis/reference_path.hpp"

namespace sl {

// A run that no watchdog stopped but whose path ended this far (max hinge distance) from the reference
// is a silent failure: it is reported as "wrong-path" rather than "ok".
inline constexpr double kWrongPathError = 1e-2;

// The sweeps' step budget (RunConfig::maxSteps): fixed-step runs get exactly what they need; adaptive
// runs get kAdaptiveStepsPerTimeUnit per unit of time, over twice what dopri5 needs at tolerance 1e-13. A
// method whose steps shrink without end (e.g. the published metric at a pole) then stops as "max-steps"
// in a fraction of a second instead of crawling toward the default bound of 5e7 steps.
inline constexpr double kAdaptiveStepsPerTimeUnit = 1000;
long stepBudget(const RunConfig& config, double duration);

struct Measurement {
  std::string status = "ok";  // ok | wrong-path | reference-stopped | a StopInfo reason
  double stopTime = 0;        // the run's last good time (the duration when it finished)
  std::string stopDetail;
  double finalError = 0;         // position error at the last grid time (NaN if the run stopped early)
  double maxError = 0;           // max over the grid times the run reached
  double maxEnergyDrift = 0;     // max |E - E0| / E0 over the grid times and every step's end (including the
                                 // step that runs past the last grid time)
  double maxRodLengthError = 0;  // likewise
  long evaluations = 0;          // vector-field evaluations
  long steps = 0;
  double wallSeconds = 0;  // one run: construction and sampling at the grid times
  double cpuSeconds = 0;   // the same span in this thread's CPU time (robust on a shared machine)

  bool failed() const { return status != "ok"; }
};

// Runs `config` from `start` once, sampling at the reference's grid times. With a reference that holds
// times but no hinges (noReference), only the fate and the invariants are measured; errors are NaN.
Measurement measureRun(const Chain& chain, const InitialState& start, const RunConfig& config,
                       const ReferencePath& reference);

// The median wall and CPU times of `repeats` runs (the measurement of the first; runs are deterministic).
Measurement measureRunTimed(const Chain& chain, const InitialState& start, const RunConfig& config,
                            const ReferencePath& reference, int repeats);

}  // namespace sl

#pragma once
// One run measured against its reference: the errors, invariants, work and fate of a single point of a
// work-precision chart or a single cell of a stability map.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "analysis/reference_path.hpp"
#include "contracts/registry.hpp"

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

// The measurement's own verdicts, beside the reasons a run stops (kStopReasons).
enum class Verdict {
  Ok,               // finished within kWrongPathError of the reference (or unchecked)
  WrongPath,        // finished, but off the reference's path
  ReferenceStopped  // the reference itself stopped: no verdict on the run
};
inline constexpr std::array<Named<Verdict>, 3> kVerdicts{{
    {Verdict::Ok, "ok"},
    {Verdict::WrongPath, "wrong-path"},
    {Verdict::ReferenceStopped, "reference-stopped"},
}};
inline std::string nameOf(Verdict v) { return std::string(traitsOf(kVerdicts, v).name); }

// What became of a run: a verdict, or why it stopped before the last grid time.
using RunStatus = std::variant<Verdict, StopReason>;

// The status as the CSVs write it: the verdict's or the stop reason's name.
std::string statusName(const RunStatus& status);
// The status of a name written by statusName; empty for any other text.
std::optional<RunStatus> parseStatus(std::string_view name);

struct Measurement {
  RunStatus status = Verdict::Ok;
  double stopTime = 0;  // the run's last good time (the duration when it finished)
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

  bool failed() const { return status != RunStatus(Verdict::Ok); }
};

// Runs `config` from `start` once, sampling at the reference's grid times. With a reference that holds
// times but no run (noReference), only the fate and the invariants are measured; errors are NaN.
Measurement measureRun(const Chain& chain, const InitialState& start, const RunConfig& config,
                       const ReferencePath& reference);

// The median wall and CPU times of `repeats` runs (the measurement of the first; runs are deterministic).
Measurement measureRunTimed(const Chain& chain, const InitialState& start, const RunConfig& config,
                            const ReferencePath& reference, int repeats);

}  // namespace sl

#include "analysis/measurement.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <vector>

#include "simulation/trajectory.hpp"

namespace sl {

std::string statusName(const RunStatus& status) {
  return std::visit([](auto kind) { return nameOf(kind); }, status);
}

std::optional<RunStatus> parseStatus(std::string_view name) {
  if (const auto verdict = parseKind(kVerdicts, name)) return *verdict;
  if (const auto reason = parseKind(kStopReasons, name)) return *reason;
  return std::nullopt;
}

namespace {

struct RunRecord {
  std::vector<Sample> samples;
  std::optional<StopInfo> stop;
  InvariantExtremes atSteps;
  long evaluations = 0, steps = 0;
  double wallSeconds = 0, cpuSeconds = 0;
};

double threadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

RunRecord recordRun(const Chain& chain, const InitialState& start, const RunConfig& config,
                    const std::vector<double>& times) {
  RunRecord record;
  record.samples.reserve(times.size());
  const auto begin = std::chrono::steady_clock::now();
  const double cpuBegin = threadCpuSeconds();
  Trajectory run(chain, start, config);
  for (double time : times) {
    auto sample = run.sampleAt(time);
    if (!sample) break;
    record.samples.push_back(std::move(*sample));
  }
  record.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  record.cpuSeconds = threadCpuSeconds() - cpuBegin;
  record.stop = run.stop();
  record.atSteps = run.invariantExtremes();
  record.evaluations = run.vectorFieldEvaluations();
  record.steps = run.steps();
  return record;
}

Measurement compare(const RunRecord& record, const ReferencePath& reference) {
  Measurement m;
  m.evaluations = record.evaluations;
  m.steps = record.steps;
  m.wallSeconds = record.wallSeconds;
  m.cpuSeconds = record.cpuSeconds;
  m.maxEnergyDrift = record.atSteps.maxRelativeEnergyDrift;
  m.maxRodLengthError = record.atSteps.maxRodLengthError;
  for (const Sample& sample : record.samples) {
    m.maxEnergyDrift = std::max(m.maxEnergyDrift, std::abs(sample.relativeEnergyDrift));
    m.maxRodLengthError = std::max(m.maxRodLengthError, sample.rodLengthError);
  }
  const bool checked = reference.config.has_value();
  const size_t compared = std::min(record.samples.size(), reference.hinges.size());
  m.maxError = checked ? 0.0 : std::nan("");
  for (size_t k = 0; k < compared; ++k) {
    const double error = hingeDistance(record.samples[k].hinges, reference.hinges[k]);
    if (!(error <= m.maxError)) m.maxError = error;  // std::max would drop a NaN; it must reach the report
  }
  const bool finished = record.samples.size() == reference.times.size();
  m.stopTime = record.samples.empty() ? 0.0 : record.samples.back().time;
  m.finalError = finished && compared == record.samples.size()
                     ? hingeDistance(record.samples.back().hinges, reference.hinges.back())
                     : std::nan("");
  if (reference.stop) {
    m.status = Verdict::ReferenceStopped;
    m.stopDetail = referenceMethodName(reference) + ": " + nameOf(reference.stop->reason) + " at time " +
                   std::to_string(reference.stop->time) + ": " + reference.stop->detail();
  } else if (record.stop && !finished) {
    m.status = record.stop->reason;
    m.stopTime = record.stop->time;
    m.stopDetail = record.stop->detail();
  } else if (checked && !(m.maxError < kWrongPathError)) {
    m.status = Verdict::WrongPath;
  }
  return m;
}

}  // namespace

long stepBudget(const RunConfig& config, double duration) {
  if (!traits(config.integrator).adaptive) return static_cast<long>(std::ceil(duration / config.step)) + 10;
  return std::max(1000L, static_cast<long>(std::ceil(kAdaptiveStepsPerTimeUnit * duration)));
}

Measurement measureRun(const Chain& chain, const InitialState& start, const RunConfig& config,
                       const ReferencePath& reference) {
  return compare(recordRun(chain, start, config, reference.times), reference);
}

Measurement measureRunTimed(const Chain& chain, const InitialState& start, const RunConfig& config,
                            const ReferencePath& reference, int repeats) {
  RunRecord first = recordRun(chain, start, config, reference.times);
  std::vector<double> wall{first.wallSeconds}, cpu{first.cpuSeconds};
  for (int r = 1; r < repeats; ++r) {
    const RunRecord again = recordRun(chain, start, config, reference.times);
    wall.push_back(again.wallSeconds);
    cpu.push_back(again.cpuSeconds);
  }
  Measurement m = compare(first, reference);
  m.wallSeconds = median(wall);
  m.cpuSeconds = median(cpu);
  return m;
}

}  // namespace sl

#pragma once
// A stability sweep: every method run from every cell of a grid of starts (stability_grid.hpp), each
// measured against a reference from a different method (reference_path.hpp), on parallelFor's threads.
// Rows come out in cell order whatever the thread count, so the output bytes depend only on the sweep.
// A sweep splits into shards (cells c with c mod N = K - 1) whose rows merge into the same table.

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/csv_table.hpp"
#include "analysis/measurement.hpp"
#include "analysis/stability_grid.hpp"
#include "contracts/registry.hpp"
#include "contracts/run_config.hpp"

namespace sl {

struct Shard {
  int index = 1;  // K, 1-based
  int count = 1;  // N
};

// Parses "K/N" (1 <= K <= N); throws std::invalid_argument saying what was expected.
Shard parseShard(const std::string& text);

struct StabilityOptions {
  std::string kind = "launch";
  int grid = 64;
  double duration = 20;
  double sampleInterval = 0.1;
  std::vector<Method> methods;           // empty: every method of the registry (kMethods)
  std::optional<Integrator> integrator;  // empty: each method's sweep default (sweepIntegratorFor)
  double tolerance = RunConfig().tolerance;
  double step = RunConfig().step;
  bool checkAgainstReference = true;  // false: fate and invariants only (no reference runs: much faster)
  int threads = 0;                    // 0: as many as the machine has (defaultThreadCount)
  Shard shard;
};

// Called after each cell with (cells done, cells in this shard); from worker threads, serialised.
using CellProgress = std::function<void(long done, long total)>;

// The integrator a method is swept with when none is given: rk4 for the published methods (the spec's
// demo integrates them with RK4; adaptive steps crawl at their poles), the default run's integrator
// (RunConfig) for the others.
Integrator sweepIntegratorFor(Method method);

std::vector<std::string> stabilityColumns();

// One row of a sweep: one method run from one cell. A cell whose start could not be made has no point and no
// errors (NaN: written as empty fields).
struct StabilityRow {
  long cell = 0;
  int i = 0, j = 0;  // cell = j * grid + i
  double x = 0, y = 0;
  Method method = Method::Ambient;
  Integrator integrator = Integrator::Dopri5;
  double setting = 0;  // RunConfig::accuracySetting
  RunStatus status = Verdict::Ok;
  double stopTime = 0, finalError = 0, maxError = 0, maxEnergyDrift = 0, maxRodLengthError = 0;
  long evaluations = 0;
  std::string referenceMethod;  // a method's name, or kNoReferenceName
  std::string stopDetail;
};

// Runs the shard's cells; returns the rows in cell order, one per cell and method.
std::vector<StabilityRow> runStabilitySweep(const StabilityOptions& options, const CellProgress& progress = {});

// The rows as the CSV writes them (stabilityColumns): shortest round-trip numbers, no value as an empty field.
CsvTable stabilityTable(const std::vector<StabilityRow>& rows);

// The whole job a sweep's rows depend on, as ordered key=value pairs: kind, grid, duration, interval, methods,
// integrators, tolerance, step, references. Every shard file records it; shards of different jobs never merge.
std::vector<std::pair<std::string, std::string>> stabilityIdentity(const StabilityOptions& options);

// A shard file's text: a first line "# linkage stability shard: key=value; ..." (stabilityIdentity), then the
// rows' CSV.
std::string stabilityShardText(const StabilityOptions& options, const std::vector<StabilityRow>& rows);

// === Files: DIR/stability-<kind>.csv, shards DIR/stability-<kind>.shard-K-of-N.csv

// At most this many shards of one sweep (a 4096 x 4096 grid has 16.8 million cells).
inline constexpr int kMaxShards = 1'000'000;
std::string stabilityCsvPath(const std::string& outDir, const std::string& kind);
std::string stabilityShardPath(const std::string& outDir, const std::string& kind, const Shard& shard);

// Rows of all shards of a sweep, in cell order. A shard file is input, read as strictly as a scene: throws
// std::invalid_argument naming the file (and row) if it has no identity line, if its identity differs from
// another shard's (naming what differs), if a field is not what its column holds, or if its rows are not
// exactly its cells (c mod N = K - 1) with every method of its identity, in order. Returns false (and leaves
// `merged` alone) if not all N shard files exist yet.
bool mergeStabilityShards(const std::string& outDir, const std::string& kind, int shardCount,
                          std::vector<StabilityRow>& merged);

// The shard counts N for which DIR holds shard files of this kind.
std::vector<int> stabilityShardCounts(const std::string& outDir, const std::string& kind);

// === Summary per method: fractions of the grid within 1e-6 and 1e-9 (status ok), and failure counts
std::vector<std::string> stabilitySummaryColumns();
CsvTable stabilitySummary(const std::vector<StabilityRow>& rows);

// The statuses of the rows in map order (code = index; also the summary's column order): the measurement's
// verdicts and the runs' stop reasons, ok first, then "other" for any other text.
std::vector<std::string> stabilityStatusNames();
int stabilityStatusCode(const std::string& status);

}  // namespace sl

#pragma once
// A stability sweep: every method run from every cell of a grid of starts (stability_grid.hpp), each
// measured against a reference from a different method (reference_path.hpp), on parallelFor's threads.
// Rows come out in cell order whatever the thread count, so the output bytes depend only on the sweep.
// A sweep splits into shards (cells c with c mod N = K - 1) whose rows merge into the same table.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/csv_table.hpp"
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

// Runs the shard's cells; returns the rows in cell order, one per cell and method.
CsvTable runStabilitySweep(const StabilityOptions& options, const CellProgress& progress = {});

// === Files: DIR/stability-<kind>.csv, shards DIR/stability-<kind>.shard-K-of-N.csv

// At most this many shards of one sweep (a 4096 x 4096 grid has 16.8 million cells).
inline constexpr int kMaxShards = 1'000'000;
std::string stabilityCsvPath(const std::string& outDir, const std::string& kind);
std::string stabilityShardPath(const std::string& outDir, const std::string& kind, const Shard& shard);

// Rows of all shards of a sweep, in cell order. Throws std::invalid_argument naming the file and row of what
// is wrong in a shard, or the cells missing from the union (it must be the full grid x grid). Returns false
// (and leaves `merged` alone) if not all N shard files exist yet.
bool mergeStabilityShards(const std::string& outDir, const std::string& kind, int shardCount, CsvTable& merged);

// The shard counts N for which DIR holds shard files of this kind.
std::vector<int> stabilityShardCounts(const std::string& outDir, const std::string& kind);

// === Summary per method: fractions of the grid within 1e-6 and 1e-9 (status ok), and failure counts
std::vector<std::string> stabilitySummaryColumns();
CsvTable stabilitySummary(const CsvTable& rows);

// The statuses of the rows in map order (code = index; also the summary's column order): the measurement's
// verdicts and the runs' stop reasons, ok first, then "other" for any other text.
std::vector<std::string> stabilityStatusNames();
int stabilityStatusCode(const std::string& status);

}  // namespace sl

#pragma once
// The trajectory CSV written by `linkage simulate` and compared by `linkage diff`: one row per sample time,
//   run,time,phi,t,phidot,tdot,energy,p1x,p1y,...,p(n-1)x,p(n-1)y,status       (4 rods)
//   run,time,c1..c(n-2),v1..v(n-2),energy,p1x,...,status                         (other n)
// Chart-0 coordinates (t unwrapped) and rates, energy = (1/2) g(v, v). status is "ok", or the stop reason on
// one final row at the stop time of a stopped run. Numbers are shortest round-trip decimals (std::to_chars),
// so the file is deterministic and reads back to the same doubles.
// Two optional columns (TrajectoryCsvLayout), present only when a scene asks for them:
//   member   after run: 0 for the run itself, 1..count for the members of its family (one row group each);
//   jacobi   before status: the size of the run's Jacobi field across the motion (|J_perp| for 4 rods), empty
//            for runs without Jacobi fields.

#include <iosfwd>
#include <string>
#include <vector>

#include "simulation/trajectory.hpp"

namespace sl {

struct TrajectoryCsvLayout {
  int rods = 4;
  bool memberColumn = false;
  bool jacobiColumn = false;
  bool chartColumns = true;  // false when a run's chain is slack (no chart): run,time,energy,p1x,...,status
};

std::vector<std::string> trajectoryCsvColumns(const TrajectoryCsvLayout& layout);  // run .. status
std::string trajectoryCsvHeader(const TrajectoryCsvLayout& layout);
inline std::vector<std::string> trajectoryCsvColumns(int rods) { return trajectoryCsvColumns(TrajectoryCsvLayout{rods}); }
inline std::string trajectoryCsvHeader(int rods) { return trajectoryCsvHeader(TrajectoryCsvLayout{rods}); }
// member: the member column's value (layout.memberColumn); the jacobi column holds sample.jacobi, if any.
std::string trajectoryCsvRow(const std::string& run, const Sample& sample, const std::string& status = "ok",
                             const TrajectoryCsvLayout& layout = {}, int member = 0);

// Samples the run at the given (non-decreasing) times and writes one row each; if the run stops, one last
// row at the stop time carries the reason, and later times are not written.
void writeTrajectoryCsv(std::ostream& out, const std::string& run, Trajectory& trajectory,
                        const std::vector<double>& times, bool withHeader = true, const TrajectoryCsvLayout& layout = {},
                        int member = 0);

struct TrajectoryCsv {
  std::vector<std::string> columns;  // as in the header, run .. status
  struct Row {
    std::string run;
    std::vector<double> values;  // the numeric columns between run and status (time first); an empty field is NaN
    std::string status;
  };
  std::vector<Row> rows;
  // Index into Row::values of a numeric column, -1 if absent.
  int valueIndex(const std::string& column) const;
};

// Throws std::runtime_error naming the source, the line and the column of the first problem.
TrajectoryCsv readTrajectoryCsv(std::istream& in, const std::string& sourceName);

}  // namespace sl

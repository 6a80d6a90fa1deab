#include "simulation/trajectory_csv.hpp"

#include <charconv>
#include <limits>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "contracts/csv_format.hpp"

namespace sl {

namespace {

}  // namespace

std::vector<std::string> trajectoryCsvColumns(const TrajectoryCsvLayout& layout) {
  const int rods = layout.rods;
  std::vector<std::string> columns = {"run"};
  if (layout.memberColumn) columns.push_back("member");
  columns.push_back("time");
  const int k = layout.chartColumns ? rods - 2 : 0;
  if (rods == 4 && layout.chartColumns) {
    columns.insert(columns.end(), {"phi", "t", "phidot", "tdot"});
  } else {
    for (int i = 1; i <= k; ++i) columns.push_back("c" + std::to_string(i));
    for (int i = 1; i <= k; ++i) columns.push_back("v" + std::to_string(i));
  }
  columns.push_back("energy");
  for (int j = 1; j < rods; ++j) {
    columns.push_back("p" + std::to_string(j) + "x");
    columns.push_back("p" + std::to_string(j) + "y");
  }
  if (layout.jacobiColumn) columns.push_back("jacobi");
  columns.push_back("status");
  return columns;
}

std::string trajectoryCsvHeader(const TrajectoryCsvLayout& layout) {
  std::string header;
  for (const std::string& column : trajectoryCsvColumns(layout)) header += (header.empty() ? "" : ",") + column;
  return header;
}

std::string trajectoryCsvRow(const std::string& run, const Sample& s, const std::string& status,
                             const TrajectoryCsvLayout& layout, int member) {
  std::string line = csvField(run);  // a name may hold a comma or a line break: quoted (RFC 4180)
  auto add = [&line](double v) {
    line += ',';
    appendCsvNumber(line, v);
  };
  if (layout.memberColumn) line += ',' + std::to_string(member);
  add(s.time);
  if (layout.chartColumns) {
    for (Eigen::Index i = 0; i < s.coords.size(); ++i) add(s.coords(i));
    for (Eigen::Index i = 0; i < s.rates.size(); ++i) add(s.rates(i));
  }
  add(s.energy);
  for (Eigen::Index j = 0; j < s.hinges.cols(); ++j) add(s.hinges(0, j)), add(s.hinges(1, j));
  if (layout.jacobiColumn) {
    if (s.jacobi)
      add(*s.jacobi);
    else
      line += ',';  // this run carries no Jacobi field
  }
  return line + "," + status;
}

void writeTrajectoryCsv(std::ostream& out, const std::string& run, Trajectory& trajectory,
                        const std::vector<double>& times, bool withHeader, const TrajectoryCsvLayout& given,
                        int member) {
  bool headerDone = !withHeader;
  auto emit = [&](const Sample& s, const std::string& status) {
    TrajectoryCsvLayout layout = given;
    layout.rods = static_cast<int>(s.hinges.cols()) + 1;
    if (!headerDone) out << trajectoryCsvHeader(layout) << '\n', headerDone = true;
    out << trajectoryCsvRow(run, s, status, layout, member) << '\n';
  };
  for (double t : times) {
    if (const std::optional<Sample> s = trajectory.sampleAt(t)) {
      emit(*s, "ok");
      continue;
    }
    const StopInfo& stop = *trajectory.stop();
    if (const std::optional<Sample> last = trajectory.sampleAt(stop.time)) emit(*last, nameOf(stop.reason));
    return;
  }
}

int TrajectoryCsv::valueIndex(const std::string& column) const {
  for (size_t i = 1; i + 1 < columns.size(); ++i)
    if (columns[i] == column) return static_cast<int>(i) - 1;
  return -1;
}

TrajectoryCsv readTrajectoryCsv(std::istream& in, const std::string& sourceName) {
  TrajectoryCsv csv;
  long lineNumber = 0;
  const auto next = [&](std::vector<std::string>& fields) {
    try {
      return readCsvRecord(in, fields, lineNumber);
    } catch (const std::invalid_argument& error) {
      throw std::runtime_error(sourceName + ":" + std::to_string(lineNumber) + ": " + error.what());
    }
  };
  if (!next(csv.columns)) throw std::runtime_error(sourceName + ": empty file, expected a trajectory CSV header");
  const bool memberFirst = csv.columns.size() > 2 && csv.columns[1] == "member";
  if (csv.columns.size() < 4 || csv.columns.front() != "run" || csv.columns[memberFirst ? 2 : 1] != "time" ||
      csv.columns.back() != "status") {
    std::string header;
    for (const std::string& column : csv.columns) header += (header.empty() ? "" : ",") + column;
    throw std::runtime_error(sourceName + ":1: expected a header 'run,[member,]time,...,status', got '" + header + "'");
  }
  std::vector<std::string> fields;
  while (next(fields)) {
    if (fields.size() == 1 && fields[0].empty()) continue;
    const std::string where = sourceName + ":" + std::to_string(lineNumber);
    if (fields.size() != csv.columns.size())
      throw std::runtime_error(where + ": expected " + std::to_string(csv.columns.size()) + " fields, got " +
                               std::to_string(fields.size()));
    TrajectoryCsv::Row row;
    row.run = fields.front();
    row.status = fields.back();
    for (size_t i = 1; i + 1 < fields.size(); ++i) {
      double value = 0;
      const std::string& f = fields[i];
      if (f.empty()) {  // an optional value this row does not have (the jacobi column of a run without it)
        row.values.push_back(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      const auto result = std::from_chars(f.data(), f.data() + f.size(), value);
      if (result.ec != std::errc() || result.ptr != f.data() + f.size())
        throw std::runtime_error(where + ": column '" + csv.columns[i] + "': expected a number, got '" + f + "'");
      row.values.push_back(value);
    }
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

}  // namespace sl

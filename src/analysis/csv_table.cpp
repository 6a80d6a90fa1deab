#include "analysis/csv_table.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace sl {

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

double parseNumber(const std::string& text) {
  if (text == "nan") return std::nan("");
  if (text == "inf") return INFINITY;
  if (text == "-inf") return -INFINITY;
  double value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size())
    throw std::invalid_argument("not a number: '" + text + "'");
  return value;
}

size_t CsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::out_of_range("no column '" + name + "'");
}

double CsvTable::number(size_t row, const std::string& name) const {
  return parseNumber(rows.at(row).at(column(name)));
}

const std::string& CsvTable::text(size_t row, const std::string& name) const { return rows.at(row).at(column(name)); }

namespace {

void writeField(std::ostream& out, const std::string& field) {
  if (field.find_first_of(",\"\n") == std::string::npos) {
    out << field;
    return;
  }
  out << '"';
  for (char c : field) out << (c == '"' ? "\"\"" : std::string(1, c));
  out << '"';
}

void writeRow(std::ostream& out, const std::vector<std::string>& fields) {
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i) out << ',';
    writeField(out, fields[i]);
  }
  out << '\n';
}

// Splits one record; a quoted field may span lines, so more lines are pulled from `in` as needed.
std::vector<std::string> splitRecord(std::string line, std::istream& in) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0;; ++i) {
    if (i == line.size()) {
      if (!quoted) break;
      std::string next;
      if (!std::getline(in, next)) throw std::invalid_argument("unterminated quoted field");
      line += '\n' + next;
    }
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

void writeCsv(std::ostream& out, const CsvTable& table) {
  writeRow(out, table.columns);
  for (const auto& row : table.rows) writeRow(out, row);
}

std::string csvText(const CsvTable& table) {
  std::ostringstream out;
  writeCsv(out, table);
  return out.str();
}

CsvTable readCsv(std::istream& in, const std::string& source) {
  CsvTable table;
  std::string line;
  long lineNumber = 0;
  try {
    if (!std::getline(in, line)) throw std::invalid_argument("empty file, expected a header row");
    ++lineNumber;
    table.columns = splitRecord(line, in);
    while (std::getline(in, line)) {
      ++lineNumber;
      if (line.empty()) continue;
      auto fields = splitRecord(line, in);
      if (fields.size() != table.columns.size())
        throw std::invalid_argument("expected " + std::to_string(table.columns.size()) + " fields, found " +
                                    std::to_string(fields.size()));
      table.rows.push_back(std::move(fields));
    }
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(source + ":" + std::to_string(lineNumber) + ": " + error.what());
  }
  return table;
}

CsvTable readCsvFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open for reading");
  return readCsv(in, path);
}

}  // namespace sl

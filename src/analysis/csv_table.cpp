#include "analysis/csv_table.hpp"

#include <algorithm>

#include "contracts/csv_format.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace sl {

std::string formatNumber(double value) {
  std::string text;
  appendCsvNumber(text, value);  // a failed run's error, say, is no value: an empty field
  return text;
}

double parseNumber(const std::string& text) {
  if (text.empty()) return std::nan("");
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

void writeRow(std::ostream& out, const std::vector<std::string>& fields) {
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i) out << ',';
    out << csvField(fields[i]);
  }
  out << '\n';
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

std::string alignedText(const CsvTable& written, const std::string& separator) {
  CsvTable table = written;
  for (auto& row : table.rows)
    for (std::string& field : row)
      if (field.empty()) field = "-";  // no value: a dash, so columns stay readable on a terminal
  std::vector<size_t> widths(table.columns.size(), 0);
  auto measure = [&](const std::vector<std::string>& fields) {
    for (size_t c = 0; c < fields.size() && c < widths.size(); ++c) widths[c] = std::max(widths[c], fields[c].size());
  };
  measure(table.columns);
  for (const auto& row : table.rows) measure(row);
  std::string out;
  auto line = [&](const std::vector<std::string>& fields) {
    std::string text;
    for (size_t c = 0; c < fields.size() && c < widths.size(); ++c) {
      if (c) text += separator;
      text += fields[c] + std::string(widths[c] - fields[c].size(), ' ');
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();  // no trailing blanks
    out += text + "\n";
  };
  line(table.columns);
  for (const auto& row : table.rows) line(row);
  return out;
}

CsvTable readCsv(std::istream& in, const std::string& source) {
  CsvTable table;
  long lineNumber = 0;
  try {
    if (!readCsvRecord(in, table.columns, lineNumber)) throw std::invalid_argument("empty file, expected a header row");
    std::vector<std::string> fields;
    while (readCsvRecord(in, fields, lineNumber)) {
      if (fields.size() == 1 && fields[0].empty()) continue;
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

#pragma once
// A small CSV table with named columns, written with shortest round-trip numbers (std::to_chars) so
// the same results always give the same bytes, and read back for merging shards and charting.

#include <iosfwd>
#include <string>
#include <vector>

namespace sl {

// Shortest decimal that reads back to the same double; an empty field for a non-finite value (no value: a CSV
// never holds nan or inf, docs/hardening.md).
std::string formatNumber(double value);

// Parses formatNumber's output (and any decimal; an empty field is NaN, no value); throws std::invalid_argument
// naming the text.
double parseNumber(const std::string& text);

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;  // each row has columns.size() fields

  // Index of a named column; throws std::out_of_range naming it.
  size_t column(const std::string& name) const;
  double number(size_t row, const std::string& name) const;
  const std::string& text(size_t row, const std::string& name) const;
};

// Fields are written as given; fields containing a comma, quote or newline are quoted.
void writeCsv(std::ostream& out, const CsvTable& table);
std::string csvText(const CsvTable& table);

// Reads a table written by writeCsv (quoted fields included). `source` names the file in errors.
CsvTable readCsv(std::istream& in, const std::string& source);
CsvTable readCsvFile(const std::string& path);

// The table for a terminal: every column padded to its widest field (header included), columns separated by
// `separator`, numbers as written, an empty field (no value) as "-". Widths count bytes: the fields are ASCII (names, numbers, units).
std::string alignedText(const CsvTable& written, const std::string& separator = "  ");

}  // namespace sl

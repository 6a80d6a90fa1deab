#pragma once
// How numbers and text are written into the program's CSV files (trajectory CSV, geometry grids, sweeps), so
// that every CSV reads back to the same values: numbers as shortest round-trip decimals (std::to_chars), text
// fields quoted as RFC 4180 says when they hold a comma, a quote or a line break.

#include <charconv>
#include <cmath>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sl {

inline void appendShortest(std::string& line, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  line.append(buffer, result.ptr);
}

inline std::string shortest(double value) {
  std::string text;
  appendShortest(text, value);
  return text;
}

// A number as a CSV field: shortest round-trip digits, or nothing (an empty field: no value) for a non-finite one.
// A CSV of this program never holds nan or inf (docs/hardening.md).
inline void appendCsvNumber(std::string& line, double value) {
  if (std::isfinite(value)) appendShortest(line, value);
}

inline std::string csvField(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// Reads one record of RFC 4180 CSV: quoted fields may hold commas, doubled quotes and line breaks; a line may
// end in CRLF. False at the end of the input (an empty line is a record of one empty field). Throws
// std::invalid_argument for a quoted field that never ends. `lines` counts the physical lines read.
inline bool readCsvRecord(std::istream& in, std::vector<std::string>& fields, long& lines) {
  std::string line;
  if (!std::getline(in, line)) return false;
  ++lines;
  fields.assign(1, std::string());
  bool quoted = false;
  for (std::size_t i = 0;; ++i) {
    if (i == line.size() || (!quoted && i + 1 == line.size() && line[i] == '\r')) {
      if (!quoted) break;
      std::string next;
      if (!std::getline(in, next)) throw std::invalid_argument("a quoted field never ends");
      ++lines;
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
  return true;
}

}  // namespace sl

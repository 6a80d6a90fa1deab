#pragma once
// How numbers and text are written into the program's CSV files (trajectory CSV, geometry grids, sweeps), so
// that every CSV reads back to the same values: numbers as shortest round-trip decimals (std::to_chars), text
// fields quoted as RFC 4180 says when they hold a comma, a quote or a line break.

#include <charconv>
#include <string>
#include <string_view>

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

inline std::string csvField(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace sl

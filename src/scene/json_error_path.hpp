#pragma once
// Where in a JSON document a parse fails, as a JSON path ("runs[1].step"): nlohmann's messages give a
// line and column for syntax errors but nothing for a number that overflows a double (1e999).

#include <string>

namespace sl {

// The path of the value being read when parsing text fails; "" if it does not fail or fails at the top.
std::string jsonPathOfParseError(const std::string& text);

}  // namespace sl

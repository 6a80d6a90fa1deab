#pragma once
// Checks on user-given names and numbers before a sweep starts, so a typo fails in a second with a
// message listing what is allowed, not after minutes of work.

#include <string>
#include <vector>

namespace sl {

// Throws std::invalid_argument: "<option>: unknown <what> 'x' (expected a, b or c)".
void requireKnownNames(const std::string& option, const std::string& what, const std::vector<std::string>& given,
                       const std::vector<std::string>& known);

// Throws std::invalid_argument unless every value is finite and positive.
void requirePositive(const std::string& option, const std::vector<double>& values);

}  // namespace sl

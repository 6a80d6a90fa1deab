#pragma once
// Checks on user-given names and numbers before a sweep starts, so a typo fails in a second with a
// message listing what is allowed, not after minutes of work. Names become the registry's kinds here;
// everything after works on the kinds.

#include <stdexcept>
#include <string>
#include <vector>

#include "contracts/registry.hpp"

namespace sl {

// "<option>: unknown <what> 'x' (expected a, b or c)".
std::invalid_argument unknownNameError(const std::string& option, const std::string& what, const std::string& name,
                                       const std::vector<std::string>& known);

// The kind of a registry table named `name`; throws unknownNameError listing the table's names.
template <class Table>
auto parseKindOption(const std::string& option, const std::string& what, const std::string& name, const Table& table) {
  if (const auto kind = parseKind(table, name)) return *kind;
  throw unknownNameError(option, what, name, namesOf(table));
}

// The kinds named by `names`, in their order; throws at the first unknown name.
template <class Table>
auto parseKindsOption(const std::string& option, const std::string& what, const std::vector<std::string>& names,
                      const Table& table) {
  std::vector<decltype(table[0].kind)> kinds;
  for (const auto& name : names) kinds.push_back(parseKindOption(option, what, name, table));
  return kinds;
}

// Throws std::invalid_argument unless every value is finite and positive.
void requirePositive(const std::string& option, const std::vector<double>& values);

// Throws std::invalid_argument unless every value is an adaptive tolerance the runs accept
// (limits::kMinTolerance to kMaxTolerance, as in a scene's runs[i].tolerance).
void requireTolerances(const std::string& option, const std::vector<double>& values);

}  // namespace sl

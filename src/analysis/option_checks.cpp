#include "analysis/option_checks.hpp"

#include <cmath>

#include "analysis/csv_table.hpp"
#include "contracts/csv_format.hpp"
#include "contracts/limits.hpp"

namespace sl {

std::invalid_argument unknownNameError(const std::string& option, const std::string& what, const std::string& name,
                                       const std::vector<std::string>& known) {
  std::string list;
  for (size_t k = 0; k < known.size(); ++k) list += (k == 0 ? "" : k + 1 == known.size() ? " or " : ", ") + known[k];
  return std::invalid_argument(option + ": unknown " + what + " '" + name + "' (expected " + list + ")");
}

void requirePositive(const std::string& option, const std::vector<double>& values) {
  for (double value : values)
    if (!(value > 0) || !std::isfinite(value))
      throw std::invalid_argument(option + ": expected positive finite numbers, found " + shortest(value));
}

void requireTolerances(const std::string& option, const std::vector<double>& values) {
  requirePositive(option, values);
  for (double value : values)
    if (value < limits::kMinTolerance || value > limits::kMaxTolerance)
      throw std::invalid_argument(option + ": found " + shortest(value) + "; expected tolerances from " +
                                  shortest(limits::kMinTolerance) + " to " + shortest(limits::kMaxTolerance));
}

}  // namespace sl

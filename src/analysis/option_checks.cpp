#include "analysis/option_checks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/csv_table.hpp"

namespace sl {

void requireKnownNames(const std::string& option, const std::string& what, const std::vector<std::string>& given,
                       const std::vector<std::string>& known) {
  for (const auto& name : given) {
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string list;
    for (size_t k = 0; k < known.size(); ++k) list += (k == 0 ? "" : k + 1 == known.size() ? " or " : ", ") + known[k];
    throw std::invalid_argument(option + ": unknown " + what + " '" + name + "' (expected " + list + ")");
  }
}

void requirePositive(const std::string& option, const std::vector<double>& values) {
  for (double value : values)
    if (!(value > 0) || !std::isfinite(value))
      throw std::invalid_argument(option + ": expected positive finite numbers, found " + formatNumber(value));
}

}  // namespace sl

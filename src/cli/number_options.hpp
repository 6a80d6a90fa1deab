#pragma once
// Validators for numeric options. CLI11's PositiveNumber and NonNegativeNumber let "nan" through (every
// comparison with NaN is false) and accept "inf"; these do not.

#include <CLI/CLI.hpp>

namespace sl {

CLI::Validator finitePositive();     // a finite number > 0
CLI::Validator finiteNonNegative();  // a finite number >= 0

}  // namespace sl

#pragma once
// Validators for numeric options: the one rule for every floating-point option of every command (a test walks them
// all). CLI11's Range, PositiveNumber and NonNegativeNumber let "nan" through (every comparison with NaN is
// false) and accept "inf"; these do not.

#include <CLI/CLI.hpp>

namespace sl {

CLI::Validator finitePositive();     // a finite number > 0
CLI::Validator finiteNonNegative();  // a finite number >= 0
CLI::Validator finiteRange(double min, double max);  // a finite number from min to max

}  // namespace sl

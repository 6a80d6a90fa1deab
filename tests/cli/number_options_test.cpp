// One rule for every floating-point option of every command (cli/number_options.hpp): "nan", "inf" and numbers
// beyond a double are refused by the option's own check, before any work. Walks the commands main() adds, so an
// option added later without the rule fails here.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include "cli/commands.hpp"

namespace sl {
namespace {

TEST(NumberOptions, EveryFloatingPointOptionRefusesNonFiniteValues) {
  CLI::App app{"linkage", "linkage"};
  addCommands(app);
  int checked = 0;
  for (CLI::App* command : app.get_subcommands({})) {
    for (const CLI::Option* option : command->get_options()) {
      if (option->get_type_name().find("FLOAT") == std::string::npos &&
          option->get_type_name().find("POSITIVE") == std::string::npos &&
          option->get_type_name().find("NONNEGATIVE") == std::string::npos)
        continue;
      const std::string name = option->get_name(false, true).substr(0, option->get_name(false, true).find(','));
      if (name.rfind("--", 0) != 0) continue;
      for (const std::string value : {"nan", "-nan", "inf", "-inf", "1e999"}) {
        CLI::App fresh{"linkage", "linkage"};
        addCommands(fresh);
        std::vector<std::string> args{name + "=" + value, command->get_name()};  // CLI11 parses in reverse
        bool refusedByItsCheck = false;
        try {
          fresh.parse(args);
        } catch (const CLI::ValidationError&) {
          refusedByItsCheck = true;
        } catch (const CLI::ConversionError&) {
          refusedByItsCheck = true;
        } catch (...) {
        }
        EXPECT_TRUE(refusedByItsCheck) << command->get_name() << " " << name << " " << value;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);  // the walk found the options (connect/periodic --max-length, diff --max-differing, ...)
}

}  // namespace
}  // namespace sl

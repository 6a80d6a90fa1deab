// `linkage list-methods`: the names a scene's runs accept.

#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

void addListMethodsCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand("list-methods", "List the methods and integrators a run can use");
  command->footer("Example: linkage list-methods");
  command->callback([] {
    std::cout << "methods:\n";
    for (const std::string& name : methodNames()) std::cout << "  " << name << '\n';
    std::cout << "integrators:\n";
    for (const std::string& name : integratorNames()) {
      std::cout << "  " << name
                << (integratorIsAdaptive(name) ? "  (adaptive: uses \"tolerance\")" : "  (fixed step: uses \"step\")")
                << '\n';
    }
  });
}

}  // namespace sl

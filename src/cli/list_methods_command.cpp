// `linkage list-methods`: the names a scene's runs accept.

#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "contracts/registry.hpp"

namespace sl {

void addListMethodsCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand("list-methods", "List the methods and integrators a run can use");
  command->footer("Example: linkage list-methods");
  command->callback([] {
    std::cout << "methods:\n";
    for (const MethodTraits& method : kMethods) std::cout << "  " << method.name << '\n';
    std::cout << "integrators:\n";
    for (const IntegratorTraits& integrator : kIntegrators) {
      std::cout << "  " << integrator.name
                << (integrator.adaptive ? "  (adaptive: uses \"tolerance\")" : "  (fixed step: uses \"step\")") << '\n';
    }
  });
}

}  // namespace sl

// `linkage list-methods`: the names a scene's runs accept, the defaults marked, one line on each.

#include <cstdio>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/summary.hpp"
#include "contracts/registry.hpp"
#include "contracts/run_config.hpp"

namespace sl {

namespace {

void listMethods(bool quiet) {
  const CommandSummary summary("list-methods", quiet);
  const RunConfig defaults;
  char line[256];
  std::cout << "methods (runs[i].method):\n";
  for (const MethodTraits& method : kMethods) {
    std::snprintf(line, sizeof line, "  %-16s%-10s%s\n", std::string(method.name).c_str(),
                  method.kind == defaults.method ? "(default)" : "", std::string(method.description).c_str());
    std::cout << line;
  }
  std::cout << "integrators (runs[i].integrator):\n";
  for (const IntegratorTraits& integrator : kIntegrators) {
    std::snprintf(line, sizeof line, "  %-16s%-10s%s; uses \"%s\"\n", std::string(integrator.name).c_str(),
                  integrator.kind == defaults.integrator ? "(default)" : "",
                  std::string(integrator.description).c_str(), integrator.adaptive ? "tolerance" : "step");
    std::cout << line;
  }
  std::snprintf(line, sizeof line, "defaults: tolerance %g, step %g\n", defaults.tolerance, defaults.step);
  std::cout << line;
  summary.print(std::to_string(kMethods.size()) + " methods, " + std::to_string(kIntegrators.size()) +
                " integrators");
}

}  // namespace

void addListMethodsCommand(CLI::App& app) {
  auto quiet = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand("list-methods", "List the methods and integrators a run can use");
  command->add_flag("--quiet", *quiet, "no summary line on stderr");
  command->footer("Details and measured figures: docs/methods.md\nExample: linkage list-methods");
  command->callback([quiet] { listMethods(*quiet); });
}

}  // namespace sl

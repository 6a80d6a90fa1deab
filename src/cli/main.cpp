// `linkage`: scene files in, trajectories, frames and videos out. Each subcommand lives in its own file.

#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "linkage: geodesics of planar linkages on their configuration spheres, rendered to frames and video.\n"
      "Write or copy a scene file (scenes/README.md), then run one command.",
      "linkage"};
  app.require_subcommand(1, 1);
  app.footer(std::string("Examples:\n  linkage validate scenes/default.json\n  linkage render scenes/default.json\n"
                         "  linkage render scenes/comparison.json --frames 0:100 --size 640x360\n\n") +
             sl::exitCodeHelp());
  sl::addRenderCommand(app);
  sl::addSimulateCommand(app);
  sl::addValidateCommand(app);
  sl::addDiffCommand(app);
  sl::addListMethodsCommand(app);
  sl::addBenchCommand(app);
  sl::addStabilityCommand(app);
  sl::addGeometryCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    app.exit(error);  // prints the message
    return sl::kExitBadInput;
  } catch (const sl::CommandExit& exit) {
    if (std::string(exit.what()).size() > 0) std::cerr << exit.what() << '\n';
    return exit.code();
  } catch (const std::invalid_argument& error) {
    std::cerr << "linkage: " << error.what() << '\n';
    return sl::kExitBadInput;
  } catch (const std::exception& error) {
    std::cerr << "linkage: " << error.what() << '\n';
    return sl::kExitFailure;
  }
  return sl::kExitOk;
}

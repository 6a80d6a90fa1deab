// `linkage`: scene files in, trajectories, frames and videos out. Each subcommand lives in its own file.

#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/help_format.hpp"
#include "render/renderer.hpp"

namespace sl {
std::string buildCommit();  // generated at build time (cmake/VersionInfo.cmake)
}

namespace {

// `linkage --version`: what a bug report needs. The GL renderer is asked for (a tiny offscreen context), since
// frames depend on it (llvmpipe's version is recorded in every manifest too).
void printVersion() {
  std::string gl;
  try {
    const sl::Renderer renderer(sl::ViewSettings{}, {16, 16});
    gl = renderer.glRenderer() + ", OpenGL " + renderer.glVersion();
  } catch (const std::exception& error) {
    gl = std::string("unavailable (") + error.what() + ")";
  }
  std::cout << "linkage " << SL_VERSION << " (commit " << sl::buildCommit() << ")\n"
            << "compiler: " << SL_COMPILER << "\n"
            << "GL renderer: " << gl << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "linkage: geodesics of planar linkages on their configuration spheres, rendered to frames and video.\n"
      "Write or copy a scene file (scenes/README.md), then run one command.",
      "linkage"};
  app.formatter(std::make_shared<sl::HelpFormatter>());  // subcommands inherit it
  bool version = false;
  app.add_flag("--version", version, "print the version, commit, compiler and GL renderer, then exit");
  app.require_subcommand(0, 1);
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
  sl::addSchemaCommand(app);
  try {
    app.parse(argc, argv);
    if (version) {
      printVersion();
      return sl::kExitOk;
    }
    if (app.get_subcommands().empty()) {
      std::cerr << "linkage: expected a command (render, simulate, validate, ...); see linkage --help\n";
      return sl::kExitBadInput;
    }
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

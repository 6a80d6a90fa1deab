// `linkage`: scene files in, trajectories, frames and videos out. Each subcommand lives in its own file.

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/environment.hpp"
#include "cli/exit_codes.hpp"
#include "cli/gl_choice.hpp"
#include "cli/help_format.hpp"
#include "cli/man_page.hpp"
#include "cli/typo_hints.hpp"
#include "render/gl_backend.hpp"
#include "render/renderer.hpp"

namespace sl {
std::string buildCommit();  // generated at build time (cmake/VersionInfo.cmake)
}

namespace {

// `linkage --version`: what a bug report needs. The GL renderer is asked for (a tiny offscreen context), since
// frames depend on it (llvmpipe's version is recorded in every manifest too).
void printVersion() {
  std::string gl, backends;
  for (sl::GlBackend b : sl::builtGlBackends()) backends += (backends.empty() ? "" : ", ") + sl::nameOf(b);
  try {
    sl::chooseGlBackend("");  // LINKAGE_GL, if set
    const sl::Renderer renderer(sl::ViewSettings{}, {16, 16}, sl::environment().shaderFolder);
    gl = renderer.glRenderer() + ", OpenGL " + renderer.glVersion() + ", through " + sl::glBackendWords();
  } catch (const std::exception& error) {
    gl = std::string("unavailable (") + error.what() + ")";
  }
  std::cout << "linkage " << SL_VERSION << " (commit " << sl::buildCommit() << ")\n"
            << "compiler: " << SL_COMPILER << "\n"
            << "GL backends: " << backends << "\n"
            << "GL renderer: " << gl << "\n";
}

// Every command's standard output is complete or the command fails (docs/hardening.md, principle 1): what is
// still buffered is flushed and the stream closed here, and an error on the way (a full disk, /dev/full, a quota)
// turns a success into exit 3 with the reason. (A reader that closes the pipe ends the process by SIGPIPE.) A command that already failed keeps its own status and
// message.
int finishStandardOutput(int code) {
  errno = 0;
  std::cout.flush();  // std::cout writes through stdout (synced with stdio): this flushes both
  const bool streamFailed = !std::cout;
  const bool flushFailed = std::fflush(stdout) != 0 || std::ferror(stdout) || streamFailed;
  const int flushErrno = errno;
  errno = 0;
  const bool closeFailed = std::fclose(stdout) != 0 && errno != EBADF;  // EBADF: there was no stdout to close
  const int error = flushErrno != 0 ? flushErrno : errno;
  if (!(flushFailed || closeFailed) || (code != sl::kExitOk && code != sl::kExitMismatch)) return code;
  std::cerr << "linkage: cannot write to standard output: " << (error != 0 ? std::strerror(error) : "write error")
            << "; what went out is incomplete\n";
  return sl::kExitFailure;
}

int runCommand(int argc, char** argv);

}  // namespace

int main(int argc, char** argv) { return finishStandardOutput(runCommand(argc, argv)); }

namespace {

int runCommand(int argc, char** argv) {
  CLI::App app{
      "linkage: geodesics of planar linkages on their configuration spheres, rendered to frames and video.\n"
      "Write or copy a scene file (scenes/README.md), then run one command.",
      "linkage"};
  app.formatter(std::make_shared<sl::HelpFormatter>());  // subcommands inherit it
  bool version = false;
  app.add_flag("--version", version, "print the version, commit, compiler and GL renderer, then exit");
  app.set_help_all_flag("--help-all", "print the help of every command");
  bool man = false;
  app.add_flag("--man", man, "print the man page (roff): linkage --man | man -l -")->group("");
  app.require_subcommand(0, 1);
  app.footer(std::string("Examples:\n  linkage validate scenes/default.json\n  linkage render scenes/default.json\n"
                         "  linkage render scenes/comparison.json --frames 0:100 --size 640x360\n"
                         "  linkage render scenes/default.json --preview\n"
                         "  linkage still scenes/default.json --time 10 --out default-t10.png\n"
                         "  linkage numbers scenes/jacobi.json\n"
                         "A guide by task: docs/guide.md (installed: share/doc/linkage/docs/guide.md).\n\n") +
             sl::exitCodeHelp());
  sl::addCommands(app);
  try {
    sl::environment();  // read once, first: an unusable variable is refused before any work starts
    app.parse(argc, argv);
    if (version) {
      printVersion();
      return sl::kExitOk;
    }
    if (man) {
      std::cout << sl::manPage(app, SL_VERSION);
      return sl::kExitOk;
    }
    if (app.get_subcommands().empty()) {
      std::cerr << "linkage: expected a command (render, simulate, validate, ...); see linkage --help\n"
                << sl::typoHints(app, argc, argv);
      return sl::kExitBadInput;
    }
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    // The program's own words first ("did you mean"), then the parser's (which may call a mistyped option's value,
    // or the scene after it, "not expected").
    std::cerr << sl::typoHints(app, argc, argv);
    app.exit(error);  // prints the message
    return sl::kExitBadInput;
  } catch (const std::exception& error) {
    const sl::ExitReport report = sl::exitReportOf(error);
    if (!report.message.empty()) std::cerr << report.message << '\n';
    return report.code;
  }
  return sl::kExitOk;
}

}  // namespace

#include "cli/man_page.hpp"

#include <sstream>

#include "cli/environment.hpp"
#include "cli/exit_codes.hpp"
#include "cli/help_format.hpp"

namespace sl {

namespace {

// Words as roff reads them inside a line: backslashes and hyphens escaped.
std::string roffWords(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  return out;
}

// Lines of text as roff reads them: roffWords, each line ended, a leading dot or quote kept from reading as a
// request.
std::string roff(const std::string& text) {
  std::string lines, line;
  std::istringstream in(roffWords(text));
  while (std::getline(in, line)) {
    if (!line.empty() && (line[0] == '.' || line[0] == '\'')) line = "\\&" + line;
    lines += line + "\n";
  }
  return lines;
}

// A help footer: its paragraphs as filled text, its "Example(s):" part as literal lines.
void footer(std::ostringstream& page, const std::string& text) {
  const std::size_t examples = text.find("Example");
  const std::string prose = text.substr(0, examples);
  if (!prose.empty()) page << ".PP\n" << roff(prose);
  if (examples == std::string::npos) return;
  const std::size_t colon = text.find('\n', examples);
  page << ".PP\n" << roff(text.substr(examples, colon - examples)) << ".RS 2\n.nf\n";
  if (colon != std::string::npos) page << roff(text.substr(colon + 1));
  page << ".fi\n.RE\n";
}

void options(std::ostringstream& page, const CLI::App& command, const HelpFormatter& formatter) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_group().empty()) continue;  // hidden
    if (command.get_parent() != nullptr && (option == command.get_help_ptr() || option == command.get_help_all_ptr()))
      continue;  // every command's --help: said once, in OPTIONS
    const bool positional = !option->nonpositional();
    page << ".TP\n.B " << roff(formatter.make_option_name(option, positional) + formatter.make_option_opts(option))
         << roff(formatter.make_option_desc(option));
  }
}

}  // namespace

std::string manPage(const CLI::App& app, const std::string& version) {
  const HelpFormatter formatter;
  std::ostringstream page;
  page << ".TH LINKAGE \"1\" \"\" \"linkage " << roffWords(version)
       << "\" \"User Commands\"\n";
  page << ".SH NAME\nlinkage \\- geodesics of planar linkages on their configuration spheres, rendered headless\n";
  page << ".SH SYNOPSIS\n.B linkage\n.I COMMAND\n[\\fIOPTIONS\\fR] \\fISCENE\\fR ...\n.br\n.B linkage\n"
          "[\\fB\\-\\-help\\fR | \\fB\\-\\-help\\-all\\fR | \\fB\\-\\-version\\fR]\n";
  page << ".SH DESCRIPTION\n" << roff(app.get_description());
  page << ".SH OPTIONS\n";
  options(page, app, formatter);
  page << ".SH COMMANDS\n";
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (command->get_group().empty()) continue;
    page << ".SS \"linkage " << roffWords(command->get_name()) << "\"\n"
         << roff(command->get_description());
    options(page, *command, formatter);
    footer(page, command->get_footer());
  }
  page << ".SH EXIT STATUS\n";
  for (const ExitStatusWords& status : kExitStatusWords)
    page << ".TP\n.B " << static_cast<int>(status.code) << "\n" << roff(status.meaning);
  page << ".PP\n" << roff(kStoppedRunWords);
  page << ".SH ENVIRONMENT\n";
  for (const EnvironmentWords& variable : kEnvironmentWords)
    page << ".TP\n.B " << roff(variable.name) << roff(variable.meaning);
  page << ".SH FILES\n"
          ".TP\n.I scene.json\nA scene: the linkage, its start, the runs and the view (linkage schema prints its JSON "
          "Schema; scenes/README.md describes every key).\n"
          ".TP\n.I renders/NAME/\nA render's frames (frame_00000.png, ...) and manifest.json, the SHA\\-256 of every "
          "frame's pixels and the scene's checksum; shards of one render share it.\n"
          ".TP\n.I VIDEO.manifest.json\nBeside a video: the checksum of every frame encoded.\n"
          ".TP\n.I /usr/share/doc/linkage/\nThe README, the guide by task (docs/guide.md) and the shipped scenes.\n";
  page << ".SH EXAMPLES\n";
  footer(page, app.get_footer().substr(0, app.get_footer().find("Exit status")));
  page << ".SH SEE ALSO\n.BR ffmpeg (1)\n";
  return page.str();
}

}  // namespace sl

#include "cli/typo_hints.hpp"

#include <algorithm>
#include <vector>

#include <CLI/CLI.hpp>

#include "scene/did_you_mean.hpp"

namespace sl {

namespace {

// "--name" for every long option of `app` (the flags' "--no-..." forms included).
std::vector<std::string> longOptions(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options())
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  return names;
}

}  // namespace

std::string typoHints(const CLI::App& app, int argc, const char* const* argv) {
  std::vector<std::string> commands;
  std::vector<const CLI::App*> subcommands;
  for (const CLI::App* sub : app.get_subcommands({})) {
    commands.push_back(sub->get_name());
    subcommands.push_back(sub);
  }
  const CLI::App* command = nullptr;
  std::string hints;
  for (int i = 1; i < argc; ++i) {
    std::string word = argv[i];
    if (word == "--") break;
    if (!command && word.rfind("-", 0) != 0) {  // the first bare word is the subcommand
      if (const auto it = std::find(commands.begin(), commands.end(), word); it != commands.end()) {
        command = subcommands[size_t(it - commands.begin())];
        continue;
      }
      const std::string close = closestName(word, commands);
      if (!close.empty()) hints += "linkage: \"" + word + "\" is no command; did you mean \"" + close + "\"?\n";
      break;
    }
    if (word.rfind("--", 0) != 0 || word.size() < 3) continue;
    word = word.substr(0, word.find('='));
    const std::vector<std::string> known = longOptions(command ? *command : app);
    if (std::find(known.begin(), known.end(), word) != known.end()) continue;
    // An abbreviation ("--t": --time or --transparent) first, then the closest name by spelling.
    std::vector<std::string> longer;
    for (const std::string& name : known)
      if (name.rfind(word, 0) == 0) longer.push_back(name);
    std::string close;
    if (!longer.empty() && longer.size() <= 3) {
      for (std::size_t k = 0; k < longer.size(); ++k)
        close += (k == 0 ? "" : k + 1 == longer.size() ? "\" or \"" : "\", \"") + longer[k];
    } else {
      close = closestName(word, known);
    }
    if (!close.empty())
      hints += "linkage: " + (command ? command->get_name() + ": " : std::string()) + "\"" + word +
               "\" is no option; did you mean \"" + close + "\"?\n";
  }
  return hints;
}

}  // namespace sl

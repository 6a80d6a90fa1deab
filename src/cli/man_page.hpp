#pragma once
// `linkage --man`: the man page in roff, made from the same help texts as --help-all (descriptions, options,
// examples) with the sections a man page has (COMMANDS, EXIT STATUS, ENVIRONMENT, FILES, EXAMPLES). The build
// writes it to linkage.1 each time linkage is linked.

#include <string>

#include <CLI/CLI.hpp>

namespace sl {

std::string manPage(const CLI::App& app, const std::string& version);

}  // namespace sl

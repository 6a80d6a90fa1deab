#pragma once
// Help texts without the parser's artefacts: "--grid N" rather than "--grid INT:INT in [1 - 4096]=64",
// "--no-charts" rather than "--no-charts{false}", and defaults said in words at the end of the description.

#include <CLI/CLI.hpp>

namespace sl {

class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* option, bool positional) const override;
  std::string make_option_opts(const CLI::Option* option) const override;
  std::string make_option_desc(const CLI::Option* option) const override;
  // --help-all: each command with its footer (its notes and examples), which CLI11 leaves out.
  std::string make_expanded(const CLI::App* command) const override;
};

}  // namespace sl

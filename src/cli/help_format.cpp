#include "cli/help_format.hpp"

namespace sl {

std::string HelpFormatter::make_option_name(const CLI::Option* option, bool positional) const {
  if (positional) return option->get_name(true, false);
  std::string names = option->get_name(false, true);
  // A negated flag is listed with the value it sets ("--no-charts{false}"): drop every {...}.
  for (std::size_t open = names.find('{'); open != std::string::npos; open = names.find('{')) {
    const std::size_t close = names.find('}', open);
    names.erase(open, close == std::string::npos ? std::string::npos : close - open + 1);
  }
  return names;
}

std::string HelpFormatter::make_option_opts(const CLI::Option* option) const {
  if (option->get_type_size() == 0) return "";  // a flag takes no value
  std::string type = option->get_type_name();   // "INT:INT in [1 - 4096]": the validator's text goes
  type = type.substr(0, type.find(':'));
  std::string text = type.empty() ? "" : " " + type;
  if (option->get_expected_max() == CLI::detail::expected_max_vector_size) text += " ...";
  if (option->get_required()) text += " (required)";
  return text;
}

std::string HelpFormatter::make_option_desc(const CLI::Option* option) const {
  std::string description = option->get_description();
  const std::string fallback = option->get_default_str();
  if (option->get_type_size() != 0 && !fallback.empty() && description.find("default") == std::string::npos)
    description += " (default " + fallback + ")";
  return description;
}

std::string HelpFormatter::make_expanded(const CLI::App* command) const {
  std::string text = CLI::Formatter::make_expanded(command);
  if (command->get_footer().empty()) return text;
  std::string footer = "\n" + command->get_footer();
  for (std::size_t at = 0; (at = footer.find('\n', at)) != std::string::npos; at += 3) footer.replace(at, 1, "\n  ");
  return text.substr(0, text.size() - 1) + footer + "\n\n";
}

}  // namespace sl

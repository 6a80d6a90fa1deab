#pragma once
// "did you mean" for the command line: a mistyped subcommand or option gets the closest known name, found by the
// same routine as misspelt scene keys (scene/did_you_mean.hpp).

#include <string>

namespace CLI {
class App;
}

namespace sl {

// Lines such as "linkage: \"rendr\": did you mean \"render\"?" for each word of argv (after the program name) that
// is no subcommand or option of `app` (or of the subcommand named) and is close to one; "" when none.
std::string typoHints(const CLI::App& app, int argc, const char* const* argv);

}  // namespace sl

#pragma once
// A configuration given on the command line (connect --to, geometry --distance-from): JSON text, or a file
// holding it, in either form a scene's `initial` accepts for a point: {"coords": [...]} (chart 0) or
// {"hinges": [[x, y], ...]} (projected onto the rod constraints, refused if further than 0.01). Errors name the
// option (or the file) and what was expected.
#include <string>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "inverse/constrained_model.hpp"
#include "linkage/chain.hpp"

namespace sl {

Eigen::VectorXd readConfigurationPoint(const Chain& chain, const ConstrainedModel& model, const std::string& text,
                                       const std::string& option);
// One configuration from parsed JSON; `where` names it in errors (a file, an option, a JSON path).
Eigen::VectorXd configurationFromJson(const Chain& chain, const ConstrainedModel& model, const nlohmann::json& j,
                                      const std::string& where);
// An option's JSON value: the text itself when it starts with '{' or '[', else a file holding it; `where` is set to
// what errors should name (the option or the file).
nlohmann::json readJsonArgument(const std::string& target, const std::string& option, std::string& where);

}  // namespace sl

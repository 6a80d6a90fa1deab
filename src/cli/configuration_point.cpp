#include "cli/configuration_point.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/exit_codes.hpp"
#include "linkage/chart.hpp"

namespace sl {

nlohmann::json readJsonArgument(const std::string& target, const std::string& option, std::string& where) {
  std::string text = target;
  where = option;
  if (!text.empty() && text.front() != '{' && text.front() != '[') {
    std::ifstream in(target);
    if (!in) throw CommandExit(kExitBadInput, option + " " + target + ": neither JSON nor a readable file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    where = target;
  }
  try {
    return nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    throw CommandExit(kExitBadInput, where + ": not JSON (" + e.what() + ")");
  }
}

Eigen::VectorXd readConfigurationPoint(const Chain& chain, const ConstrainedModel& model, const std::string& target,
                                       const std::string& option) {
  std::string where;
  const nlohmann::json j = readJsonArgument(target, option, where);
  return configurationFromJson(chain, model, j, where);
}

Eigen::VectorXd configurationFromJson(const Chain& chain, const ConstrainedModel& model, const nlohmann::json& j,
                                      const std::string& where) {
  if (!j.is_object()) throw CommandExit(kExitBadInput, where + ": expected an object with \"coords\" or \"hinges\"");
  if (j.contains("coords")) {
    const auto& c = j["coords"];
    if (chain.isSlack()) throw CommandExit(kExitBadInput, where + ": coords: a slack chain has no chart; give hinges");
    if (!c.is_array() || static_cast<int>(c.size()) != chain.sphereDimension())
      throw CommandExit(kExitBadInput, where + ": coords: expected an array of " +
                                           std::to_string(chain.sphereDimension()) + " numbers");
    Eigen::VectorXd coords(chain.sphereDimension());
    for (int i = 0; i < coords.size(); ++i) {
      if (!c[static_cast<std::size_t>(i)].is_number() || !std::isfinite(c[static_cast<std::size_t>(i)].get<double>()))
        throw CommandExit(kExitBadInput, where + ": coords[" + std::to_string(i) + "]: expected a finite number");
      coords(i) = c[static_cast<std::size_t>(i)].get<double>();
    }
    return ConstrainedModel::stack(hingePositions(chain, coords));
  }
  if (j.contains("hinges")) {
    const auto& h = j["hinges"];
    if (!h.is_array() || static_cast<int>(h.size()) != chain.hingeCount())
      throw CommandExit(kExitBadInput,
                        where + ": hinges: expected " + std::to_string(chain.hingeCount()) + " points [x, y]");
    Eigen::Matrix2Xd hinges(2, chain.hingeCount());
    for (int k = 0; k < chain.hingeCount(); ++k) {
      const auto& p = h[static_cast<std::size_t>(k)];
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number() ||
          !std::isfinite(p[0].get<double>()) || !std::isfinite(p[1].get<double>()))
        throw CommandExit(kExitBadInput, where + ": hinges[" + std::to_string(k) + "]: expected [x, y]");
      hinges(0, k) = p[0].get<double>();
      hinges(1, k) = p[1].get<double>();
    }
    Eigen::VectorXd q = ConstrainedModel::stack(hinges);
    if (!model.projectPosition(q) || (q - ConstrainedModel::stack(hinges)).cwiseAbs().maxCoeff() > 1e-2)
      throw CommandExit(kExitBadInput, where + ": hinges: not within 0.01 of a configuration with unit rods");
    return q;
  }
  throw CommandExit(kExitBadInput, where + ": expected an object with \"coords\" or \"hinges\"");
}

}  // namespace sl

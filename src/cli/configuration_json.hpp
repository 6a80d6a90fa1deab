#pragma once
// Configurations and velocities as JSON, for the commands that print them (connect, periodic).
#include <Eigen/Dense>
#include <nlohmann/json.hpp>

namespace sl {

// [x0, x1, ...]
inline nlohmann::json vectorJson(const Eigen::VectorXd& v) {
  nlohmann::json out = nlohmann::json::array();
  for (double x : v) out.push_back(x);
  return out;
}

// Stacked hinges (x1, y1, x2, y2, ...) as [[x1, y1], [x2, y2], ...].
inline nlohmann::json hingesJson(const Eigen::VectorXd& q) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index k = 0; k + 1 < q.size(); k += 2) out.push_back({q(k), q(k + 1)});
  return out;
}

}  // namespace sl

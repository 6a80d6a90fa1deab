#pragma once
// Richardson extrapolation in h^2 for values computed on grids halved at each level: the diagonal of the
// table (for errors with an expansion in even powers of h: symmetric discretisations, periodic polygons).
#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace sl {

struct Richardson {
  std::vector<std::vector<Eigen::VectorXd>> table;
  Eigen::VectorXd add(const Eigen::VectorXd& value) {
    std::vector<Eigen::VectorXd> row{value};
    if (!table.empty()) {
      const auto& previous = table.back();
      for (std::size_t k = 1; k <= previous.size(); ++k) {
        const double factor = std::pow(4.0, static_cast<double>(k)) - 1.0;
        row.push_back(row[k - 1] + (row[k - 1] - previous[k - 1]) / factor);
      }
    }
    table.push_back(row);
    return row.back();
  }
};

}  // namespace sl

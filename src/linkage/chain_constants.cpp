#include "linkage/chain_constants.hpp"

#include <cmath>

#include "contracts/limits.hpp"
#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"

namespace sl {

ChainConstants::ChainConstants(const Chain& c)
    : chain((c.validate(true), c)),
      amplitude(c.isSlack() ? std::nan("") : chainAmplitude(c.rods, c.baseLength)),  // a slack chain has no chart
      mass(ambientMassMatrix(c)),
      stackedMass(c.rods <= limits::kMaxRods ? stackedMassMatrix(c) : Eigen::MatrixXd()) {}

}  // namespace sl

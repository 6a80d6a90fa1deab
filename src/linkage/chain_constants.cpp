#include "linkage/chain_constants.hpp"

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"

namespace sl {

ChainConstants::ChainConstants(const Chain& c)
    : chain((c.validate(), c)),
      amplitude(chainAmplitude(c.rods, c.baseLength)),
      mass(ambientMassMatrix(c)),
      stackedMass(stackedMassMatrix(c)) {}

}  // namespace sl

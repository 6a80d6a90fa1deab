#include "inverse/self_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sl {

namespace {

bool lengthsAgree(double route1, double route2) {
  return std::abs(route1 - route2) <= kRouteAgreement * std::max(1.0, std::abs(route1));
}

}  // namespace

SelfCheck selfCheck(const ClosedGeodesic& g) {
  const double closure = g.closure();
  if (!std::isfinite(g.length) || !std::isfinite(closure) ||
      (g.independentLength && !std::isfinite(*g.independentLength)))
    return SelfCheck::notFinite;
  if (closure > kClosureBound) return SelfCheck::openClosure;
  if (g.independentLength && !lengthsAgree(g.length, *g.independentLength)) return SelfCheck::routesDisagree;
  return SelfCheck::confirmed;
}

SelfCheck selfCheck(const Connection& c) {
  if (!std::isfinite(c.length) || !std::isfinite(c.endError) || (c.discrete && !std::isfinite(c.discrete->length)))
    return SelfCheck::notFinite;
  if (c.endError > kEndErrorBound) return SelfCheck::missedTarget;
  if (c.discrete && !lengthsAgree(c.length, c.discrete->length)) return SelfCheck::routesDisagree;
  return SelfCheck::confirmed;
}

SelfCheck selfCheck(const DistanceMap& map) {
  if (!std::isfinite(map.injectivityRadius) || !std::isfinite(map.klingenberg())) return SelfCheck::notFinite;
  // The phi rows run pole to pole: a cell is pi / (rows - 1) in chart units, the grid's resolution.
  const double cell = std::numbers::pi / std::max<double>(1.0, static_cast<double>(map.phis.size()) - 1);
  if (std::abs(map.injectivityRadius - map.klingenberg()) > kInjectivityAgreementCells * cell)
    return SelfCheck::radiiDisagree;
  return SelfCheck::confirmed;
}

SelfCheck selfCheck(const Holonomy& h) {
  const double excess = h.excessDifference().value_or(0.0);
  if (!std::isfinite(h.angle) || !std::isfinite(h.chartAngle) || !std::isfinite(h.enclosedCurvature) ||
      !std::isfinite(excess))
    return SelfCheck::notFinite;
  if (std::abs(h.routeDifference()) > kHolonomyRouteBound) return SelfCheck::turningDisagrees;
  if (std::abs(h.curvatureDifference()) > kGaussBonnetBound || std::abs(excess) > kGaussBonnetBound)
    return SelfCheck::gaussBonnetFails;
  return SelfCheck::confirmed;
}

}  // namespace sl

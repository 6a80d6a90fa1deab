#include "analysis/stability_grid.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/starts.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSpeed = 0.5;

// Cell centres of [lo, hi) split into `grid` cells: periodic axes and open intervals.
double cellCentre(double lo, double hi, int grid, int index) { return lo + (index + 0.5) * (hi - lo) / grid; }

// Grid points from lo to hi inclusive (a single point sits at lo).
double gridPoint(double lo, double hi, int grid, int index) {
  return grid == 1 ? lo : lo + index * (hi - lo) / (grid - 1);
}

// The round-sphere tangent vector at chart point (phi, t) with the given heading (0 = along increasing t).
InitialState headingStart(double phi, double t, double heading) {
  const Eigen::Vector2d coords(phi, t);
  const Eigen::Vector3d x = spherePointFromCoordinates<double>(Eigen::VectorXd(coords));
  const Eigen::Vector3d east(-std::sin(t), std::cos(t), 0.0);
  const Eigen::Vector3d north(-std::sin(phi) * std::cos(t), -std::sin(phi) * std::sin(t), std::cos(phi));
  const Eigen::Vector3d v = kSpeed * (std::cos(heading) * east + std::sin(heading) * north);
  return {x, v};
}

}  // namespace

std::vector<std::string> stabilityKindNames() { return {"launch", "direction", "pole", "seam", "length", "drift"}; }

bool isStabilityKind(const std::string& kind) {
  for (const auto& name : stabilityKindNames())
    if (name == kind) return true;
  return false;
}

std::pair<std::string, std::string> stabilityAxisLabels(const std::string& kind) {
  if (kind == "launch" || kind == "drift") return {"launch t_0", "launch {/Symbol f}_0"};
  if (kind == "direction") return {"heading (0 = +t, {/Symbol p}/2 = +{/Symbol f})", "launch {/Symbol f}_0"};
  if (kind == "pole")
    return {"log_{10} closest approach to the pole (leftmost: through it)", "azimuth of the approach"};
  if (kind == "seam") return {"log_{10}(t_0 - {/Symbol p}/2) (leftmost: on the seam)", "heading"};
  if (kind == "length") return {"u, L = 3 + sign(u)(1 - 10^{-6|u|})", "heading"};
  throw std::invalid_argument("unknown stability sweep kind '" + kind + "'");
}

double defaultStabilityDuration(const std::string& kind) { return kind == "drift" ? 1000.0 : 20.0; }

StabilityCell stabilityCell(const std::string& kind, int grid, int i, int j, double duration) {
  StabilityCell cell;
  cell.i = i;
  cell.j = j;
  cell.chain = Chain::uniform(4, 3.0);
  if (kind == "launch" || kind == "drift") {
    cell.x = cellCentre(-kPi, kPi, grid, i);
    cell.y = cellCentre(-kPi / 2, kPi / 2, grid, j);
    cell.start = headingStart(cell.y, cell.x, 0.7);
  } else if (kind == "direction") {
    cell.x = cellCentre(0, 2 * kPi, grid, i);
    cell.y = cellCentre(-kPi / 2, kPi / 2, grid, j);
    cell.start = headingStart(cell.y, 0.2, cell.x);
  } else if (kind == "pole") {
    cell.x = gridPoint(-11, -1, grid, i);
    cell.y = cellCentre(0, 2 * kPi, grid, j);
    const double distance = i == 0 ? 0.0 : std::pow(10.0, cell.x);
    cell.start = stateArrivingAt(cell.chain, closestApproachToPole(3, distance, cell.y, kSpeed), duration / 2);
  } else if (kind == "seam") {
    cell.x = gridPoint(-13, -1, grid, i);
    cell.y = cellCentre(0, 2 * kPi, grid, j);
    const double offset = i == 0 ? 0.0 : std::pow(10.0, cell.x);
    cell.start = headingStart(0.3, kPi / 2 + offset, cell.y);
  } else if (kind == "length") {
    cell.x = gridPoint(-1, 1, grid, i);
    cell.y = cellCentre(0, 2 * kPi, grid, j);
    const double gap = 1.0 - std::pow(10.0, -6.0 * std::abs(cell.x));
    cell.chain = Chain::uniform(4, 3.0 + (cell.x < 0 ? -gap : gap));
    cell.start = headingStart(0.3, 0.2, cell.y);
  } else {
    throw std::invalid_argument("unknown stability sweep kind '" + kind + "'");
  }
  return cell;
}

}  // namespace sl

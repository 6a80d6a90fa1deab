#include "frames/sphere_decoration.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <map>
#include <set>
#include <utility>

#include "geometry/curvature.hpp"
#include "geometry/curvature_grid.hpp"
#include "inverse/distance_map.hpp"
#include "inverse/geodesic_flow.hpp"
#include "inverse/holonomy.hpp"
#include "inverse/periodic.hpp"
#include "linkage/chart.hpp"

namespace sl {
namespace {

const double kPi = std::acos(-1.0);

SphereField colourField(const ConfigurationSurface& surface, SphereColoring coloring) {
  SphereField field;
  field.phiCount = kSphereFieldRows;
  field.tCount = 2 * kSphereFieldRows;
  // Cell centres (frame_state.hpp): the texture's linear filtering then interpolates between exact values.
  std::vector<double> phis(field.phiCount), ts(field.tCount);
  for (int i = 0; i < field.phiCount; ++i) phis[i] = -kPi / 2 + (i + 0.5) * kPi / field.phiCount;
  for (int j = 0; j < field.tCount; ++j) ts[j] = -kPi + (j + 0.5) * 2 * kPi / field.tCount;
  const std::vector<CurvatureSample> samples = curvatureGrid(surface, phis, ts);
  const bool curvature = coloring == SphereColoring::Curvature;
  field.coloring = coloring;
  field.diverging = curvature;
  field.values.reserve(samples.size());
  field.min = INFINITY;
  field.max = -INFINITY;
  for (const CurvatureSample& s : samples) {
    const double value = curvature ? s.gaussianCurvature : s.bending;
    field.values.push_back(static_cast<float>(value));
    field.min = std::min(field.min, value);
    field.max = std::max(field.max, value);
  }
  return field;
}

// Evenly spread points (a Fibonacci lattice), each with its ellipse: the long axis along the stiffest direction,
// half-axes proportional to sqrt(S_max) and sqrt(S_min), the largest over the sphere a fixed fraction of the
// spacing so that neighbours never overlap.
std::vector<SphereEllipse> stiffnessEllipses(const ConfigurationSurface& surface) {
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  std::vector<CurvatureSample> samples;
  for (int k = 0; k < kStiffnessEllipses; ++k) {
    const double z = 1.0 - (k + 0.5) * 2.0 / kStiffnessEllipses;
    const double r = std::sqrt(1.0 - z * z);
    samples.push_back(surface.curvatureAt(Eigen::Vector3d(r * std::cos(golden * k), r * std::sin(golden * k), z)));
  }
  double largest = 0;
  for (const CurvatureSample& s : samples) largest = std::max(largest, std::sqrt(s.stiffnessMax));
  const double spacing = std::sqrt(4 * kPi / kStiffnessEllipses);
  const double scale = largest > 0 ? 0.42 * spacing / largest : 0.0;
  std::vector<SphereEllipse> ellipses;
  for (const CurvatureSample& s : samples) {
    const Eigen::Vector3d x = s.spherePoint.normalized();
    const Eigen::Vector3d along = (s.stiffnessDirection - s.stiffnessDirection.dot(x) * x).normalized();
    const Eigen::Vector3d across = x.cross(along);
    const Eigen::Vector3d major = along * std::sqrt(s.stiffnessMax) * scale;
    const Eigen::Vector3d minor = across * std::sqrt(std::max(s.stiffnessMin, 0.0)) * scale;
    ellipses.push_back({{x.x(), x.y(), x.z()}, {major.x(), major.y(), major.z()}, {minor.x(), minor.y(), minor.z()}});
  }
  return ellipses;
}

Vec3 vec(const Eigen::Vector3d& x) { return {x.x(), x.y(), x.z()}; }

// The conjugate locus in the order of the directions, broken where neighbours lie far apart (directions whose
// conjugate point is beyond the map's cap are left out), closed when it goes once round.
std::vector<SphereCurve> conjugateCurves(const DistanceMap& map) {
  constexpr double kBreak = 0.2;  // a chord of the unit sphere, about 8 cells of the grid
  std::vector<SphereCurve> curves;
  const auto& locus = map.conjugateLocus;
  for (std::size_t k = 0; k < locus.size(); ++k) {
    if (k == 0 || (locus[k].x - locus[k - 1].x).norm() > kBreak) curves.push_back({SphereCurveKind::ConjugateLocus, {}});
    curves.back().points.push_back(vec(locus[k].x));
  }
  if (curves.size() > 1 && (locus.back().x - locus.front().x).norm() <= kBreak) {  // the last runs into the first
    curves.back().points.insert(curves.back().points.end(), curves.front().points.begin(), curves.front().points.end());
    curves.erase(curves.begin());
  } else if (curves.size() == 1 && (locus.back().x - locus.front().x).norm() <= kBreak) {
    curves.back().points.push_back(curves.back().points.front());
  }
  return curves;
}

// The cut locus as the graph cutGraphShape counts: each cut edge of the grid joins the two faces beside it, drawn
// between the faces' centres (the colour field's cells); chained into polylines from its ends and forks.
std::vector<SphereCurve> cutCurves(const DistanceMap& map) {
  const int rows = static_cast<int>(map.phis.size()), cols = static_cast<int>(map.ts.size());
  std::map<int, std::set<int>> next;
  for (const CutEdge& e : map.cutLocus) {
    const int i = e.a / cols, j = e.a % cols;
    const bool alongRow = e.b / cols == i;
    const int f = alongRow ? (i - 1) * cols + j : i * cols + (j + cols - 1) % cols, g = i * cols + j;
    next[f].insert(g);
    next[g].insert(f);
  }
  const double dphi = kPi / (rows - 1), dt = 2 * kPi / cols;
  std::map<int, Eigen::Vector3d> place;
  for (const auto& [face, neighbours] : next) {
    const double phi = map.phis[static_cast<std::size_t>(face / cols)] + dphi / 2,
                 t = map.ts[static_cast<std::size_t>(face % cols)] + dt / 2;
    place[face] = Eigen::Vector3d(std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi));
  }
  // The staircase along the grid relaxed towards the curve it stands for: every vertex but the ends moves to the
  // mean of itself and its neighbours, a few rounds (within a cell or two of where it was).
  for (int round = 0; round < 8; ++round) {
    std::map<int, Eigen::Vector3d> moved = place;
    for (const auto& [face, neighbours] : next) {
      if (neighbours.size() < 2) continue;
      Eigen::Vector3d sum = place[face];
      for (const int other : neighbours) sum += place[other];
      moved[face] = sum.normalized();
    }
    place = std::move(moved);
  }
  auto centre = [&](int face) { return vec(place[face]); };
  std::set<std::pair<int, int>> used;
  std::vector<SphereCurve> curves;
  auto walk = [&](int from, int to) {
    SphereCurve curve{SphereCurveKind::CutLocus, {centre(from)}};
    for (;;) {
      used.insert({std::min(from, to), std::max(from, to)});
      curve.points.push_back(centre(to));
      if (next[to].size() != 2) break;
      const int after = *next[to].begin() == from ? *next[to].rbegin() : *next[to].begin();
      if (used.count({std::min(to, after), std::max(to, after)})) break;
      from = to;
      to = after;
    }
    curves.push_back(std::move(curve));
  };
  for (bool ends : {true, false})  // from the ends and forks first, then what is left: cycles
    for (const auto& [face, neighbours] : next)
      if (!ends || neighbours.size() != 2)
        for (const int other : neighbours)
          if (!used.count({std::min(face, other), std::max(face, other)})) walk(face, other);
  return curves;
}

// The distance from the point over the sphere on the nodes of a grid whose cells are the colour field's (each cell
// the mean of its corners), and its loci as curves.
void addDistance(const Chain& chain, const Eigen::VectorXd& spherePoint, bool fromStart, SphereDecoration& decoration) {
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  DistanceMapOptions options;
  options.grid = kSphereFieldRows + 1;
  options.columns = 2 * kSphereFieldRows;
  const DistanceMap map = distanceMap(
      model,
      [&chain](const Eigen::VectorXd& q) -> Eigen::Vector3d {
        return spherePointFromHinges(chain, ConstrainedModel::unstack(q));
      },
      ConstrainedModel::stack(hingePositionsAt(chain, spherePoint)), options);
  SphereField field;
  field.coloring = SphereColoring::Distance;
  field.phiCount = kSphereFieldRows;
  field.tCount = 2 * kSphereFieldRows;
  field.min = 0;  // at the point itself
  field.max = 0;
  const int cols = field.tCount;
  for (int i = 0; i < field.phiCount; ++i)
    for (int j = 0; j < field.tCount; ++j) {
      auto at = [&](int ii, int jj) { return map.distance[static_cast<std::size_t>(ii * cols + jj % cols)]; };
      const double value = (at(i, j) + at(i, j + 1) + at(i + 1, j) + at(i + 1, j + 1)) / 4;
      field.values.push_back(static_cast<float>(value));
      field.max = std::max(field.max, value);
    }
  decoration.field = std::move(field);
  decoration.distance = SphereDistance{vec(map.point), fromStart, map.injectivityRadius};
  decoration.curves = conjugateCurves(map);
  for (SphereCurve& curve : cutCurves(map)) decoration.curves.push_back(std::move(curve));
}

// The simple closed geodesics of `linkage periodic`'s list, each followed once round from its start: a closed curve
// of the unit sphere.
std::vector<SphereCurve> closedGeodesicCurves(const Chain& chain) {
  constexpr int kPoints = 512;
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const GeodesicFlow flow(model, 1e-10);
  std::vector<SphereCurve> curves;
  for (const ClosedGeodesic& g : closedGeodesicsOf(chain, 0)) {
    if (!g.simple) continue;
    SphereCurve curve{SphereCurveKind::ClosedGeodesic, {}};
    FlowState state{g.point, g.velocity, Eigen::MatrixXd(g.point.size(), 0), Eigen::MatrixXd(g.point.size(), 0)};
    curve.points.push_back(vec(spherePointFromHinges(chain, ConstrainedModel::unstack(state.q)).normalized()));
    for (int k = 1; k <= kPoints; ++k) {
      if (!flow.advance(state, g.length / kPoints)) break;
      curve.points.push_back(vec(spherePointFromHinges(chain, ConstrainedModel::unstack(state.q)).normalized()));
    }
    curves.push_back(std::move(curve));
  }
  return curves;
}

// A vector carried round the polygon through the corners: each side sampled at kSamplesPerSide even steps of its
// time (frames draw every other sample as an arrow and the carried vector between them) and the three figures of
// Gauss-Bonnet.
SphereTransport transportAround(const Chain& chain, const std::vector<Eigen::VectorXd>& corners) {
  constexpr int kSamplesPerSide = 12;
  const Holonomy h = polygonHolonomy(chain, corners, nullptr, kSamplesPerSide);
  SphereTransport transport;
  transport.samplesPerSide = kSamplesPerSide;
  for (const Holonomy::Sample& s : h.samples)
    transport.arrows.push_back({vec(Eigen::Vector3d(s.point).normalized()),
                                vec(Eigen::Vector3d(s.transported).normalized()), s.piece, s.fraction, s.swept});
  for (const Eigen::VectorXd& c : corners) transport.corners.push_back(vec(Eigen::Vector3d(c).normalized()));
  transport.holonomy = h.angle;
  transport.angleExcess = h.angleExcess.value_or(0.0);
  transport.enclosedCurvature = h.enclosedCurvature;
  return transport;
}

}  // namespace

std::shared_ptr<const SphereDecoration> makeSphereDecoration(const Chain& chain, const SphereSurfaceSpec& spec,
                                                             const Eigen::VectorXd& distancePoint, bool fromStart,
                                                             const std::vector<Eigen::VectorXd>& holonomyCorners) {
  if (!spec.decorated()) return nullptr;
  const ConfigurationSurface surface(chain);
  auto decoration = std::make_shared<SphereDecoration>();
  if (spec.colorBy == SphereColoring::Distance) {
    if (distancePoint.size() != 3)
      throw std::invalid_argument("makeSphereDecoration: the distance colouring needs a point of the sphere");
    addDistance(chain, distancePoint, fromStart, *decoration);
  } else if (spec.colorBy != SphereColoring::None) {
    decoration->field = colourField(surface, spec.colorBy);
  }
  decoration->seam = spec.seam;
  if (spec.closedGeodesics)
    for (SphereCurve& curve : closedGeodesicCurves(chain)) decoration->curves.push_back(std::move(curve));
  if (spec.stiffness) decoration->ellipses = stiffnessEllipses(surface);
  if (spec.holonomy) {
    if (holonomyCorners.size() < 3)
      throw std::invalid_argument("makeSphereDecoration: the holonomy needs the polygon's corners (at least 3)");
    decoration->transport = transportAround(chain, holonomyCorners);
  }
  return decoration;
}

}  // namespace sl

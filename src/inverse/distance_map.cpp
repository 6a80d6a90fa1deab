#include "inverse/distance_map.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "contracts/parallel_for.hpp"
#include "inverse/connect.hpp"
#include "inverse/geodesic_flow.hpp"

namespace sl {

namespace {

constexpr double kPi = std::numbers::pi;

struct Sample {
  double s;
  Eigen::VectorXd q, v, dq, dv;
};

// One direction of the fan: its raw integrator samples up to the first conjugate point (or the cap), then
// the sphere points at arc lengths k * ds up to the length bound (the last at the end if sooner).
struct Trace {
  double angle = 0;
  std::vector<Sample> samples;
  bool conjugate = false;
  ConjugatePoint conjugatePoint;
  double end = 0;
  std::vector<Eigen::Vector3d> x;
  std::vector<double> xs;
  std::vector<double> spread;  // |dx / d angle| on the unit sphere: the Jacobi field seen there
};

Eigen::VectorXd hermite(const Sample& a, const Sample& b, double s) {
  const double h = b.s - a.s, u = (s - a.s) / h, u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * a.q + (u3 - 2 * u2 + u) * h * a.v + (-2 * u3 + 3 * u2) * b.q + (u3 - u2) * h * b.v;
}

Eigen::VectorXd hermiteVariation(const Sample& a, const Sample& b, double s) {
  const double h = b.s - a.s, u = (s - a.s) / h, u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * a.dq + (u3 - 2 * u2 + u) * h * a.dv + (-2 * u3 + 3 * u2) * b.dq + (u3 - u2) * h * b.dv;
}

Eigen::VectorXd directionAt(const Eigen::MatrixXd& basis, double angle) {
  return std::cos(angle) * basis.col(0) + std::sin(angle) * basis.col(1);
}

// Follows the unit-speed geodesic in direction `angle` with the Jacobi field J(0) = 0, J'(0) across the fan,
// until J first vanishes (found to the integrator's accuracy by Newton's method on <J(s), J(s0)>_M from the
// last step before the sign change) or the cap.
Trace traceDirection(const GeodesicFlow& flow, const Eigen::VectorXd& point, const Eigen::MatrixXd& basis,
                     double angle, double cap) {
  const ConstrainedModel& model = flow.model();
  Trace trace;
  trace.angle = angle;
  FlowState state{point, directionAt(basis, angle), Eigen::MatrixXd::Zero(point.size(), 1),
                  directionAt(basis, angle + kPi / 2)};
  std::optional<Sample> crossing;
  flow.advance(state, cap, [&](double s, const FlowState& x) {
    Sample current{s, x.q, x.v, x.dq.col(0), x.dv.col(0)};
    if (!trace.samples.empty() && model.inner(current.dq, trace.samples.back().dq) < 0) {
      crossing = std::move(current);
      return false;
    }
    trace.samples.push_back(std::move(current));
    return true;
  });
  trace.end = trace.samples.back().s;
  if (!crossing) return trace;
  const Sample& before = trace.samples.back();
  const double h = crossing->s - before.s, f0 = before.dq.squaredNorm() > 0 ? model.inner(before.dq, before.dq) : 1;
  const double f1 = model.inner(crossing->dq, before.dq);
  double step = h * f0 / (f0 - f1);
  FlowState at;
  for (int iteration = 0; iteration < 8; ++iteration) {
    at = FlowState{before.q, before.v, before.dq, before.dv};
    flow.advance(at, step);
    const double f = model.inner(at.dq.col(0), before.dq), slope = model.inner(at.dv.col(0), before.dq);
    const double change = slope != 0 ? f / slope : 0;
    step = std::clamp(step - change, 0.0, h);
    if (std::abs(change) < 1e-13) break;
  }
  at = FlowState{before.q, before.v, before.dq, before.dv};
  flow.advance(at, step);
  trace.conjugate = true;
  trace.conjugatePoint.angle = angle;
  trace.conjugatePoint.distance = before.s + step;
  trace.conjugatePoint.q = at.q;
  trace.samples.push_back(Sample{before.s + step, at.q, at.v, at.dq.col(0), at.dv.col(0)});
  trace.end = trace.samples.back().s;
  return trace;
}

void resample(Trace& trace, const SphereProjection& project, double ds, double bound) {
  trace.x.clear();
  trace.xs.clear();
  trace.spread.clear();
  const double last = std::min(trace.end, bound);
  std::size_t segment = 0;
  for (int k = 0;; ++k) {
    double s = k * ds;
    const bool final = s >= last;
    if (final) s = last;
    while (segment + 2 < trace.samples.size() && trace.samples[segment + 1].s < s) ++segment;
    const Sample& a = trace.samples[segment];
    const Sample& b = trace.samples[std::min(segment + 1, trace.samples.size() - 1)];
    const double at = std::clamp(s, a.s, b.s);
    const Eigen::VectorXd q = b.s > a.s ? hermite(a, b, at) : a.q;
    const Eigen::VectorXd dq = b.s > a.s ? hermiteVariation(a, b, at) : a.dq;
    trace.x.push_back(project(q));
    const double e = 1e-6;
    trace.spread.push_back((project(q + e * dq) - trace.x.back()).norm() / e);
    trace.xs.push_back(s);
    if (final) break;
  }
}

// The grid's nodes as unit vectors, and the best arrival at each.
struct Raster {
  int rows = 0, cols = 0;
  std::vector<Eigen::Vector3d> nodes;
  std::vector<double> distance, direction, spread;
  void reset() {
    distance.assign(nodes.size(), std::numeric_limits<double>::infinity());
    direction.assign(nodes.size(), 0.0);
    spread.assign(nodes.size(), 0.0);
  }
};

// Rasterises the spherical triangle (a, b, c) (short, so its gnomonic image is the flat triangle): every node
// whose ray meets it gets the barycentric interpolation of the arc lengths and angles, if shorter.
void rasteriseTriangle(Raster& r, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                       const Eigen::Vector3d& s, const Eigen::Vector3d& angle, const Eigen::Vector3d& spread) {
  Eigen::Matrix3d m;
  m << a, b, c;
  const double det = m.determinant();
  if (std::abs(det) < 1e-18) return;
  const Eigen::Matrix3d inverse = m.inverse();
  const Eigen::Vector3d centre = (a + b + c).normalized();
  double radius = 0;
  for (const Eigen::Vector3d* v : {&a, &b, &c}) radius = std::max(radius, std::acos(std::clamp(centre.dot(*v), -1.0, 1.0)));
  const double dphi = kPi / (r.rows - 1), dt = 2 * kPi / r.cols;
  radius += 1e-9;
  const double phi = std::asin(std::clamp(centre.z(), -1.0, 1.0)), t = std::atan2(centre.y(), centre.x());
  const int i0 = std::max(0, static_cast<int>(std::ceil((phi - radius + kPi / 2) / dphi - 1e-9)));
  const int i1 = std::min(r.rows - 1, static_cast<int>(std::floor((phi + radius + kPi / 2) / dphi + 1e-9)));
  const double widest = std::max(std::abs(phi - radius), std::abs(phi + radius));
  const bool allColumns = widest >= kPi / 2 - 1e-12 || radius / std::cos(widest) >= kPi;
  const double halfWidth = allColumns ? kPi : std::asin(std::min(1.0, std::sin(radius) / std::cos(widest))) + 1e-9;
  const int j0 = allColumns ? 0 : static_cast<int>(std::ceil((t - halfWidth + kPi) / dt));
  const int j1 = allColumns ? r.cols - 1 : static_cast<int>(std::floor((t + halfWidth + kPi) / dt));
  for (int i = i0; i <= i1; ++i) {
    for (int jj = j0; jj <= j1; ++jj) {
      const int j = ((jj % r.cols) + r.cols) % r.cols;
      const std::size_t node = static_cast<std::size_t>(i * r.cols + j);
      const Eigen::Vector3d w = inverse * r.nodes[node];
      const double sum = w.sum();
      if (sum <= 0 || w.minCoeff() < -1e-12 * sum) continue;
      const Eigen::Vector3d bary = w / sum;
      const double value = bary.dot(s);
      if (value < r.distance[node]) {
        r.distance[node] = value;
        r.direction[node] = bary.dot(angle);
        r.spread[node] = bary.dot(spread);
      }
    }
  }
}

// The triangles between neighbouring traces (the last with the first, a turn later).
void rasterise(Raster& r, const std::vector<const Trace*>& fan, std::size_t first, std::size_t last) {
  for (std::size_t p = first; p < last; ++p) {
    const Trace& u = *fan[p];
    const Trace& w = *fan[(p + 1) % fan.size()];
    const double angleU = u.angle, angleW = p + 1 == fan.size() ? w.angle + 2 * kPi : w.angle;
    const std::size_t common = std::min(u.x.size(), w.x.size());
    for (std::size_t k = 0; k + 1 < common; ++k) {
      const Eigen::Vector3d au(angleU, angleW, angleW), bu(angleU, angleW, angleU);
      rasteriseTriangle(r, u.x[k], w.x[k], w.x[k + 1], {u.xs[k], w.xs[k], w.xs[k + 1]}, au,
                        {u.spread[k], w.spread[k], w.spread[k + 1]});
      rasteriseTriangle(r, u.x[k], w.x[k + 1], u.x[k + 1], {u.xs[k], w.xs[k + 1], u.xs[k + 1]}, bu,
                        {u.spread[k], w.spread[k + 1], u.spread[k + 1]});
    }
    const Trace& longer = u.x.size() > w.x.size() ? u : w;
    const Trace& shorter = u.x.size() > w.x.size() ? w : u;
    const double angleLong = &longer == &u ? angleU : angleW, angleShort = &longer == &u ? angleW : angleU;
    for (std::size_t k = common - 1; k + 1 < longer.x.size(); ++k)
      rasteriseTriangle(r, shorter.x[common - 1], longer.x[k], longer.x[k + 1],
                        {shorter.xs[common - 1], longer.xs[k], longer.xs[k + 1]},
                        {angleShort, angleLong, angleLong},
                        {shorter.spread[common - 1], longer.spread[k], longer.spread[k + 1]});
  }
}

void rasteriseFan(Raster& r, const std::vector<const Trace*>& fan, int threads) {
  const std::size_t chunks = std::max<std::size_t>(1, std::min<std::size_t>(fan.size(), 8));
  std::vector<Raster> parts(chunks, r);
  parallelFor(chunks, static_cast<std::size_t>(threads), [&](std::size_t c) {
    parts[c].reset();
    rasterise(parts[c], fan, c * fan.size() / chunks, (c + 1) * fan.size() / chunks);
  });
  r.reset();
  for (const Raster& part : parts)
    for (std::size_t n = 0; n < r.distance.size(); ++n)
      if (part.distance[n] < r.distance[n]) {
        r.distance[n] = part.distance[n];
        r.direction[n] = part.direction[n];
        r.spread[n] = part.spread[n];
      }
}

double circularDifference(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 2 * kPi);
  return std::min(d, 2 * kPi - d);
}

}  // namespace

DistanceMap distanceMap(const ConstrainedModel& model, const SphereProjection& project, const Eigen::VectorXd& point,
                        const DistanceMapOptions& options) {
  if (model.freedom() != 2) throw std::invalid_argument("distanceMap: the configuration space must be a surface");
  const int columns = options.columns > 0 ? options.columns : options.grid;
  if (options.grid < 8 || columns < 8 || options.directions < 8)
    throw std::invalid_argument("distanceMap: at least an 8 x 8 grid and 8 directions");
  const GeodesicFlow flow(model, options.tolerance);
  DistanceMap map;
  map.basis = model.tangentBasis(point);
  map.point = project(point);
  Raster raster;
  raster.rows = options.grid;
  raster.cols = columns;
  for (int i = 0; i < raster.rows; ++i) {
    map.phis.push_back(-kPi / 2 + kPi * i / (raster.rows - 1));
    for (int j = 0; j < raster.cols; ++j) {
      const double phi = map.phis.back(), t = -kPi + 2 * kPi * j / raster.cols;
      raster.nodes.emplace_back(std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi));
    }
  }
  for (int j = 0; j < raster.cols; ++j) map.ts.push_back(-kPi + 2 * kPi * j / raster.cols);
  const double cell = kPi / (raster.rows - 1);

  std::map<double, Trace> fan;  // by angle in [0, 2 pi)
  int traced = 0, expected = options.directions;
  std::mutex progressMutex;
  auto traceAll = [&](const std::vector<double>& angles, double cap) {
    std::vector<Trace> traces(angles.size());
    parallelFor(angles.size(), static_cast<std::size_t>(options.threads), [&](std::size_t k) {
      traces[k] = traceDirection(flow, point, map.basis, angles[k], cap);
      if (options.progress) {
        const std::lock_guard<std::mutex> lock(progressMutex);
        options.progress(++traced, std::max(expected, traced));
      }
    });
    for (Trace& t : traces) fan.emplace(t.angle, std::move(t));
  };

  // The first fan, each geodesic to its first conjugate point or the cap; how fast the sphere point moves
  // along it sets the arc-length step, its farthest arrival the length bound.
  std::vector<double> angles;
  for (int k = 0; k < options.directions; ++k) angles.push_back(2 * kPi * k / options.directions);
  traceAll(angles, options.lengthCap);
  double speed = 1e-3;
  for (const auto& [angle, trace] : fan)
    for (const Sample& s : trace.samples) {
      const double e = 1e-6;
      speed = std::max(speed, (project(s.q + e * s.v) - project(s.q)).norm() / e);
    }
  const double ds = 1.5 * cell / speed;
  auto collect = [&] {
    std::vector<const Trace*> list;
    for (const auto& [angle, trace] : fan) list.push_back(&trace);
    return list;
  };
  double bound = options.lengthCap;
  auto resampleAll = [&](const std::vector<double>& which) {
    parallelFor(which.size(), static_cast<std::size_t>(options.threads),
                [&](std::size_t k) { resample(fan.at(which[k]), project, ds, bound); });
  };
  resampleAll(angles);
  rasteriseFan(raster, collect(), options.threads);
  double farthest = 0;
  for (double d : raster.distance)
    if (std::isfinite(d)) farthest = std::max(farthest, d);
  bound = 1.2 * farthest + 4 * ds;
  resampleAll(angles);

  // Bisect between neighbours that separate by more than a grid spacing within the bound.
  const double cap = std::min(options.lengthCap, 2 * bound);
  for (int round = 0; round < 12; ++round) {
    std::vector<double> added;
    const std::vector<const Trace*> list = collect();
    for (std::size_t p = 0; p < list.size(); ++p) {
      const Trace& u = *list[p];
      const Trace& w = *list[(p + 1) % list.size()];
      const double upper = p + 1 == list.size() ? w.angle + 2 * kPi : w.angle;
      if (upper - u.angle < 1e-7) continue;
      double gap = 0;
      for (std::size_t k = 0; k < std::min(u.x.size(), w.x.size()); ++k) gap = std::max(gap, (u.x[k] - w.x[k]).norm());
      if (gap > cell) added.push_back(std::fmod((u.angle + upper) / 2, 2 * kPi));
    }
    if (added.empty()) break;
    expected = traced + static_cast<int>(added.size());
    traceAll(added, cap);
    resampleAll(added);
  }
  map.geodesics = static_cast<int>(fan.size());

  rasteriseFan(raster, collect(), options.threads);
  // Fill the nodes no triangle reached from their reached neighbours (none, normally).
  for (int pass = 0; pass < 8; ++pass) {
    bool missing = false;
    std::vector<double> filled = raster.distance;
    for (int i = 0; i < raster.rows; ++i)
      for (int j = 0; j < raster.cols; ++j) {
        const int n = i * raster.cols + j;
        if (std::isfinite(raster.distance[static_cast<std::size_t>(n)])) continue;
        if (pass == 0) ++map.uncovered;
        double sum = 0;
        int count = 0;
        for (const auto& [di, dj] : {std::pair{0, 1}, {0, -1}, {1, 0}, {-1, 0}}) {
          const int ii = i + di, jj = ((j + dj) % raster.cols + raster.cols) % raster.cols;
          if (ii < 0 || ii >= raster.rows) continue;
          const double d = raster.distance[static_cast<std::size_t>(ii * raster.cols + jj)];
          if (std::isfinite(d)) {
            sum += d;
            ++count;
            raster.direction[static_cast<std::size_t>(n)] = raster.direction[static_cast<std::size_t>(ii * raster.cols + jj)];
          }
        }
        if (count > 0) filled[static_cast<std::size_t>(n)] = sum / count;
        else missing = true;
      }
    raster.distance = filled;
    if (!missing) break;
  }
  map.distance = raster.distance;
  map.direction.resize(raster.direction.size());
  for (std::size_t n = 0; n < raster.direction.size(); ++n) {
    const double a = std::fmod(raster.direction[n], 2 * kPi);
    map.direction[n] = a < 0 ? a + 2 * kPi : a;
  }
  for (double d : map.distance) map.farthest = std::max(map.farthest, d);

  map.conjugateRadius = std::numeric_limits<double>::infinity();
  for (auto& [angle, trace] : fan) {
    if (!trace.conjugate) continue;
    ConjugatePoint c = trace.conjugatePoint;
    c.x = project(c.q);
    map.conjugateRadius = std::min(map.conjugateRadius, c.distance);
    map.conjugateLocus.push_back(std::move(c));
  }

  // The cut locus: grid edges across which the shortest arrival comes from distinct directions. Near the
  // point every direction arrives within a few cells, so a disc of 12 cells about it is left out.
  const double nearPoint = 12 * cell;
  auto considered = [&](int n) { return (raster.nodes[static_cast<std::size_t>(n)] - map.point).norm() > nearPoint; };
  auto examine = [&](int a, int b) {
    if (!considered(a) || !considered(b)) return;
    // On one sheet of the exponential map the direction changes by about |dx| / spread between neighbours;
    // a jump well beyond that (and beyond cutAngle) means two distinct geodesics.
    const std::size_t ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    const double jump = circularDifference(map.direction[ua], map.direction[ub]);
    const double smooth = (raster.nodes[ua] - raster.nodes[ub]).norm() / std::max(1e-12, (raster.spread[ua] + raster.spread[ub]) / 2);
    if (jump <= options.cutAngle || jump <= 3 * smooth) return;
    CutEdge e;
    e.a = a;
    e.b = b;
    e.distance = (map.distance[static_cast<std::size_t>(a)] + map.distance[static_cast<std::size_t>(b)]) / 2;
    e.x = (raster.nodes[static_cast<std::size_t>(a)] + raster.nodes[static_cast<std::size_t>(b)]).normalized();
    map.cutLocus.push_back(e);
  };
  for (int i = 0; i < raster.rows; ++i)
    for (int j = 0; j < raster.cols; ++j) {
      const int n = i * raster.cols + j;
      if (i > 0 && i + 1 < raster.rows) examine(n, i * raster.cols + (j + 1) % raster.cols);
      if (i + 1 < raster.rows) examine(n, n + raster.cols);
    }
  map.injectivityRadius = std::numeric_limits<double>::infinity();
  for (const CutEdge& e : map.cutLocus) map.injectivityRadius = std::min(map.injectivityRadius, e.distance);
  // A first conjugate point still reached by no shorter geodesic is a cut point too (an end of the cut locus,
  // or all of it on a round sphere): the map there, interpolated, is not below its distance.
  for (ConjugatePoint& c : map.conjugateLocus) {
    const double phi = std::asin(std::clamp(c.x.z(), -1.0, 1.0)), t = std::atan2(c.x.y(), c.x.x());
    const double fi = std::clamp((phi + kPi / 2) / cell, 0.0, raster.rows - 1.0), fj = (t + kPi) / (2 * kPi) * raster.cols;
    const int i0 = std::min(static_cast<int>(fi), raster.rows - 2), j0 = static_cast<int>(std::floor(fj));
    const double wi = fi - i0, wj = fj - j0;
    auto at = [&](int i, int j) {
      return map.distance[static_cast<std::size_t>(i * raster.cols + ((j % raster.cols) + raster.cols) % raster.cols)];
    };
    const double there = (1 - wi) * ((1 - wj) * at(i0, j0) + wj * at(i0, j0 + 1)) +
                         wi * ((1 - wj) * at(i0 + 1, j0) + wj * at(i0 + 1, j0 + 1));
    c.cut = there >= c.distance - 2 * ds;
    if (c.cut) map.injectivityRadius = std::min(map.injectivityRadius, c.distance);
  }
  map.shortestLoop = shortestGeodesicLoop(model, point, 2 * bound, options.tolerance);
  return map;
}

double shortestGeodesicLoop(const ConstrainedModel& model, const Eigen::VectorXd& point, double bound,
                            double tolerance) {
  const GeodesicFlow flow(model, tolerance);
  const Eigen::MatrixXd basis = model.tangentBasis(point);
  constexpr int kDirections = 64;
  std::vector<double> best(kDirections, 0.0);
  parallelFor(kDirections, [&](std::size_t k) {
    const Eigen::VectorXd u = directionAt(basis, 2 * kPi * static_cast<double>(k) / kDirections);
    FlowState state{point, u, Eigen::MatrixXd(point.size(), 0), Eigen::MatrixXd(point.size(), 0)};
    std::vector<std::pair<double, double>> path;  // (s, |q - point|)
    flow.advance(state, bound, [&](double s, const FlowState& x) {
      path.emplace_back(s, (x.q - point).norm());
      return true;
    });
    double shortest = 0;
    for (std::size_t i = 1; i + 1 < path.size(); ++i) {
      if (path[i].first < 1e-2 * bound || path[i].second > 0.5) continue;
      if (path[i].second > path[i - 1].second || path[i].second > path[i + 1].second) continue;
      const auto loop = shootConnection(model, point, point, path[i].first * u, tolerance);
      if (loop && loop->length > 1e-3 && (shortest == 0 || loop->length < shortest)) shortest = loop->length;
    }
    best[k] = shortest;
  });
  double shortest = 0;
  for (double b : best)
    if (b > 0 && (shortest == 0 || b < shortest)) shortest = b;
  return shortest;
}

std::optional<Arrival> shortestArrival(const ConstrainedModel& model, const DistanceMap& map,
                                       const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                       const Eigen::Vector3d& x) {
  const std::size_t rows = map.phis.size(), columns = map.ts.size();
  if (rows < 2 || columns < 2) throw std::invalid_argument("shortestArrival: the map has no grid");
  // The cell holding x in chart 0: rows phi from pole to pole, columns t periodic from -pi.
  const double phi = std::asin(std::clamp(x.z(), -1.0, 1.0)), t = std::atan2(x.y(), x.x());
  const double rowStep = map.phis[1] - map.phis[0], columnStep = map.ts[1] - map.ts[0];
  const std::size_t i = std::min(rows - 2, static_cast<std::size_t>(std::max(0.0, (phi - map.phis[0]) / rowStep)));
  const std::size_t j = static_cast<std::size_t>(std::max(0.0, std::floor((t - map.ts[0]) / columnStep))) % columns;
  std::optional<Arrival> best;
  for (const std::size_t row : {i, i + 1})
    for (const std::size_t column : {j, (j + 1) % columns}) {
      const std::size_t n = row * columns + column;
      if (!std::isfinite(map.distance[n]) || !std::isfinite(map.direction[n])) continue;
      const Eigen::VectorXd seed = map.distance[n] * directionAt(map.basis, map.direction[n]);
      const std::optional<Connection> shot = shootConnection(model, from, to, seed);
      if (!shot || (best && shot->length >= best->distance)) continue;
      const double along = model.inner(shot->velocity, map.basis.col(0)),
                   across = model.inner(shot->velocity, map.basis.col(1));
      best = Arrival{shot->length, std::atan2(across, along)};
    }
  return best;
}

}  // namespace sl

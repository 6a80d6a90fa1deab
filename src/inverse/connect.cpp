#include "inverse/connect.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "inverse/geodesic_flow.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

namespace {

double pathDistance(const std::vector<Eigen::VectorXd>& a, const std::vector<Eigen::VectorXd>& b) {
  double worst = 0;
  for (std::size_t j = 0; j < a.size() && j < b.size(); ++j) worst = std::max(worst, maxAbs(a[j] - b[j]));
  return worst;
}

}  // namespace

std::vector<Eigen::VectorXd> shootingPath(const ConstrainedModel& model, const Eigen::VectorXd& from,
                                          const Eigen::VectorXd& velocity, int intervals, double tolerance) {
  const GeodesicFlow flow(model, tolerance);
  const int n = model.dimension();
  FlowState state{from, velocity, Eigen::MatrixXd(n, 0), Eigen::MatrixXd(n, 0)};
  std::vector<Eigen::VectorXd> path{from};
  for (int j = 1; j <= intervals; ++j) {
    flow.advance(state, 1.0 / intervals);
    path.push_back(state.q);
  }
  return path;
}

std::optional<Connection> shootConnection(const ConstrainedModel& model, const Eigen::VectorXd& from,
                                          const Eigen::VectorXd& to, Eigen::VectorXd velocity, double tolerance) {
  const GeodesicFlow flow(model, tolerance);
  const int n = model.dimension();
  const Eigen::MatrixXd basis = model.tangentBasis(from);
  const int d = static_cast<int>(basis.cols());
  // Long chains: the derivative dq(1)/dv costs d variation columns, O(d) times a bare shot; shot once, then
  // kept up to date by Broyden's rank-one updates from bare shots, and shot again only when a step fails
  // to halve the error (docs/geometry.md, "Long chains"). Small models take the exact derivative every time.
  const bool broyden = d > kExactShootingFreedom;
  velocity = model.projectVelocity(from, velocity);
  double previous = INFINITY;
  Eigen::MatrixXd jacobian;                // dq(1)/dv B: exact, or Broyden's estimate
  bool fresh = false;                      // the last step came from the exact derivative
  Eigen::VectorXd lastStep, lastResidual;  // for Broyden's update
  int exactShots = 0;
  for (int iteration = 1; iteration <= (broyden ? 80 : 40); ++iteration) {
    const bool exact = !broyden || jacobian.size() == 0 || lastStep.size() == 0;
    // Near the conjugate locus Newton stalls with the exact derivative too; the exact shots, the costly ones,
    // are bounded so that such a seed fails in a few of them.
    if (broyden && exact && ++exactShots > kMaxExactShots) return std::nullopt;
    FlowState state{from, velocity, Eigen::MatrixXd::Zero(n, exact ? d : 0), exact ? basis : Eigen::MatrixXd(n, 0)};
    try {
      flow.advance(state, 1.0);
    } catch (const std::runtime_error&) {
      return std::nullopt;
    }
    const Eigen::VectorXd residual = state.q - to;
    const double error = maxAbs(residual);
    if (error <= 1e-13 || (error <= 1e-12 && error >= previous * 0.5)) {
      Connection c;
      c.velocity = velocity;
      c.length = model.norm(velocity);
      c.endError = error;
      c.newtonIterations = iteration;
      return c;
    }
    if (exact) {
      jacobian = state.dq;
      fresh = true;
    } else if (error > 0.5 * previous && !fresh) {
      // Broyden's estimate no longer halves the error: back to the last point, the exact derivative there.
      velocity -= basis * lastStep;
      lastStep.resize(0);
      continue;
    } else {
      const Eigen::VectorXd change = residual - lastResidual;
      jacobian += (change - jacobian * lastStep) * lastStep.transpose() / lastStep.squaredNorm();
      fresh = false;
    }
    previous = error;
    lastResidual = residual;
    // Gauss-Newton in the mass metric: min |J x + r|_M.
    const Eigen::MatrixXd& j = jacobian;
    Eigen::VectorXd x;
    if (broyden) {
      const Eigen::MatrixXd mj = model.sparseMass() * j;
      x = (j.transpose() * mj).ldlt().solve(-(mj.transpose() * residual));
    } else {
      const Eigen::MatrixXd normal = j.transpose() * model.mass() * j;
      x = normal.ldlt().solve(-(j.transpose() * model.mass() * residual));
    }
    Eigen::VectorXd step = basis * x;
    const double limit = 0.5 * std::max(1.0, model.norm(velocity));
    if (model.norm(step) > limit) {
      x *= limit / model.norm(step);
      step = basis * x;
    }
    velocity += step;
    lastStep = x;
    if (!velocity.allFinite()) return std::nullopt;
  }
  return std::nullopt;
}

std::vector<std::vector<Eigen::VectorXd>> sphereArcPaths(const Chain& chain, const Eigen::VectorXd& from,
                                                         const Eigen::VectorXd& to, int intervals) {
  std::vector<std::vector<Eigen::VectorXd>> out;
  if (chain.isSlack()) return out;
  const Eigen::VectorXd a = spherePointFromHinges(chain, ConstrainedModel::unstack(from));
  const Eigen::VectorXd b = spherePointFromHinges(chain, ConstrainedModel::unstack(to));
  Eigen::VectorXd w = b - a.dot(b) * a;
  if (w.norm() < 1e-9) {  // antipodal or equal: any perpendicular direction
    w = Eigen::VectorXd::Unit(a.size(), 0) - a(0) * a;
    if (w.norm() < 1e-3) w = Eigen::VectorXd::Unit(a.size(), 1) - a(1) * a;
  }
  w.normalize();
  const double angle = std::atan2(b.dot(w), a.dot(b));  // in [0, pi]
  for (double total : {angle, angle - 2 * std::numbers::pi}) {
    std::vector<Eigen::VectorXd> path;
    for (int i = 0; i <= intervals; ++i) {
      const double s = total * i / intervals;
      path.push_back(i == 0 ? from
                     : i == intervals
                         ? to
                         : ConstrainedModel::stack(hingePositionsAt(chain, std::cos(s) * a + std::sin(s) * w)));
    }
    out.push_back(path);
  }
  return out;
}

int morseIndexOnChain(const Chain& chain, const Eigen::VectorXd& from, const Eigen::VectorXd& velocity) {
  if (chain.rods < 4) return 0;  // a circle has no conjugate points
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const double length = model.norm(velocity);
  if (chain.isSlack()) return -1;  // the Jacobi fields start from a point of the configuration sphere
  const Eigen::VectorXd x = spherePointFromHinges(chain, ConstrainedModel::unstack(from));
  const InitialState start(x,
                           sphereVelocityFromHingeVelocities(chain, x, ConstrainedModel::unstack(velocity / length)));
  RunConfig config;
  config.jacobi = true;
  Trajectory run(chain, start, config);
  run.sampleAt(length);
  int count = 0;
  for (double t : run.conjugateTimes())
    if (t < length * (1 - 1e-9)) ++count;
  return count;
}

namespace {

// When the continuation fails: shot from the arc's first chord; on long chains, where the arc's branch of
// shots can fold before the target (docs/geometry.md, "Long chains"), from route 2's geodesic found by descent
// from the arc.
std::optional<Connection> fromTheArc(const ConstrainedModel& model, const Chain& chain, const Eigen::VectorXd& from,
                                     const Eigen::VectorXd& to, const std::vector<Eigen::VectorXd>& arc,
                                     double tolerance) {
  const int intervals = static_cast<int>(arc.size()) - 1;
  auto c = shootConnection(model, from, to, (arc[1] - arc[0]) * intervals, tolerance);
  if (c || static_cast<int>(model.tangentBasis(from).cols()) <= kExactShootingFreedom) return c;
  // The first chord over its time step, projected onto the tangent space, is the initial velocity to O(h^2)
  // (the geodesic's acceleration is normal to it); two node counts extrapolate it to O(h^4). No refinement to
  // route 2's accuracy: Newton's shots finish the job.
  std::vector<Eigen::VectorXd> nodes = sphereArcPaths(chain, from, to, 5 * kPathSamples)[0];
  for (std::size_t i = 1; i + 1 < nodes.size(); ++i) model.projectPosition(nodes[i]);
  if (!descendDiscrete(model, nodes) || !solveDiscrete(model, nodes)) return std::nullopt;
  const auto chord = [&] {
    const double k = static_cast<double>(nodes.size() - 1);
    return model.projectVelocity(from, (nodes[1] - nodes[0]) * k);
  };
  const Eigen::VectorXd coarse = chord();
  if ((c = shootConnection(model, from, to, coarse, tolerance))) return c;
  nodes = refine(model, nodes);
  if (!solveDiscrete(model, nodes)) return std::nullopt;
  return shootConnection(model, from, to, (4 * chord() - coarse) / 3, tolerance);
}

}  // namespace

std::optional<Connection> directConnection(const ConstrainedModel& model, const Chain* chain,
                                           const Eigen::VectorXd& from, const Eigen::VectorXd& to, double tolerance) {
  if (chain == nullptr || chain->isSlack()) return shootConnection(model, from, to, to - from, tolerance);
  // Continuation along the great-circle arc: shoot at the arc's points one stage further each time, from
  // the previous stage's velocity stretched to the longer arc, so Newton always starts close.
  const int intervals = 64, stages = 4;
  const auto arc = sphereArcPaths(*chain, from, to, intervals)[0];
  Eigen::VectorXd velocity = (arc[1] - arc[0]) * intervals / stages;
  std::optional<Connection> c;
  for (int stage = 1; stage <= stages; ++stage) {
    c = shootConnection(model, from, arc[static_cast<std::size_t>(stage * intervals / stages)], velocity, tolerance);
    if (!c) return fromTheArc(model, *chain, from, to, arc, tolerance);
    velocity = c->velocity * (stage + 1.0) / stage;
  }
  return c;
}

bool sameShape(const ConstrainedModel& model, const Eigen::VectorXd& from, const Eigen::VectorXd& to) {
  return model.norm(from - to) < kSameShapeDistance;
}

std::vector<Connection> findConnections(const ConstrainedModel& model, const Chain* chain, const Eigen::VectorXd& from,
                                        const Eigen::VectorXd& to, const ConnectOptions& options) {
  std::vector<Connection> found;
  auto add = [&](std::optional<Connection> c) {
    // The motion of no length (staying put) is no motion: its direction would be rounding noise.
    if (!c || c->length < kSameShapeDistance) return;
    for (const Connection& known : found)
      if (model.norm(known.velocity - c->velocity) < 1e-6 * std::max(1.0, c->length)) return;
    found.push_back(*c);
  };
  add(directConnection(model, chain, from, to, options.tolerance));
  double maxLength = options.maxLength;
  if (maxLength <= 0) maxLength = found.empty() ? 10.0 : 2.5 * found[0].length;

  // The fan: unit-speed geodesics from the start, their closest approaches to the target as seeds.
  const Eigen::MatrixXd basis = model.tangentBasis(from);
  const int d = static_cast<int>(basis.cols());
  std::vector<Eigen::VectorXd> directions;
  if (d == 1) {
    directions = {basis.col(0), -basis.col(0)};
  } else if (d == 2) {
    for (int k = 0; k < options.directions; ++k) {
      const double a = 2 * std::numbers::pi * (k + 0.5) / options.directions;
      directions.push_back(std::cos(a) * basis.col(0) + std::sin(a) * basis.col(1));
    }
  } else {
    for (int i = 0; i < d; ++i) {
      directions.push_back(basis.col(i));
      directions.push_back(-basis.col(i));
      for (int j = i + 1; j < std::min(d, 4); ++j)  // diagonals among the first four only: O(d) rays
        for (double s : {1.0, -1.0}) {
          directions.push_back((basis.col(i) + s * basis.col(j)) / std::sqrt(2.0));
          directions.push_back(-(basis.col(i) + s * basis.col(j)) / std::sqrt(2.0));
        }
    }
  }
  struct Seed {
    double distance;
    Eigen::VectorXd velocity;
  };
  std::vector<Seed> seeds;
  const GeodesicFlow flow(model, 1e-9);
  const int n = model.dimension();
  const std::size_t shots = d > kExactShootingFreedom ? kLongChainSeeds : 60;
  const auto tell = [&](std::size_t done, std::size_t total) {
    if (options.progress) options.progress(static_cast<long>(done), static_cast<long>(total));
  };
  std::size_t raysDone = 0;
  for (const Eigen::VectorXd& u : directions) {
    tell(raysDone++, directions.size() + shots);
    stopIfCancelled(options.cancelled);
    FlowState state{from, u, Eigen::MatrixXd(n, 0), Eigen::MatrixXd(n, 0)};
    double d2 = INFINITY, d1 = INFINITY, t1 = 0;
    try {
      flow.advance(state, maxLength * 1.05, [&](double t, const FlowState& s) {
        if (options.cancelled && options.cancelled()) return false;  // a long ray answers within a step
        const double d0 = model.norm(s.q - to);
        if (d1 < d2 && d1 <= d0 && d1 < 0.6 && t1 > 0) seeds.push_back({d1, t1 * u});
        d2 = d1;
        d1 = d0;
        t1 = t;
        return true;
      });
    } catch (const std::runtime_error&) {
    }
  }
  std::sort(seeds.begin(), seeds.end(), [](const Seed& a, const Seed& b) { return a.distance < b.distance; });
  // Each seed costs a shot with the derivative; in high dimension the fan's close approaches mostly lead
  // back to the same few geodesics, so only the closest are shot (docs/geometry.md, "Long chains").
  if (seeds.size() > shots) seeds.resize(shots);
  std::size_t shotsDone = 0;
  for (const Seed& seed : seeds) {
    tell(directions.size() + shotsDone++, directions.size() + seeds.size());
    stopIfCancelled(options.cancelled);
    add(shootConnection(model, from, to, seed.velocity, options.tolerance));
  }
  found.erase(std::remove_if(found.begin(), found.end(),
                             [&](const Connection& c) { return c.length > maxLength * (1 + 1e-12); }),
              found.end());
  const auto shorter = [](const Connection& a, const Connection& b) { return a.length < b.length; };
  std::sort(found.begin(), found.end(), shorter);

  // A motion route 1 found: its path and its Morse index.
  const auto describe = [&](Connection& c) {
    c.path = shootingPath(model, from, c.velocity, kPathSamples, options.tolerance);
    // The Jacobi fields' Gram determinant of n - 3 fields loses its zeros among the products of many small
    // factors on long chains; there the discrete action's second variation counts them.
    if (chain != nullptr)
      c.morseIndex = d > kExactShootingFreedom ? discreteMorseIndex(model, from, c.velocity)
                                               : morseIndexOnChain(*chain, from, c.velocity);
  };
  tell(directions.size() + seeds.size(), directions.size() + seeds.size());
  for (Connection& c : found) {
    stopIfCancelled(options.cancelled);
    describe(c);
  }
  if (!options.discreteRoute) return found;

  // Route 2: first from seeds that know nothing of route 1, then from route 1's paths for the rest.
  auto match = [&](const DiscreteGeodesic& g) -> Connection* {
    for (Connection& c : found)
      if (std::abs(c.length - g.length) < 1e-6 && pathDistance(c.path, g.path) < 1e-5) return &c;
    return nullptr;
  };
  auto record = [&](Connection* c, const DiscreteGeodesic& g) {
    if (c == nullptr || c->discrete) return;
    c->discrete = g;
    c->lengthDifference = std::abs(c->length - g.length);
    c->pathDifference = pathDistance(c->path, g.path);
  };
  if (chain != nullptr) {
    const auto arcs = sphereArcPaths(*chain, from, to, 5 * kPathSamples);
    for (std::size_t k = 0; k < arcs.size(); ++k) {
      const auto g = discreteGeodesic(model, arcs[k], k == 0 ? DiscreteSeed::SphereArc : DiscreteSeed::SphereArcLongWay,
                                      d > kExactShootingFreedom);
      if (!g) continue;
      Connection* c = match(*g);
      // Long chains shoot few of the fan's seeds and may miss a geodesic route 2 found from the arc: shot
      // from the discrete path's first chord (projected onto the tangent space, O(h^2) from the geodesic's
      // velocity), it is found by route 1 too and then checked like the others.
      if (c == nullptr && d > kExactShootingFreedom && g->length <= maxLength * (1 + 1e-12)) {
        const std::size_t before = found.size();
        add(shootConnection(model, from, to, g->startVelocity, options.tolerance));
        if (found.size() > before) describe(found.back());
        std::sort(found.begin(), found.end(), shorter);
        c = match(*g);
      }
      record(c, *g);
    }
  }
  for (Connection& c : found) {
    if (c.discrete) continue;
    const int intervals = kPathSamples * std::max(5, static_cast<int>(std::ceil(2 * c.length)));
    const auto g = discreteGeodesic(model, shootingPath(model, from, c.velocity, intervals, options.tolerance),
                                    DiscreteSeed::ShootingPath);
    if (g && match(*g) == &c) record(&c, *g);
  }
  return found;
}

}  // namespace sl

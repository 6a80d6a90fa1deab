#include "inverse/periodic.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "contracts/csv_format.hpp"
#include "contracts/limits.hpp"
#include "inverse/connect.hpp"
#include "inverse/geodesic_flow.hpp"
#include "linkage/chart.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kOrbitSamples = 512;


// How close a point of a sampled orbit must come to count as on it: the chords of kOrbitSamples points stray
// from the curve by about (spacing)^2 curvature / 8, and the curvature grows as the orbit shrinks; 1e-3 of the
// length squared (over its scale) bounds that with margin on a sphere of even masses.
double onOrbitTolerance(double length) {
  const double spacing = length / kOrbitSamples;
  return (2 * spacing * spacing + 1e-9 * orbitScale(length) * orbitScale(length)) / orbitScale(length);
}

// The same bound measured on the sampled orbit itself: a chord's sag is an eighth of the second difference
// |y(i-1) - 2 y(i) + y(i+1)| (h^2 times the curvature). With masses far apart the mass-weighted orbit bends
// much more sharply than the even-mass estimate above (masses [0.01, 1, 100] listed one orbit five times),
// so the larger of the two is used, with a factor 2 of margin.
double onOrbitTolerance(const std::vector<Eigen::VectorXd>& orbit, double length) {
  double sag = 0;
  const std::size_t n = orbit.size();
  for (std::size_t i = 0; i < n; ++i)
    sag = std::max(sag, (orbit[(i + n - 1) % n] - 2 * orbit[i] + orbit[(i + 1) % n]).norm() / 8);
  return std::max(onOrbitTolerance(length), 2 * sag);
}

// A unit tangent vector M-orthogonal to the unit velocity v at q (2-dimensional models).
Eigen::VectorXd across(const ConstrainedModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  const Eigen::MatrixXd basis = model.tangentBasis(q);
  Eigen::VectorXd best;
  double bestSize = -1;
  for (Eigen::Index j = 0; j < basis.cols(); ++j) {
    Eigen::VectorXd n = basis.col(j) - model.inner(basis.col(j), v) * v;
    const double size = model.norm(n);
    if (size > bestSize) {
      bestSize = size;
      best = n / size;
    }
  }
  return best;
}

// The orbit sampled at kOrbitSamples points, in coordinates where M is the identity (y = U q, M = U^T U).
std::vector<Eigen::VectorXd> sampledOrbit(const ConstrainedModel& model, const Eigen::VectorXd& q0,
                                          const Eigen::VectorXd& v0, double period) {
  const GeodesicFlow flow(model, 1e-12);
  const Eigen::MatrixXd u = model.mass().llt().matrixU();
  FlowState s{q0, v0, Eigen::MatrixXd(q0.size(), 0), Eigen::MatrixXd(q0.size(), 0)};
  std::vector<Eigen::VectorXd> out{u * q0};
  for (int i = 1; i < kOrbitSamples; ++i) {
    flow.advance(s, period / kOrbitSamples);
    out.push_back(u * s.q);
  }
  return out;
}

double segmentDistance(const Eigen::VectorXd& a0, const Eigen::VectorXd& a1, const Eigen::VectorXd& b0,
                       const Eigen::VectorXd& b1) {
  const Eigen::VectorXd u = a1 - a0, w = b1 - b0, r = a0 - b0;
  const double uu = u.dot(u), ww = w.dot(w), uw = u.dot(w), ur = u.dot(r), wr = w.dot(r);
  if (ww == 0.0) return (r + std::clamp(-ur / uu, 0.0, 1.0) * u).norm();  // b is a point
  const double det = uu * ww - uw * uw;
  double s = det > 1e-300 ? std::clamp((uw * wr - ww * ur) / det, 0.0, 1.0) : 0.0;
  const double t = std::clamp((uw * s + wr) / ww, 0.0, 1.0);
  s = std::clamp((uw * t - ur) / uu, 0.0, 1.0);
  return (r + s * u - t * w).norm();
}

// Distance from a point (in the U coordinates) to the closed polyline.
double distanceToOrbit(const std::vector<Eigen::VectorXd>& orbit, const Eigen::VectorXd& y) {
  double best = INFINITY;
  const std::size_t n = orbit.size();
  for (std::size_t i = 0; i < n; ++i) best = std::min(best, segmentDistance(orbit[i], orbit[(i + 1) % n], y, y));
  return best;
}

// A transversal self-crossing brings two non-neighbouring segments within O(h^2); a simple curve keeps them
// about its injectivity scale apart.
bool isSimple(const std::vector<Eigen::VectorXd>& orbit, double spacing) {
  const int n = static_cast<int>(orbit.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 4; j < n; ++j) {
      if (n - (j - i) < 4) continue;
      if (segmentDistance(orbit[static_cast<std::size_t>(i)], orbit[static_cast<std::size_t>((i + 1) % n)],
                          orbit[static_cast<std::size_t>(j)],
                          orbit[static_cast<std::size_t>((j + 1) % n)]) < 0.1 * spacing)
        return false;
    }
  return true;
}

bool symmetricMasses(const Chain& chain) {
  return chain.hingeMasses.isApprox(chain.hingeMasses.reverse().eval(), 1e-14) &&
         chain.rodMasses.isApprox(chain.rodMasses.reverse().eval(), 1e-14);
}

void classify(ClosedGeodesic& g) {
  const double trace = g.monodromy.trace(), det = g.monodromy.determinant();
  const std::complex<double> root = std::sqrt(std::complex<double>(trace * trace / 4 - det));
  g.eigenvalues << trace / 2 + root, trace / 2 - root;
  if (std::abs(std::abs(trace) - 2) < 1e-9) {
    g.stability = Stability::Parabolic;
  } else if (std::abs(trace) < 2) {
    g.stability = Stability::Elliptic;
    g.rotationNumber = std::acos(trace / 2) / (2 * kPi);
  } else {
    g.stability = Stability::Hyperbolic;
  }
}

}  // namespace

// The search's thresholds are in the orbit's own units: with absolute ones, a small orbit's chord sag exceeds the
// on-orbit tolerance (the orbit is listed again, as a twin), and Newton's velocity residual, whose rounding floor
// grows as 1 / size, never reaches its threshold (nothing is listed).
double orbitScale(double length) { return std::min(1.0, length / (2 * kPi)); }

std::optional<ClosedGeodesic> shootClosedGeodesic(const ConstrainedModel& model, Eigen::VectorXd q0, Eigen::VectorXd v0,
                                                  double period, const Eigen::MatrixXd* twist) {
  if (model.freedom() != 2) throw std::invalid_argument("shootClosedGeodesic: a 2-dimensional model is needed");
  const GeodesicFlow flow(model, 1e-12);
  if (!model.projectPosition(q0)) return std::nullopt;
  v0 = model.projectVelocity(q0, v0);
  v0 /= model.norm(v0);
  const double startPeriod = period;
  double previous = INFINITY;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Eigen::VectorXd n0 = across(model, q0, v0);
    Eigen::VectorXd dq = n0, dvs = Eigen::VectorXd::Zero(q0.size());
    model.projectVariation(q0, v0, dq, dvs);
    FlowState s{q0, v0, Eigen::MatrixXd(q0.size(), 2), Eigen::MatrixXd(q0.size(), 2)};
    s.dq.col(0) = n0;
    s.dq.col(1).setZero();
    s.dv.col(0) = dvs;
    s.dv.col(1) = n0;
    try {
      flow.advance(s, period);
    } catch (const std::runtime_error&) {
      return std::nullopt;
    }
    const Eigen::Index n = q0.size();
    Eigen::VectorXd residual(2 * n);
    const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
    const Eigen::MatrixXd& map = twist != nullptr ? *twist : identity;
    residual << s.q - map * q0, s.v - map * v0;
    // In the orbit's own units: on a small configuration sphere the velocity turns 1 / size times faster, and its
    // residual's rounding floor grows with it (about 1e-10 at size 1e-3, where the position closes to 1e-13).
    const double error = std::max(maxAbs(s.q - map * q0), orbitScale(period) * maxAbs(s.v - map * v0));
    if (twist != nullptr && (error <= 1e-13 || (error <= 1e-11 && error >= previous * 0.5)))
      return shootClosedGeodesic(model, q0, v0, 2 * period);  // the whole orbit, checked without the twist
    if (error <= 1e-13 || (error <= 1e-11 && error >= previous * 0.5)) {
      ClosedGeodesic g;
      g.length = period;
      g.point = q0;
      g.velocity = v0;
      g.positionClosure = maxAbs(s.q - q0);
      g.velocityClosure = maxAbs(s.v - v0);
      g.monodromy << model.inner(s.dq.col(0), n0), model.inner(s.dq.col(1), n0), model.inner(s.dv.col(0), n0),
          model.inner(s.dv.col(1), n0);
      classify(g);
      return g;
    }
    previous = error;
    Eigen::MatrixXd jac(2 * n, 3);
    jac.col(0) << s.dq.col(0) - map * n0, s.dv.col(0) - map * dvs;
    jac.col(1) << s.dq.col(1), s.dv.col(1) - map * n0;
    jac.col(2) << s.v, flow.acceleration(s.q, s.v);
    Eigen::Vector3d step = jac.colPivHouseholderQr().solve(-residual);
    const double size = orbitScale(period);  // an offset of 0.3 would leave a small configuration sphere
    const double scale =
        std::max({std::abs(step(0)) / (0.3 * size), std::abs(step(1)) / 0.3, std::abs(step(2)) / (0.3 * period), 1.0});
    step /= scale;
    q0 += step(0) * n0;
    if (!model.projectPosition(q0)) return std::nullopt;
    v0 = model.projectVelocity(q0, v0 + step(1) * n0);
    v0 /= model.norm(v0);
    period += step(2);
    if (!(period > 1e-3 * startPeriod) || !q0.allFinite()) return std::nullopt;
  }
  return std::nullopt;
}

std::vector<ClosedGeodesic> findClosedGeodesics(const ConstrainedModel& model, const Chain* chain,
                                                const std::vector<Eigen::VectorXd>& seedPoints,
                                                const PeriodicOptions& options,
                                                const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>>& starts,
                                                const std::vector<ClosedGeodesicGuess>& guesses) {
  const double maxLength = options.maxLength > 0 ? options.maxLength : 30.0;
  struct Seed {
    double residual;
    Eigen::VectorXd q, v;
    double period;
    bool twisted = false;
  };
  std::vector<Seed> seeds;
  const GeodesicFlow flow(model, 1e-9);
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> rays = starts;
  for (Eigen::VectorXd q : seedPoints) {
    model.projectPosition(q);
    const Eigen::MatrixXd basis = model.tangentBasis(q);
    for (int k = 0; k < options.directions; ++k) {
      const double angle = kPi * k / options.directions;
      rays.emplace_back(q, std::cos(angle) * basis.col(0) + std::sin(angle) * basis.col(1));
    }
  }
  constexpr std::size_t kMaxShots = 48;
  const auto tell = [&](std::size_t done, std::size_t total) {
    if (options.progress) options.progress(static_cast<long>(done), static_cast<long>(total));
  };
  {
    std::size_t raysDone = 0;
    for (auto [q, u] : rays) {
      tell(raysDone++, rays.size() + kMaxShots + guesses.size());
      stopIfCancelled(options.cancelled);
      model.projectPosition(q);
      u = model.projectVelocity(q, u);
      u /= model.norm(u);
      FlowState s{q, u, Eigen::MatrixXd(q.size(), 0), Eigen::MatrixXd(q.size(), 0)};
      double r2 = INFINITY, r1 = INFINITY, t1 = 0, w2 = INFINITY, w1 = INFINITY;
      bool left = false;
      const bool twisted = options.twist.size() > 0;
      const Eigen::VectorXd twistedQ = twisted ? Eigen::VectorXd(options.twist * q) : q;
      const Eigen::VectorXd twistedU = twisted ? Eigen::VectorXd(options.twist * u) : u;
      try {
        flow.advance(s, maxLength * 1.02, [&](double t, const FlowState& st) {
          if (options.cancelled && options.cancelled()) return false;  // a long ray answers within a step
          const double r0 = model.norm(st.q - q) + model.norm(st.v - u);
          if (r0 > 0.5) left = true;
          if (left && r1 < r2 && r1 <= r0 && r1 < 0.5) seeds.push_back({r1, q, u, t1});
          if (twisted) {  // returns to the mirror image, at half the period
            const double w0 = model.norm(st.q - twistedQ) + model.norm(st.v - twistedU);
            if (t <= maxLength / 2 && w1 < w2 && w1 <= w0 && w1 < 0.5) seeds.push_back({w1, q, u, t1, true});
            w2 = w1;
            w1 = w0;
          }
          r2 = r1;
          r1 = r0;
          t1 = t;
          return true;
        });
      } catch (const std::runtime_error&) {
      }
    }
    stopIfCancelled(options.cancelled);
  }
  // Half the shots go to the closest returns, half to the earliest: a long ray's recurrences near a long orbit
  // return closer than a short simple orbit's first return, and would take every shot (masses [0.01, 1, 100]
  // at L = 3.5 listed three closed geodesics of length 37-46 and none of the simple ones).
  const auto closer = [](const Seed& a, const Seed& b) { return a.residual < b.residual; };
  std::sort(seeds.begin(), seeds.end(), closer);
  if (seeds.size() > kMaxShots) {
    const auto half = seeds.begin() + kMaxShots / 2;
    std::stable_sort(half, seeds.end(), [](const Seed& a, const Seed& b) { return a.period < b.period; });
    seeds.resize(kMaxShots);
    std::stable_sort(seeds.begin(), seeds.end(), closer);
  }
  for (auto it = guesses.rbegin(); it != guesses.rend(); ++it)
    seeds.insert(seeds.begin(), {0.0, it->point, it->velocity, it->period});
  std::size_t shotsDone = 0;

  std::vector<ClosedGeodesic> found;
  std::vector<std::vector<Eigen::VectorXd>> orbits;
  const Eigen::MatrixXd u = model.mass().llt().matrixU();
  for (const Seed& seed : seeds) {
    tell(rays.size() + shotsDone++, rays.size() + seeds.size());
    stopIfCancelled(options.cancelled);
    bool covered = false;  // a seed on a known orbit with a multiple of its period: nothing new
    for (std::size_t i = 0; i < found.size() && !covered; ++i) {
      const double ratio = (seed.twisted ? 2 : 1) * seed.period / found[i].length;
      covered = std::abs(ratio - std::round(ratio)) < 0.02 && std::round(ratio) >= 1 &&
                distanceToOrbit(orbits[i], u * seed.q) < 1e-3 * orbitScale(found[i].length);
    }
    if (covered) continue;
    std::optional<ClosedGeodesic> g =
        shootClosedGeodesic(model, seed.q, seed.v, seed.period, seed.twisted ? &options.twist : nullptr);
    if (!g || g->length > maxLength * (1 + 1e-9)) continue;
    bool known = false;
    for (std::size_t i = 0; i < found.size() && !known; ++i) {
      const double ratio = g->length / found[i].length;
      if (std::abs(ratio - std::round(ratio)) < 1e-7 && std::round(ratio) >= 1 &&
          distanceToOrbit(orbits[i], u * g->point) < onOrbitTolerance(orbits[i], found[i].length))
        known = true;  // the same one, or a multiple cover of it
      else if (std::abs(1 / ratio - std::round(1 / ratio)) < 1e-7) {
        std::vector<Eigen::VectorXd> orbit = sampledOrbit(model, g->point, g->velocity, g->length);
        if (distanceToOrbit(orbit, u * found[i].point) < onOrbitTolerance(orbit, g->length)) {
          found[i] = *g;  // a multiple cover was found first: keep the primitive one
          orbits[i] = std::move(orbit);
          known = true;
        }
      }
    }
    if (known) continue;
    orbits.push_back(sampledOrbit(model, g->point, g->velocity, g->length));
    g->simple = isSimple(orbits.back(), g->length / kOrbitSamples);
    found.push_back(*g);
  }
  tell(rays.size() + seeds.size(), rays.size() + seeds.size());
  if (chain != nullptr) {
    for (std::size_t i = 0; i < found.size(); ++i) {
      for (const ChainSymmetry symmetry : kindsOf(kChainSymmetries)) {
        if (symmetry != ChainSymmetry::Mirror && !symmetricMasses(*chain)) continue;
        const Eigen::VectorXd image = applyChainSymmetry(*chain, symmetry, found[i].point);
        if (distanceToOrbit(orbits[i], u * image) > onOrbitTolerance(orbits[i], found[i].length)) continue;
        bool fixed = true;
        for (int k = 0; k < kOrbitSamples; k += kOrbitSamples / 16) {
          const Eigen::VectorXd q = u.triangularView<Eigen::Upper>().solve(orbits[i][static_cast<std::size_t>(k)]);
          if (maxAbs(applyChainSymmetry(*chain, symmetry, q) - q) > 1e-6) fixed = false;
        }
        found[i].symmetries.push_back({symmetry, fixed});
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const ClosedGeodesic& a, const ClosedGeodesic& b) {
    if (a.simple != b.simple) return a.simple;
    return a.length < b.length;
  });
  return found;
}

Eigen::VectorXd applyChainSymmetry(const Chain& chain, ChainSymmetry symmetry, const Eigen::VectorXd& q) {
  const int hinges = chain.hingeCount();
  Eigen::VectorXd out(q.size());
  for (int k = 0; k < hinges; ++k) {
    if (symmetry == ChainSymmetry::Mirror) {
      out(2 * k) = q(2 * k);
      out(2 * k + 1) = -q(2 * k + 1);
    } else {
      const int other = hinges - 1 - k;  // p_k <- p_(n-k)
      out(2 * k) = chain.baseLength - q(2 * other);
      out(2 * k + 1) = (symmetry == ChainSymmetry::EndSwap ? 1.0 : -1.0) * q(2 * other + 1);
    }
  }
  return out;
}

std::vector<ClosedGeodesic> chainClosedGeodesics(const Chain& chain, const PeriodicOptions& options) {
  if (chain.rods != 4 || chain.isSlack())
    throw std::invalid_argument("closed geodesics of the configuration sphere need 4 rods and n - 2 < L < n");
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  // Seeds: the chain's symmetric geodesic candidates as starts (the end swap's fixed curve along itself; the
  // shortest motion between the half turn's fixed points, both ways), and fans from two chart points.
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> starts;
  std::vector<ClosedGeodesicGuess> guesses;
  std::vector<Connection> betweenPoles;
  double scale = 0;  // a length the simple ones are expected near, for the default bound
  if (symmetricMasses(chain)) {
    const double w = kPi / 4, h = 1e-6;
    starts.emplace_back(endSwapFixedPoint(chain, w),
                        (endSwapFixedPoint(chain, w + h) - endSwapFixedPoint(chain, w - h)) / (2 * h));
    // Every geodesic between the half turn's two fixed points closes up, continued by its image under the half
    // turn, at twice its length: the motions between them (connect.hpp, shooting only) are guesses.
    const auto poles = halfTurnFixedPoints(chain);
    if (const auto c = directConnection(model, &chain, poles[0], poles[1])) {
      scale = 2 * c->length;
      ConnectOptions connect;
      connect.maxLength = options.maxLength > 0 ? options.maxLength / 2 : 1.25 * scale;
      connect.discreteRoute = false;
      connect.directions = 24;
      connect.cancelled = options.cancelled;
      connect.progress = options.progress;
      betweenPoles = findConnections(model, nullptr, poles[0], poles[1], connect);
      for (const Connection& between : betweenPoles)
        guesses.push_back({poles[0], between.velocity / between.length, 2 * between.length});
    }
  }
  std::vector<Eigen::VectorXd> points;
  for (double t : {0.3, 2.0}) {
    Eigen::VectorXd c(2);
    c << 0.4, t;
    points.push_back(ConstrainedModel::stack(hingePositions(chain, c)));
  }
  if (!symmetricMasses(chain))  // no symmetric guesses: fan from more points
    for (const auto& [phi, t] : {std::pair{0.0, 0.0}, {1.2, 1.0}, {-0.8, -1.2}, {0.0, 1.57}}) {
      Eigen::VectorXd c(2);
      c << phi, t;
      points.push_back(ConstrainedModel::stack(hingePositions(chain, c)));
    }
  // Without the symmetric guesses, the end swap's fixed set (a closed curve round the sphere, a geodesic only
  // for symmetric masses) gives the size: a fixed bound would let every ray wind hundreds of times round a
  // small sphere near L = n, and seed from each multiple cover.
  if (scale == 0) scale = closedCurveLength(model, [&](double w) { return endSwapFixedPoint(chain, w); });
  PeriodicOptions bounded = options;
  if (bounded.maxLength <= 0) bounded.maxLength = 2.5 * scale;
  if (!symmetricMasses(chain)) {  // the mirror is still an isometry: seek the closed geodesics it maps to themselves
    bounded.twist = Eigen::MatrixXd::Identity(6, 6);
    for (int k = 1; k < 6; k += 2) bounded.twist(k, k) = -1;
  }
  // The symmetric guesses first; fans only when they do not give the three simple ones Lyusternik and
  // Schnirelmann promise (always for asymmetric masses).
  std::vector<ClosedGeodesic> found = findClosedGeodesics(model, &chain, {}, bounded, starts, guesses);
  if (std::count_if(found.begin(), found.end(), [](const ClosedGeodesic& g) { return g.simple; }) < 3 ||
      options.maxLength > 0)
    found = findClosedGeodesics(model, &chain, points, bounded, starts, guesses);

  // Route 2.
  if (symmetricMasses(chain)) {
    const double fixedSet = closedCurveLength(model, [&](double w) { return endSwapFixedPoint(chain, w); });
    for (ClosedGeodesic& g : found)
      if (g.fixedBy(ChainSymmetry::EndSwap) && std::abs(g.length - fixedSet) < 1e-6) {
        g.independentLength = fixedSet;
        g.independentRoute = "fixed set of the end swap, polygons extrapolated";
      }
    const auto poles = halfTurnFixedPoints(chain);
    const Eigen::MatrixXd u = model.mass().llt().matrixU();
    auto throughPoles = [&](const ClosedGeodesic& g) {
      const std::vector<Eigen::VectorXd> orbit = sampledOrbit(model, g.point, g.velocity, g.length);
      return distanceToOrbit(orbit, u * poles[0]) < onOrbitTolerance(orbit, g.length);
    };
    std::vector<DiscreteGeodesic> halves;
    for (const auto& arc : sphereArcPaths(chain, poles[0], poles[1], 5 * kPathSamples))
      if (const auto half = discreteGeodesic(model, arc, DiscreteSeed::SphereArc)) halves.push_back(*half);
    for (ClosedGeodesic& g : found) {
      if (g.independentLength || !throughPoles(g)) continue;
      for (const DiscreteGeodesic& half : halves)
        if (std::abs(g.length - 2 * half.length) < 1e-6) {
          g.independentLength = 2 * half.length;
          g.independentRoute = "twice the discrete geodesic between the half turn's fixed points";
        }
      if (g.independentLength) continue;
      // Not reached from the arcs: the discrete route from route 1's path between the poles.
      std::optional<DiscreteGeodesic> discrete;
      for (const Connection& between : betweenPoles) {
        if (discrete || std::abs(g.length - 2 * between.length) > 1e-6) continue;
        const int intervals = kPathSamples * std::max(5, static_cast<int>(std::ceil(2 * between.length)));
        discrete = discreteGeodesic(model, shootingPath(model, poles[0], between.velocity, intervals),
                                    DiscreteSeed::ShootingPath);
      }
      if (discrete && std::abs(g.length - 2 * discrete->length) < 1e-6) {
        g.independentLength = 2 * discrete->length;
        g.independentRoute =
            "twice the discrete geodesic between the half turn's fixed points (seeded by the shooting path)";
      }
    }
  }
  return found;
}

std::optional<std::string> periodicSearchRefusal(const Chain& chain) {
  if (chain.rods != 4 || chain.isSlack()) return std::nullopt;
  const Eigen::VectorXd masses =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(ConstrainedModel::fromChain(chain).mass(), Eigen::EigenvaluesOnly)
          .eigenvalues();
  const double ratio = masses.maxCoeff() / masses.minCoeff();
  if (ratio <= limits::kMaxPeriodicMassRatio * (1 + 1e-9)) return std::nullopt;
  return "hinge and rod masses " + shortest(ratio) + " apart (the kinetic mass matrix's condition number): the " +
         "closed-geodesic search integrates explicitly, its light hinge swings sqrt(" + shortest(ratio) +
         ") times faster than the heavy one moves, and it would run for many minutes to hours; expected masses at " +
         "most " + shortest(limits::kMaxPeriodicMassRatio) + " apart";
}

std::vector<ClosedGeodesic> closedGeodesicsOf(const Chain& chain, double maxLength, bool (*cancelled)(),
                                              const SearchProgress& progress) {
  if (chain.rods == 3) return {circleClosedGeodesic(chain)};
  if (const auto refusal = periodicSearchRefusal(chain)) throw std::invalid_argument(*refusal);
  PeriodicOptions options;
  options.maxLength = maxLength;
  options.cancelled = cancelled;
  options.progress = progress;
  return chainClosedGeodesics(chain, options);
}

}  // namespace sl

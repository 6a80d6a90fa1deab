#include "inverse/holonomy.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "geometry/curvature.hpp"
#include "inverse/connect.hpp"
#include "inverse/geodesic_flow.hpp"
#include "inverse/parallel_transport.hpp"
#include "linkage/chain_constants.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"

namespace sl {

namespace {

constexpr double kPi = std::numbers::pi;
// The enclosed curvature's quadrature (coneCurvature): a Gauss-Legendre rule composed over 1, 2 and 4 parts of each
// piece of the loop until two results agree, and along each chord adaptive Gauss-Kronrod (15 points, at most 8
// bisections, to 1e-12). Near L = n - 2 the curvature gathers into narrow peaks where the chain folds flat: one fixed
// rule missed 4e-4 of the equator's 2 pi at L = 2.05. The effort is bounded; what it does not reach, the holonomy's
// own check reports.
constexpr int kQuadratureNodes = 32;
// The swept curvature drawn against time (Holonomy::Sample::swept): this rule on each interval between samples.
constexpr int kSweptNodes = 8;
constexpr double kChordTolerance = 1e-12;
constexpr unsigned kChordDepth = 8;
constexpr double kPieceTolerance = 1e-12;
constexpr int kMaxPieceParts = 4;
constexpr double kTransportTolerance = 1e-13;

struct QuadratureRule {
  std::vector<double> nodes, weights;  // on [0, 1]
};

// Boost.Math's Gauss-Legendre rule of `Points` nodes moved from [-1, 1] to [0, 1].
template <int Points>
const QuadratureRule& gaussRule() {
  static const QuadratureRule rule = [] {
    using Gauss = boost::math::quadrature::gauss<double, Points>;
    QuadratureRule r;
    const auto& abscissa = Gauss::abscissa();
    const auto& weights = Gauss::weights();
    std::vector<std::pair<double, double>> rule;  // ascending nodes: the path is integrated from one to the next
    for (std::size_t i = 0; i < abscissa.size(); ++i)
      for (double sign : {-1.0, 1.0}) {
        if (abscissa[i] == 0.0 && sign > 0) continue;
        rule.emplace_back(0.5 * (1.0 + sign * abscissa[i]), 0.5 * weights[i]);
      }
    std::sort(rule.begin(), rule.end());
    for (const auto& [node, weight] : rule) {
      r.nodes.push_back(node);
      r.weights.push_back(weight);
    }
    return r;
  }();
  return rule;
}

// The rule on each of `parts` equal parts of [0, 1], in ascending order.
QuadratureRule composed(const QuadratureRule& rule, int parts) {
  QuadratureRule whole;
  for (int part = 0; part < parts; ++part)
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
      whole.nodes.push_back((part + rule.nodes[j]) / parts);
      whole.weights.push_back(rule.weights[j] / parts);
    }
  return whole;
}

// A g-orthonormal frame of the tangent plane at x in the orientation of the outward normal, in both forms.
struct OrientedFrame {
  Eigen::VectorXd sphere[2];   // sphere velocities
  Eigen::VectorXd ambient[2];  // stacked hinge velocities
};

// The frame whose first vector is the path's left normal there (g-perpendicular to its velocity, a sphere
// velocity): the vector the loop carries starts pointing into the region the loop turns round, and drawn along the
// sides it never lies on them.
OrientedFrame orientedFrame(const Chain& chain, const Eigen::VectorXd& x, const Eigen::VectorXd& pathVelocity) {
  const std::vector<Eigen::VectorXd> along = orthonormalTangentFrame(chain, x, pathVelocity, 2);
  const double side = Eigen::Vector3d(x).dot(Eigen::Vector3d(along[0]).cross(Eigen::Vector3d(along[1])));
  std::vector<Eigen::VectorXd> basis =
      orthonormalTangentFrame(chain, x, side < 0 ? Eigen::VectorXd(-along[1]) : along[1]);
  const Eigen::Vector3d p = x, a = basis[0], b = basis[1];
  if (p.dot(a.cross(b)) < 0) basis[1] = -basis[1];
  OrientedFrame frame;
  for (int i = 0; i < 2; ++i) {
    frame.sphere[i] = basis[static_cast<size_t>(i)];
    frame.ambient[i] = ConstrainedModel::stack(hingeVelocitiesOnSphere(chain, x, frame.sphere[i]));
  }
  return frame;
}

// The angle of w in the frame (w tangent at the frame's point, given as a stacked hinge velocity).
double angleInFrame(const ConstrainedModel& model, const OrientedFrame& frame, const Eigen::VectorXd& w) {
  return std::atan2(model.inner(w, frame.ambient[1]), model.inner(w, frame.ambient[0]));
}

// The turning angle from direction a to direction b in the frame.
double turningAngle(const ConstrainedModel& model, const OrientedFrame& frame, const Eigen::VectorXd& a,
                    const Eigen::VectorXd& b) {
  return angleDifference(angleInFrame(model, frame, b), angleInFrame(model, frame, a));
}

// A piece of a loop at ascending parameters s in [0, 1]: its points and their derivatives d/ds.
using PieceSampler = std::function<void(const std::vector<double>& s, std::vector<Eigen::Vector3d>& points,
                                        std::vector<Eigen::Vector3d>& derivatives)>;

// The geodesic from `start` followed for `duration`, as a piece of a loop at parameters s in [0, 1].
PieceSampler geodesicPiece(const Chain& chain, const GeodesicFlow& flow, const FlowState& start, double duration) {
  return [&chain, &flow, start, duration](const std::vector<double>& nodes, std::vector<Eigen::Vector3d>& points,
                                          std::vector<Eigen::Vector3d>& derivatives) {
    FlowState along = start;
    double at = 0;
    for (double node : nodes) {
      flow.advance(along, (node - at) * duration);
      at = node;
      const Eigen::VectorXd p = spherePointFromHinges(chain, ConstrainedModel::unstack(along.q));
      points.emplace_back(p);
      derivatives.emplace_back(duration *
                               sphereVelocityFromHingeVelocities(chain, p, ConstrainedModel::unstack(along.v)));
    }
  };
}

// The cone's integrand at one point of the loop and its derivative d/ds there:
// det[A, gamma, gamma'] * (integral of K dA along the chord from A to gamma, per unit det).
double coneIntegrand(const ConfigurationSurface& surface, const Eigen::Vector3d& apex, const Eigen::Vector3d& point,
                     const Eigen::Vector3d& derivative) {
  const double angle = std::atan2(apex.cross(point).norm(), apex.dot(point));
  if (!(angle < 3.0))
    throw std::invalid_argument("holonomy: the loop passes opposite its apex; split it into smaller loops");
  // y = (1 - u) A + u gamma: det[x, x_u, x_s] = u det[A, gamma, gamma'] / |y|^3 for x = y / |y|.
  const auto along = [&](double u) {
    const Eigen::Vector3d y = (1.0 - u) * apex + u * point;
    const double r = y.norm();
    const SecondFundamentalForm form = surface.secondFundamentalFormAt(y / r);
    return gaussianCurvature(form) * areaDensity(form) * u / (r * r * r);
  };
  return apex.dot(point.cross(derivative)) *
         boost::math::quadrature::gauss_kronrod<double, 15>::integrate(along, 0.0, 1.0, kChordDepth, kChordTolerance);
}

// Integral of K dA over the cone of chords from the apex to one piece of the loop. Along each chord adaptive
// Gauss-Kronrod; along the piece the Gauss-Legendre rule composed over 1, 2 and 4 equal parts until two
// successive results agree to kPieceTolerance (near L = n - 2 the curvature gathers into peaks a single rule misses).
double coneCurvature(const ConfigurationSurface& surface, const Eigen::Vector3d& apex, const PieceSampler& sample) {
  const QuadratureRule& rule = gaussRule<kQuadratureNodes>();
  double previous = 0;
  for (int parts = 1;; parts *= 2) {
    const QuadratureRule composite = composed(rule, parts);
    std::vector<Eigen::Vector3d> points, derivatives;
    sample(composite.nodes, points, derivatives);
    double total = 0;
    for (std::size_t j = 0; j < composite.nodes.size(); ++j)
      total += composite.weights[j] * coneIntegrand(surface, apex, points[j], derivatives[j]);
    if (parts > 1 && std::abs(total - previous) <= kPieceTolerance * std::max(1.0, std::abs(total))) return total;
    if (parts >= kMaxPieceParts) return total;  // unconverged: the holonomy's own check will say so
    previous = total;
  }
}

// The cone's curvature from the piece's start to each of `intervals` equal steps of it (kSweptNodes on each step):
// entry k is the integral over [0, (k + 1) / intervals].
std::vector<double> sweptCurvature(const ConfigurationSurface& surface, const Eigen::Vector3d& apex,
                                   const PieceSampler& sample, int intervals) {
  const QuadratureRule& rule = gaussRule<kSweptNodes>();
  const QuadratureRule composite = composed(rule, intervals);
  std::vector<Eigen::Vector3d> points, derivatives;
  sample(composite.nodes, points, derivatives);
  std::vector<double> swept;
  double total = 0;
  for (std::size_t j = 0; j < composite.nodes.size(); ++j) {
    total += composite.weights[j] * coneIntegrand(surface, apex, points[j], derivatives[j]);
    if ((j + 1) % rule.nodes.size() == 0) swept.push_back(total);
  }
  return swept;
}

Eigen::Vector3d apexOf(const std::vector<Eigen::VectorXd>& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::VectorXd& p : points) sum += Eigen::Vector3d(p);
  if (sum.norm() < 1e-6)
    throw std::invalid_argument(
        "holonomy: the loop's corners balance round the sphere's centre; "
        "split it into smaller loops");
  return sum.normalized();
}

void requireFourRods(const Chain& chain) {
  if (chain.rods != 4)
    throw std::invalid_argument("holonomy: computed for 4 rods (a surface, S^2); found " + std::to_string(chain.rods) +
                                " rods");
}

}  // namespace

double angleDifference(double x, double y) {
  double d = std::remainder(x - y, 2.0 * kPi);
  if (d <= -kPi) d += 2.0 * kPi;
  return d;
}

double Holonomy::routeDifference() const { return angleDifference(angle, chartAngle); }
double Holonomy::curvatureDifference() const { return angleDifference(angle, enclosedCurvature); }
std::optional<double> Holonomy::excessDifference() const {
  if (!angleExcess) return std::nullopt;
  return angleDifference(angle, *angleExcess);
}

Holonomy polygonHolonomy(const Chain& chain, const std::vector<Eigen::VectorXd>& corners, bool (*cancelled)(),
                         int samplesPerPiece) {
  requireFourRods(chain);
  if (corners.size() < 3) throw std::invalid_argument("holonomy: expected at least 3 corners");
  const ChainConstants bound(chain);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const std::size_t m = corners.size();
  std::vector<Eigen::VectorXd> x(m), q(m), velocity(m);
  for (std::size_t i = 0; i < m; ++i) {
    x[i] = corners[i].normalized();
    q[i] = ConstrainedModel::stack(hingePositionsAt(chain, x[i]));
  }
  Holonomy h;
  for (std::size_t i = 0; i < m; ++i) {
    stopIfCancelled(cancelled);
    const std::size_t next = (i + 1) % m;
    if (sameShape(model, q[i], q[next]))
      throw std::invalid_argument("holonomy: corners " + std::to_string(i + 1) + " and " + std::to_string(next + 1) +
                                  " are the same shape");
    const std::optional<Connection> piece = directConnection(model, &chain, q[i], q[next]);
    if (!piece)
      throw std::runtime_error("holonomy: no motion found from corner " + std::to_string(i + 1) + " to corner " +
                               std::to_string(next + 1));
    velocity[i] = piece->velocity;
    h.pieceLengths.push_back(piece->length);
    h.length += piece->length;
  }
  stopIfCancelled(cancelled);
  std::vector<Eigen::VectorXd> xdot(m);  // each piece's start velocity, as a sphere velocity
  for (std::size_t i = 0; i < m; ++i)
    xdot[i] = sphereVelocityFromHingeVelocities(chain, x[i], ConstrainedModel::unstack(velocity[i]));
  const OrientedFrame start = orientedFrame(chain, x[0], xdot[0]);

  // Ambient route, and each piece's arriving velocity and its points at the quadrature nodes.
  const GeodesicFlow flow(model, kTransportTolerance);
  const ConfigurationSurface surface(chain);
  const Eigen::Vector3d apex = apexOf(x);
  h.apex = apex;
  Eigen::VectorXd w = start.ambient[0];
  std::vector<Eigen::VectorXd> arriving(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t next = (i + 1) % m;
    const Eigen::VectorXd carried = w;  // as the previous piece brought it
    FlowState s{q[i], velocity[i], Eigen::MatrixXd(q[i].size(), 0), Eigen::MatrixXd(q[i].size(), 0), w};
    flow.advance(s, 1.0);
    arriving[i] = s.v;
    w = model.projectVelocity(q[next], s.transported.col(0));
    // The piece at given parameters, for the enclosed curvature.
    const PieceSampler piece = geodesicPiece(
        chain, flow, {q[i], velocity[i], Eigen::MatrixXd(q[i].size(), 0), Eigen::MatrixXd(q[i].size(), 0)}, 1.0);
    if (samplesPerPiece > 0) {  // a separate pass, so that the angle does not depend on how the loop is drawn
      FlowState shown{q[i], velocity[i], Eigen::MatrixXd(q[i].size(), 0), Eigen::MatrixXd(q[i].size(), 0), carried};
      const std::vector<double> swept = sweptCurvature(surface, apex, piece, samplesPerPiece);
      for (int k = 0; k <= samplesPerPiece; ++k) {
        if (k > 0) flow.advance(shown, 1.0 / samplesPerPiece);
        const Eigen::VectorXd p = spherePointFromHinges(chain, ConstrainedModel::unstack(shown.q));
        h.samples.push_back(
            {p, sphereVelocityFromHingeVelocities(chain, p, ConstrainedModel::unstack(shown.v)),
             sphereVelocityFromHingeVelocities(chain, p, ConstrainedModel::unstack(shown.transported.col(0))), i,
             double(k) / samplesPerPiece, k == 0 ? 0.0 : swept[std::size_t(k - 1)]});
      }
    }
    h.enclosedCurvature += coneCurvature(surface, apex, piece);
  }
  h.angle = angleInFrame(model, start, w);

  // Chart route.
  const ChristoffelField gamma = chainChristoffelField(bound);
  Eigen::VectorXd ws = start.sphere[0];
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t next = (i + 1) % m;
    const ChartTransport t = transportAlongGeodesicInCharts(gamma, x[i], xdot[i], 1.0, {ws}, kTransportTolerance);
    ws = t.vectors[0] - t.vectors[0].dot(x[next]) * x[next];
    h.chartChanges += t.chartChanges;
  }
  h.chartAngle = angleInFrame(model, start, ConstrainedModel::stack(hingeVelocitiesOnSphere(chain, x[0], ws)));

  // Gauss-Bonnet for a geodesic polygon: the region to the left has integral K dA = 2 pi - sum of turning angles.
  double turning = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const double e = turningAngle(model, i == 0 ? start : orientedFrame(chain, x[i], xdot[i]),
                                  arriving[(i + m - 1) % m], velocity[i]);
    h.interiorAngles.push_back(kPi - e);
    turning += e;
  }
  h.angleExcess = 2.0 * kPi - turning;
  return h;
}

Holonomy closedGeodesicHolonomy(const Chain& chain, const ClosedGeodesic& geodesic) {
  requireFourRods(chain);
  if (!(geodesic.length > 0)) throw std::invalid_argument("holonomy: a closed geodesic of positive length expected");
  constexpr int kPieces = 8;  // the cone's quadrature piece by piece (a closed geodesic goes round the sphere)
  const ChainConstants bound(chain);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const GeodesicFlow flow(model, kTransportTolerance);
  const Eigen::VectorXd& q0 = geodesic.point;
  const double piece = geodesic.length / kPieces;
  // Each piece's start, and the apex: the mean of the unit left normals x cross x' / |x cross x'| along the loop.
  std::vector<FlowState> starts;
  Eigen::Vector3d apex = Eigen::Vector3d::Zero();
  FlowState along{q0, geodesic.velocity, Eigen::MatrixXd(q0.size(), 0), Eigen::MatrixXd(q0.size(), 0)};
  for (int k = 0; k < kPieces; ++k) {
    starts.push_back(along);
    for (int j = 0; j < 4; ++j) {
      const Eigen::Vector3d x = spherePointFromHinges(chain, ConstrainedModel::unstack(along.q));
      const Eigen::Vector3d xdot = sphereVelocityFromHingeVelocities(chain, x, ConstrainedModel::unstack(along.v));
      apex += x.cross(xdot).normalized();
      flow.advance(along, piece / 4);
    }
  }
  if (!(apex.norm() > 1e-6))
    throw std::invalid_argument(
        "holonomy: this closed geodesic has no side to call its inside (it balances round "
        "the sphere's centre)");
  apex.normalize();
  const Eigen::VectorXd x0 = spherePointFromHinges(chain, ConstrainedModel::unstack(q0));
  const Eigen::VectorXd xdot0 =
      sphereVelocityFromHingeVelocities(chain, x0, ConstrainedModel::unstack(geodesic.velocity));
  const OrientedFrame start = orientedFrame(chain, x0, xdot0);
  Holonomy h;
  h.length = geodesic.length;
  h.apex = apex;
  // Ambient route: the vector rides in the flow; back at the start it is projected onto its tangent plane (the loop
  // closes to the periodic search's closure).
  FlowState carried{q0, geodesic.velocity, Eigen::MatrixXd(q0.size(), 0), Eigen::MatrixXd(q0.size(), 0),
                    start.ambient[0]};
  flow.advance(carried, geodesic.length);
  h.angle = angleInFrame(model, start, model.projectVelocity(q0, carried.transported.col(0)));
  // Chart route.
  const ChartTransport t = transportAlongGeodesicInCharts(chainChristoffelField(bound), x0, xdot0, geodesic.length,
                                                          {start.sphere[0]}, kTransportTolerance);
  const Eigen::VectorXd ws = t.vectors[0] - t.vectors[0].dot(x0) * x0;
  h.chartAngle = angleInFrame(model, start, ConstrainedModel::stack(hingeVelocitiesOnSphere(chain, x0, ws)));
  h.chartChanges = t.chartChanges;
  // The curvature to the left, over the cone from the apex, piece by piece.
  const ConfigurationSurface surface(chain);
  for (const FlowState& from : starts)
    h.enclosedCurvature += coneCurvature(surface, apex, geodesicPiece(chain, flow, from, piece));
  return h;
}

Holonomy latitudeHolonomy(const Chain& chain, double phi) {
  requireFourRods(chain);
  if (!(std::abs(phi) < kPi / 2)) throw std::invalid_argument("holonomy: expected a latitude phi with |phi| < pi/2");
  const ChainConstants bound(chain);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const double c = std::cos(phi), s = std::sin(phi);
  const PathPoint sphere = [c, s](double arc, Eigen::VectorXd& x, Eigen::VectorXd& xdot) {
    const double t = arc - kPi;
    x = Eigen::Vector3d(c * std::cos(t), c * std::sin(t), s);
    xdot = Eigen::Vector3d(-c * std::sin(t), c * std::cos(t), 0.0);
  };
  const PathPoint ambient = [&](double arc, Eigen::VectorXd& q, Eigen::VectorXd& qdot) {
    Eigen::VectorXd x, xdot;
    sphere(arc, x, xdot);
    q = ConstrainedModel::stack(hingePositionsAt(chain, x));
    qdot = ConstrainedModel::stack(hingeVelocitiesOnSphere(chain, x, xdot));
  };
  Eigen::VectorXd x0, xdot0;
  sphere(0.0, x0, xdot0);
  const OrientedFrame start = orientedFrame(chain, x0, xdot0);
  Holonomy h;
  const Eigen::MatrixXd w = transportAlongPathAmbient(model, ambient, 2.0 * kPi, start.ambient[0], kTransportTolerance);
  h.angle = angleInFrame(model, start, w.col(0));
  const std::vector<Eigen::VectorXd> ws = transportAlongPathInCharts(chainChristoffelField(bound), sphere, 2.0 * kPi,
                                                                     {start.sphere[0]}, kTransportTolerance);
  h.chartAngle = angleInFrame(model, start, ConstrainedModel::stack(hingeVelocitiesOnSphere(chain, x0, ws[0])));
  // The cap's curvature over the cone from the pole on the latitude's side (the loop never passes opposite its
  // apex), in four quarters; and the loop's length.
  const ConfigurationSurface surface(chain);
  const Eigen::Vector3d pole(0, 0, phi < 0 ? -1.0 : 1.0);
  const QuadratureRule& rule = gaussRule<kQuadratureNodes>();
  for (int quarter = 0; quarter < 4; ++quarter) {
    const PieceSampler piece = [&](const std::vector<double>& nodes, std::vector<Eigen::Vector3d>& points,
                                   std::vector<Eigen::Vector3d>& derivatives) {
      for (double node : nodes) {
        Eigen::VectorXd x, xdot;
        sphere((quarter + node) * kPi / 2, x, xdot);
        points.emplace_back(x);
        derivatives.emplace_back(xdot * (kPi / 2));
      }
    };
    h.enclosedCurvature += coneCurvature(surface, pole, piece);
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
      Eigen::VectorXd q, qdot;
      ambient((quarter + rule.nodes[j]) * kPi / 2, q, qdot);
      h.length += rule.weights[j] * (kPi / 2) * model.norm(qdot);
    }
  }
  return h;
}

}  // namespace sl

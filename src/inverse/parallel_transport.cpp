#include "inverse/parallel_transport.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "inverse/controlled_steps.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/exact_fields.hpp"

namespace sl {

namespace {

using Packed = std::vector<double>;

// A chart is given up between steps once another is twice as well conditioned at the point: no chart is ever used
// near its singular set, and no chart change is made back and forth for nothing.
constexpr double kChartChangeRatio = 0.5;

// The chart side's state: a chart of the atlas and the coordinates of the point in it.
struct Chart {
  int index = 0;
  std::vector<int> axes;

  explicit Chart(const Eigen::VectorXd& x) { choose(x); }
  void choose(const Eigen::VectorXd& x) {
    index = bestSphereChart(x);
    axes = sphereChartAxes(static_cast<int>(x.size()), index);
  }
  bool shouldChange(const Eigen::VectorXd& x) const {
    return sphereChartRegularity(x, index) < kChartChangeRatio * sphereChartRegularity(x, bestSphereChart(x));
  }
};

// Gamma(u, w)^i = Gamma^i_jk u^j w^k.
Eigen::VectorXd contract(const std::vector<Eigen::MatrixXd>& gamma, const Eigen::VectorXd& u,
                         const Eigen::VectorXd& w) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(gamma.size()));
  for (Eigen::Index i = 0; i < out.size(); ++i) out(i) = u.dot(gamma[static_cast<size_t>(i)] * w);
  return out;
}

void requireTangent(const Eigen::VectorXd& x, const std::vector<Eigen::VectorXd>& vectors, const char* what) {
  for (const Eigen::VectorXd& w : vectors)
    if (w.size() != x.size() || !w.allFinite())
      throw std::invalid_argument(std::string(what) + ": expected vectors of " + std::to_string(x.size()) +
                                  " finite numbers");
}

}  // namespace

ChristoffelField chainChristoffelField(const ChainConstants& bound) {
  return [&bound](const std::vector<int>& axes, const Eigen::VectorXd& coords) {
    return christoffelSymbols(bound, axes, coords);
  };
}

ChartTransport transportAlongGeodesicInCharts(const ChristoffelField& gamma, const Eigen::VectorXd& point,
                                              const Eigen::VectorXd& velocity, double duration,
                                              const std::vector<Eigen::VectorXd>& vectors, double tolerance) {
  requireTangent(point, vectors, "parallel transport");
  const Eigen::Index k = point.size() - 1, m = static_cast<Eigen::Index>(vectors.size());
  ChartTransport out{point.normalized(), velocity, vectors, 0};
  Chart chart(out.point);
  // y = (c, c', W_1, ..., W_m) in the chart.
  auto load = [&](Packed& y) {
    y.assign(static_cast<size_t>(k * (2 + m)), 0.0);
    Eigen::Map<Eigen::VectorXd> c(y.data(), k), r(y.data() + k, k);
    c = coordinatesInChart(chart.axes, out.point);
    r = ratesInChart(chart.axes, c, out.velocity);
    for (Eigen::Index j = 0; j < m; ++j)
      Eigen::Map<Eigen::VectorXd>(y.data() + (2 + j) * k, k) = ratesInChart(chart.axes, c, out.vectors[size_t(j)]);
  };
  auto store = [&](const Packed& y) {
    const Eigen::Map<const Eigen::VectorXd> c(y.data(), k), r(y.data() + k, k);
    out.point = spherePointInChart<double>(chart.axes, c);
    out.velocity = sphereVelocityInChart(chart.axes, c, r);
    for (Eigen::Index j = 0; j < m; ++j)
      out.vectors[size_t(j)] =
          sphereVelocityInChart(chart.axes, c, Eigen::Map<const Eigen::VectorXd>(y.data() + (2 + j) * k, k));
  };
  auto system = [&](const Packed& y, Packed& dydt, double) {
    const Eigen::Map<const Eigen::VectorXd> c(y.data(), k), r(y.data() + k, k);
    const std::vector<Eigen::MatrixXd> symbols = gamma(chart.axes, c);
    dydt.resize(y.size());
    Eigen::Map<Eigen::VectorXd>(dydt.data(), k) = r;
    Eigen::Map<Eigen::VectorXd>(dydt.data() + k, k) = -contract(symbols, r, r);
    for (Eigen::Index j = 0; j < m; ++j)
      Eigen::Map<Eigen::VectorXd>(dydt.data() + (2 + j) * k, k) =
          -contract(symbols, r, Eigen::Map<const Eigen::VectorXd>(y.data() + (2 + j) * k, k));
  };
  Packed y;
  load(y);
  integrateControlled(
      system, y, duration, tolerance,
      [&](double, Packed& state) {
        const Eigen::VectorXd x =
            spherePointInChart<double>(chart.axes, Eigen::Map<const Eigen::VectorXd>(state.data(), k));
        if (!chart.shouldChange(x)) return true;
        store(state);
        chart.choose(out.point);
        ++out.chartChanges;
        load(state);
        return true;
      },
      "parallel transport (charts)");
  store(y);
  return out;
}

std::vector<Eigen::VectorXd> transportAlongPathInCharts(const ChristoffelField& gamma, const PathPoint& path,
                                                        double length, const std::vector<Eigen::VectorXd>& vectors,
                                                        double tolerance) {
  Eigen::VectorXd x, xdot;
  path(0.0, x, xdot);
  requireTangent(x, vectors, "parallel transport");
  const Eigen::Index k = x.size() - 1, m = static_cast<Eigen::Index>(vectors.size());
  Chart chart(x);
  std::vector<Eigen::VectorXd> out = vectors;
  // y = (W_1, ..., W_m) as rates of the chart; the point and its velocity come from the path.
  auto load = [&](double s, Packed& y) {
    path(s, x, xdot);
    const Eigen::VectorXd c = coordinatesInChart(chart.axes, x);
    y.assign(static_cast<size_t>(k * m), 0.0);
    for (Eigen::Index j = 0; j < m; ++j)
      Eigen::Map<Eigen::VectorXd>(y.data() + j * k, k) = ratesInChart(chart.axes, c, out[size_t(j)]);
  };
  auto store = [&](double s, const Packed& y) {
    path(s, x, xdot);
    const Eigen::VectorXd c = coordinatesInChart(chart.axes, x);
    for (Eigen::Index j = 0; j < m; ++j)
      out[size_t(j)] = sphereVelocityInChart(chart.axes, c, Eigen::Map<const Eigen::VectorXd>(y.data() + j * k, k));
  };
  auto system = [&](const Packed& y, Packed& dydt, double s) {
    Eigen::VectorXd p, pdot;
    path(s, p, pdot);
    const Eigen::VectorXd c = coordinatesInChart(chart.axes, p);
    const Eigen::VectorXd r = ratesInChart(chart.axes, c, pdot);
    const std::vector<Eigen::MatrixXd> symbols = gamma(chart.axes, c);
    dydt.resize(y.size());
    for (Eigen::Index j = 0; j < m; ++j)
      Eigen::Map<Eigen::VectorXd>(dydt.data() + j * k, k) =
          -contract(symbols, r, Eigen::Map<const Eigen::VectorXd>(y.data() + j * k, k));
  };
  Packed y;
  load(0.0, y);
  integrateControlled(
      system, y, length, tolerance,
      [&](double s, Packed& state) {
        path(s, x, xdot);
        if (!chart.shouldChange(x)) return true;
        store(s, state);
        chart.choose(x);
        load(s, state);
        return true;
      },
      "parallel transport (charts)");
  store(length, y);
  return out;
}

Eigen::MatrixXd transportAlongPathAmbient(const ConstrainedModel& model, const PathPoint& path, double length,
                                          const Eigen::MatrixXd& vectors, double tolerance) {
  const Eigen::Index n = model.dimension(), m = vectors.cols();
  if (vectors.rows() != n || !vectors.allFinite())
    throw std::invalid_argument("parallel transport: expected vectors of " + std::to_string(n) + " finite numbers");
  Packed y(vectors.data(), vectors.data() + vectors.size());
  auto system = [&](const Packed& state, Packed& dydt, double s) {
    Eigen::VectorXd q, qdot;
    path(s, q, qdot);
    const KktFactor kkt(model, q);
    dydt.resize(state.size());
    for (Eigen::Index j = 0; j < m; ++j) {
      const Eigen::Map<const Eigen::VectorXd> w(state.data() + j * n, n);
      Eigen::Map<Eigen::VectorXd>(dydt.data() + j * n, n) =
          kkt.solve(Eigen::VectorXd::Zero(n), -model.secondDerivatives(qdot, w));
    }
  };
  integrateControlled(
      system, y, length, tolerance, [](double, Packed&) { return true; }, "parallel transport (ambient)");
  return Eigen::Map<const Eigen::MatrixXd>(y.data(), n, m);
}

}  // namespace sl

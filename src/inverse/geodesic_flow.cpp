#include "inverse/geodesic_flow.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "inverse/controlled_steps.hpp"

namespace sl {

namespace {

using Packed = std::vector<double>;

void pack(const FlowState& s, Packed& y) {
  const Eigen::Index n = s.q.size(), k = s.dq.cols(), w = s.transported.cols();
  y.resize(static_cast<std::size_t>(2 * n * (1 + k) + n * w));
  Eigen::Map<Eigen::VectorXd>(y.data(), n) = s.q;
  Eigen::Map<Eigen::VectorXd>(y.data() + n, n) = s.v;
  Eigen::Map<Eigen::MatrixXd>(y.data() + 2 * n, n, k) = s.dq;
  Eigen::Map<Eigen::MatrixXd>(y.data() + 2 * n + n * k, n, k) = s.dv;
  if (w > 0) Eigen::Map<Eigen::MatrixXd>(y.data() + 2 * n * (1 + k), n, w) = s.transported;
}

void unpack(const Packed& y, FlowState& s) {
  const Eigen::Index n = s.q.size(), k = s.dq.cols(), w = s.transported.cols();
  s.q = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
  s.v = Eigen::Map<const Eigen::VectorXd>(y.data() + n, n);
  s.dq = Eigen::Map<const Eigen::MatrixXd>(y.data() + 2 * n, n, k);
  s.dv = Eigen::Map<const Eigen::MatrixXd>(y.data() + 2 * n + n * k, n, k);
  if (w > 0) s.transported = Eigen::Map<const Eigen::MatrixXd>(y.data() + 2 * n * (1 + k), n, w);
}

}  // namespace

GeodesicFlow::GeodesicFlow(const ConstrainedModel& model, double tolerance) : model_(model), tolerance_(tolerance) {}

void GeodesicFlow::derivative(const Packed& y, Packed& dydt, int columns, int transported) const {
  ++evaluations_;
  const int n = model_.dimension();
  const Eigen::Map<const Eigen::VectorXd> q(y.data(), n), v(y.data() + n, n);
  const KktFactor kkt(model_, q);
  Eigen::VectorXd mu;
  const Eigen::VectorXd a = kkt.solve(Eigen::VectorXd::Zero(n), -model_.secondDerivatives(v, v), &mu);
  dydt.resize(y.size());
  Eigen::Map<Eigen::VectorXd>(dydt.data(), n) = v;
  Eigen::Map<Eigen::VectorXd>(dydt.data() + n, n) = a;
  for (int j = 0; j < columns; ++j) {
    const Eigen::Map<const Eigen::VectorXd> dq(y.data() + 2 * n + n * j, n),
        dv(y.data() + 2 * n + n * columns + n * j, n);
    Eigen::Map<Eigen::VectorXd>(dydt.data() + 2 * n + n * j, n) = dv;
    Eigen::Map<Eigen::VectorXd>(dydt.data() + 2 * n + n * columns + n * j, n) =
        kkt.solve(-model_.hessianCombination(mu, dq),
                  -2.0 * model_.secondDerivatives(v, dv) - model_.secondDerivatives(dq, a));
  }
  const Eigen::Index offset = 2 * n * (1 + columns);
  for (int j = 0; j < transported; ++j) {
    const Eigen::Map<const Eigen::VectorXd> w(y.data() + offset + n * j, n);
    Eigen::Map<Eigen::VectorXd>(dydt.data() + offset + n * j, n) =
        kkt.solve(Eigen::VectorXd::Zero(n), -model_.secondDerivatives(v, w));
  }
}

Eigen::VectorXd GeodesicFlow::acceleration(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  FlowState s{q, v, Eigen::MatrixXd(q.size(), 0), Eigen::MatrixXd(q.size(), 0)};
  Packed y, dydt;
  pack(s, y);
  derivative(y, dydt, 0);
  return Eigen::Map<const Eigen::VectorXd>(dydt.data() + q.size(), q.size());
}

bool GeodesicFlow::advance(FlowState& state, double duration,
                           const std::function<bool(double, const FlowState&)>& observer) const {
  const int columns = static_cast<int>(state.dq.cols()), transported = static_cast<int>(state.transported.cols());
  auto system = [&](const Packed& y, Packed& dydt, double) { derivative(y, dydt, columns, transported); };
  Packed y;
  pack(state, y);
  if (observer && !observer(0.0, state)) return duration == 0.0;
  const auto settle = [&](double t, Packed& packed) {
    unpack(packed, state);
    if (model_.relativeResidual(state.q) > 1e-15) {
      model_.projectPosition(state.q);
      state.v = model_.projectVelocity(state.q, state.v);
      model_.projectVariations(state.q, state.v, state.dq, state.dv);
      for (Eigen::Index j = 0; j < state.transported.cols(); ++j)
        state.transported.col(j) = model_.projectVelocity(state.q, state.transported.col(j));
      pack(state, packed);
    }
    return !observer || observer(t, state);
  };
  const bool whole = integrateControlled(system, y, duration, tolerance_, settle, "geodesic flow");
  unpack(y, state);
  return whole;
}

}  // namespace sl

#pragma once
// Parallel transport along paths of the configuration space (docs/geometry.md, "Parallel transport and
// holonomy"), by two routes that share nothing past the chain's positions:
//   ambient: a vector W tangent to the configuration space {c(q) = 0} in (R^N, M) is parallel along q(s) when its
//     derivative is normal, M W' + G^T nu = 0, and it stays tangent, G W' = -(q'^T A_i W)_i (the constraints'
//     second derivatives): one KKT solve per evaluation, any ConstrainedModel (chains of any length, the
//     ellipsoid). Along a geodesic W rides in GeodesicFlow (FlowState::transported); along any other path here.
//   charts: dW^i/ds = -Gamma^i_jk c'^j W^k in an atlas chart of the sphere (linkage/sphere_coordinates.hpp) with
//     exact Christoffel symbols, the geodesic itself by c'' = -Gamma(c', c'); the chart is changed between steps
//     when a better conditioned one exists, so poles and seams are ordinary points.
// Vectors cross between the routes as sphere velocities (tangent vectors of the unit sphere in R^(k+1)) on the
// chart side and as ambient vectors (stacked hinge velocities for a chain) on the other.

#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "inverse/constrained_model.hpp"
#include "linkage/chain_constants.hpp"

namespace sl {

// Gamma[i](j, k) = Gamma^i_jk of a metric on the unit sphere S^k, in the atlas chart with these axes.
using ChristoffelField =
    std::function<std::vector<Eigen::MatrixXd>(const std::vector<int>& axes, const Eigen::VectorXd& coords)>;
// The chain's kinetic metric (simulation/exact_fields.hpp).
ChristoffelField chainChristoffelField(const ChainConstants& bound);

// A path given by its position and velocity at each parameter s in [0, length].
using PathPoint = std::function<void(double s, Eigen::VectorXd& position, Eigen::VectorXd& velocity)>;

// The end of a geodesic on the chart side with the vectors carried along it (all sphere velocities).
struct ChartTransport {
  Eigen::VectorXd point, velocity;
  std::vector<Eigen::VectorXd> vectors;
  int chartChanges = 0;
};

// Chart route along the geodesic from (point, velocity) for time `duration`.
ChartTransport transportAlongGeodesicInCharts(const ChristoffelField& gamma, const Eigen::VectorXd& point,
                                              const Eigen::VectorXd& velocity, double duration,
                                              const std::vector<Eigen::VectorXd>& vectors, double tolerance = 1e-13);

// Chart route along a path of sphere points s -> (x(s), x'(s)), s in [0, length].
std::vector<Eigen::VectorXd> transportAlongPathInCharts(const ChristoffelField& gamma, const PathPoint& path,
                                                        double length, const std::vector<Eigen::VectorXd>& vectors,
                                                        double tolerance = 1e-13);

// Ambient route along a path of the model s -> (q(s), q'(s)), s in [0, length]; the columns of `vectors` are
// tangent at q(0).
Eigen::MatrixXd transportAlongPathAmbient(const ConstrainedModel& model, const PathPoint& path, double length,
                                          const Eigen::MatrixXd& vectors, double tolerance = 1e-13);

}  // namespace sl

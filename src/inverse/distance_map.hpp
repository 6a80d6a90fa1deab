#pragma once
// The distance from one point over a whole 2-sphere (a 2-dimensional ConstrainedModel: the 4-rod chain's
// configuration sphere, an ellipsoid, a round sphere), its conjugate locus, its cut locus and the injectivity
// radius (docs/geometry.md, "Distance map, cut and conjugate locus").
//   The exponential map: unit-speed geodesics from the point in a fan of directions (refined in angle where
//   neighbours separate), each carrying the Jacobi field J with J(0) = 0, J'(0) = the unit direction across
//   the fan; the first zero of J is the first conjugate point, where the geodesic is cut at the latest. The
//   triangles between neighbouring geodesics and arc-length steps are rasterised into the equirectangular
//   (phi, t) grid of the curvature maps, each node keeping its shortest arrival (length and direction).
//   The cut locus: grid edges across which the direction of the shortest arrival jumps (two distinct
//   shortest geodesics). The injectivity radius: the distance to the nearest cut point, checked against
//   Klingenberg's lemma, min(first conjugate distance, half the shortest geodesic loop through the point).
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "inverse/constrained_model.hpp"

namespace sl {

// The unit sphere point a configuration is drawn at (the chain: its sphere point; an ellipsoid: x / |x|).
using SphereProjection = std::function<Eigen::Vector3d(const Eigen::VectorXd& q)>;

struct DistanceMapOptions {
  int grid = 256;             // grid x grid nodes of uniformChartGrid: phi pole to pole, t periodic
  int columns = 0;            // nodes in t if not `grid` (the sphere panel: 2 (grid - 1), square cells)
  int directions = 128;       // the first fan, refined by bisection where neighbours separate
  double tolerance = 1e-10;   // the integrator's
  double lengthCap = 40;      // no geodesic is followed further (one that meets no conjugate point)
  double cutAngle = 0.25;     // a jump of the arrival direction (radians) across a grid edge marks the cut locus
  int threads = 0;            // 0: every core
  std::function<void(int done, int total)> progress;  // geodesics traced so far (called from one thread)
};

struct ConjugatePoint {
  double angle = 0;      // direction of the geodesic in the tangent basis at the point
  double distance = 0;   // arc length to the first zero of the Jacobi field
  Eigen::VectorXd q;     // the configuration there
  Eigen::Vector3d x;     // its sphere point
  bool cut = false;      // no shorter geodesic reaches it: a cut point (an end of the cut locus)
};

struct CutEdge {
  int a = 0, b = 0;      // grid nodes (row-major) whose shortest arrivals come from distinct geodesics
  double distance = 0;   // the mean of theirs
  Eigen::Vector3d x;     // midpoint on the unit sphere
};

struct DistanceMap {
  std::vector<double> phis, ts;   // the grid nodes
  std::vector<double> distance;   // row-major, phis.size() x ts.size()
  std::vector<double> direction;  // the angle of the shortest geodesic's start (same basis as ConjugatePoint)
  int uncovered = 0;              // nodes no triangle reached (filled from their neighbours)
  std::vector<ConjugatePoint> conjugateLocus;  // by angle; directions whose conjugate point is beyond the cap left out
  std::vector<CutEdge> cutLocus;
  Eigen::Vector3d point;          // the sphere point of the centre
  double injectivityRadius = 0;   // distance to the nearest cut point (a cut edge, or a conjugate cut point)
  double conjugateRadius = 0;     // the shortest distance to a first conjugate point
  double shortestLoop = 0;        // the shortest geodesic loop through the point (0: none found)
  double farthest = 0;            // the largest distance on the grid
  int geodesics = 0;              // directions traced
  Eigen::MatrixXd basis;          // the M-orthonormal tangent basis the angles refer to
  double klingenberg() const {    // Klingenberg's lemma: inj = min(conjugate radius, half the shortest loop)
    return shortestLoop > 0 ? std::min(conjugateRadius, shortestLoop / 2) : conjugateRadius;
  }
};

DistanceMap distanceMap(const ConstrainedModel& model, const SphereProjection& project, const Eigen::VectorXd& point,
                        const DistanceMapOptions& options = {});

// The distance from the map's point to one configuration `to` (sphere point x), exact: the map's shortest arrivals
// at the four grid nodes around x seed route 1 of connect (shootConnection), and the shortest converged motion is
// taken (across the cut locus the nodes' arrivals come from distinct geodesics; both are tried). Nothing when no
// seed converges. `from` is the map's point.
struct Arrival {
  double distance = 0;   // the kinetic length of the shortest motion found
  double direction = 0;  // its start's angle in the map's tangent basis
};
std::optional<Arrival> shortestArrival(const ConstrainedModel& model, const DistanceMap& map,
                                       const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                       const Eigen::Vector3d& x);

// The shortest geodesic loop through the point up to the length bound (geodesics from it back to it, by
// shooting from a fan's near returns); 0 if none was found.
double shortestGeodesicLoop(const ConstrainedModel& model, const Eigen::VectorXd& point, double bound,
                            double tolerance = 1e-10);

// The cut locus as a graph on the grid's faces (each cut edge joins the two faces beside it): its cycles, and
// the components of its closure (the conjugate cut points, its ends, joined to the cut faces within three faces
// and to each other: near an end, where neighbouring geodesics barely separate, the jump of direction is too
// small to mark every edge). A tree: one component, no cycle.
struct CutGraphShape {
  int vertices = 0, edges = 0, edgeComponents = 0, components = 0;
  int cycles() const { return edges - vertices + edgeComponents; }
};
CutGraphShape cutGraphShape(const DistanceMap& map);

// Local extrema of the first conjugate distance over the directions (the cusps of the conjugate locus),
// changes smaller than `noise` ignored.
int conjugateCusps(const DistanceMap& map, double noise = 1e-7);

}  // namespace sl

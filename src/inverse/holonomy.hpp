#pragma once
// Holonomy of loops of motions of a 4-rod chain (a surface, S^2): a tangent vector parallel transported once round
// a closed loop comes back turned, by the total Gaussian curvature the loop encloses (Gauss-Bonnet; docs/geometry.md,
// "Parallel transport and holonomy"). Computed, and checked, three ways:
//   - the turning angle of the vector by both routes of inverse/parallel_transport.hpp;
//   - the total curvature of the region to the loop's left, integral of K dA with the exact K (geometry/curvature.hpp),
//     over the cone of chords from an apex: the chain (s, u) -> (1 - u) A + u gamma(s), pushed onto the sphere, has
//     the loop as its boundary, so for any loop avoiding -A it integrates K dA over the enclosed region with sign;
//   - for a loop of geodesic pieces (corners joined by their shortest motions), the angle excess of its corners,
//     2 pi - sum of the turning angles (for a small counter-clockwise triangle, angle sum - pi).
// Angles are measured in the kinetic metric in the orientation of the sphere's outward normal: a loop running
// counter-clockwise round its region, seen from outside, turns vectors by +integral of K dA (mod 2 pi).

#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "contracts/run_control.hpp"
#include "inverse/periodic.hpp"
#include "linkage/chain.hpp"

namespace sl {

struct Holonomy {
  double angle = 0;             // the turning of a transported vector, ambient route, in (-pi, pi]
  double chartAngle = 0;        // the same by the chart route
  double enclosedCurvature = 0; // integral of K dA over the region to the loop's left (not reduced mod 2 pi)
  std::optional<double> angleExcess;  // geodesic loops: 2 pi - sum of turning angles at the corners
  std::vector<double> interiorAngles; // geodesic loops: pi - turning angle, at each corner
  std::vector<double> pieceLengths;   // geodesic loops: the length of each motion
  double length = 0;                  // of the whole loop, in the kinetic metric
  int chartChanges = 0;               // the chart route's changes of chart round the loop
  Eigen::VectorXd apex;               // geodesic loops: the enclosed curvature's cone is from here (the corners' mean)
  // Geodesic loops, when asked for: each piece sampled evenly in its time, from its start (the vector as the previous
  // piece brought it) to its end, with the transported vector (ambient route) and the path's velocity as sphere
  // velocities, and the curvature swept so far: integral of K dA over the cone of chords from the loop's apex to the
  // piece between its start and this sample (the holonomy of that closed wedge, by Gauss-Bonnet; summed over the
  // pieces at fraction 1 it is enclosedCurvature).
  struct Sample {
    Eigen::VectorXd point, velocity, transported;
    std::size_t piece = 0;
    double fraction = 0;  // of the piece's time
    double swept = 0;
  };
  std::vector<Sample> samples;

  // The checks, each reduced to (-pi, pi]: routes against each other, holonomy against the enclosed curvature and
  // against the angle excess.
  double routeDifference() const;
  double curvatureDifference() const;
  std::optional<double> excessDifference() const;
};

// The geodesic polygon through the sphere points `corners` (at least 3, consecutive ones distinct and not
// antipodal), each pair joined by its shortest motion (inverse/connect.hpp), the last back to the first.
// Throws std::invalid_argument for fewer than 3 corners or a chain that is not of 4 rods, std::runtime_error if no
// motion between two corners is found.
Holonomy polygonHolonomy(const Chain& chain, const std::vector<Eigen::VectorXd>& corners, bool (*cancelled)() = nullptr,
                         int samplesPerPiece = 0);

// The latitude phi = constant of chart 0 (|phi| < pi/2), run with t increasing: counter-clockwise round the pole
// phi = pi/2, whose cap is the enclosed region.
Holonomy latitudeHolonomy(const Chain& chain, double phi);

// A closed geodesic (inverse/periodic.hpp) once round from its start. A vector carried along it comes back as it
// left: the velocity is carried to itself, and on a surface a rotation fixing a vector is none; so the holonomy is 0
// and the curvature to the loop's left is a whole number of turns (2 pi for a simple one: Gauss-Bonnet with a
// geodesic boundary). The cone's apex is the loop's mean left normal (the loop runs counter-clockwise round it).
Holonomy closedGeodesicHolonomy(const Chain& chain, const ClosedGeodesic& geodesic);

// (x - y) reduced to (-pi, pi].
double angleDifference(double x, double y);

}  // namespace sl

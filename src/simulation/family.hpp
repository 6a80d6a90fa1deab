#pragma once
// Families of geodesics around a run: the starts of a fan, a parallel family or a cloud
// (contracts/run_config.hpp, FamilySpec), each a valid start on the run's chain. Members share the run's
// method and integrator; the frames stage and `simulate` integrate them beside the run.

#include <functional>
#include <vector>

#include "contracts/run_config.hpp"
#include "linkage/chain.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

// The kinetic metric's inner product g(u, v) of two tangent vectors of S^(n-2) at x (polarisation of
// speedSquared, so that it is the very metric the runs integrate).
double kineticInner(const Chain& chain, const Eigen::VectorXd& x, const Eigen::VectorXd& u, const Eigen::VectorXd& v);

// A g-orthonormal basis of the tangent space at x whose first vector is along `first` (not zero), the rest in
// a fixed order (Gram-Schmidt of the Euclidean tangent basis): the same for the same input, bit for bit.
// `count` limits the frame to its first vectors (0: the whole frame, n-2 of them). O(n^3) for the whole frame.
std::vector<Eigen::VectorXd> orthonormalTangentFrame(const Chain& chain, const Eigen::VectorXd& x,
                                                     const Eigen::VectorXd& first, std::size_t count = 0);

// The members' starts, in member order (the order of the wavefront). `config` integrates the parallel
// family's orthogonal geodesic. Throws std::invalid_argument if a member's start is not valid (e.g. the
// orthogonal geodesic stopped before reaching it).
std::vector<InitialState> familyStarts(const Chain& chain, const InitialState& start, const FamilySpec& family,
                                       const RunConfig& config);

// The members' motions, in member order: the run's chain, method, integrator and watchdogs, without the run's
// Jacobi fields (a family shows how geodesics spread; only the run itself carries its linearisation). Each
// member gets `cancelled` (Trajectory::setCancellation), which is also asked between members: true throws
// RunCancelled, so that setting up a large family answers a signal too.
std::vector<Trajectory> familyMembers(const Chain& chain, const InitialState& start, const FamilySpec& family,
                                      const RunConfig& config,
                                      const std::function<bool()>& cancelled = {});

}  // namespace sl

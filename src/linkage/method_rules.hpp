#pragma once
// Which method can move which chain from which start: the one statement of these rules. The scene loader turns
// a refusal into a message at the run's JSON path, the simulation into its exception; both ask here.

#include <vector>

#include "contracts/registry.hpp"
#include "linkage/chain.hpp"

namespace sl {

enum class MethodRefusal {
  JacobiNeedsAmbient,        // Jacobi fields are the ambient method's linearisation
  SlackChainHasNoChart,      // a chart method on a slack chain (L <= n-2)
  HingeStartHasNoChart,      // a chart method from a start by hinges
  TooManyRodsForCharts,      // a chart method on more than limits::kMaxRods rods
  JacobiNeedsSpherePoint,    // Jacobi fields from a start by hinges, or on a slack chain
  JacobiNeedsFourRods,       // 3 rods have no direction across the motion
  PublishedNeedsFourRods,    // a published method (spec sections 4, 5) on other than 4 rods
  PublishedNeedsSpecMasses,  // ... on 4 rods without unit hinge masses and massless rods
};

struct MotionRequest {
  Method method = Method::Ambient;
  // The chain, or null while its number of rods is unknown (a scene with an invalid "rods"): the rules that
  // depend on n or L are then skipped, as a made-up n would refuse what is not wrong.
  const Chain* chain = nullptr;
  bool startByHinges = false;  // else a point of the configuration sphere (chart coordinates or a drag)
  bool jacobi = false;         // with the Jacobi fields along the motion
};

// Every reason the request cannot be carried out, in the order above; empty when it can. Of the chart rules
// (slack, hinges, too many rods) only the first that applies is given, and of the published ones only one.
std::vector<MethodRefusal> methodRefusals(const MotionRequest& request);

}  // namespace sl

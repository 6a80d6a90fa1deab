#pragma once
// Starts that name a found motion (a scene's initial.connect, initial.periodic), and the configuration the sphere's
// distance colouring is measured from (view.sphere.distance_from): resolved once, when the scene is read for a
// command, so that every command, shard, frame range and still starts the same runs and draws the same sphere.

#include "scene/scene.hpp"
#include "scene/scene_problems.hpp"

namespace sl {

// Places view.sphere.distance_from on the rod constraints (Scene::distancePoint). Finds the motion each such run's
// start names (inverse/connect.hpp, inverse/periodic.hpp; a search shared by several runs is made once) and records its sphere point and velocity in the run's InitialSpec::motion; sets a
// left-out duration to the longest motion's time and fills the title's {runs[i].length} and {runs[i].stability}.
// Returns the problems (JSON path and words: an index past the motions found, hinges off the rod constraints); the
// scene is complete only when there are none.
std::vector<SceneProblem> resolveMotionStarts(Scene& scene);

}  // namespace sl

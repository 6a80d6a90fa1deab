#pragma once
// The scene's start (chart coordinates or a drag on the sphere) as the chart-free InitialState of its runs.

#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

// Chart coordinates and rates (chart 0, the spec's) or a drag (the spec's demo), by the simulation's
// conversions (simulation/initial_state.hpp); unit_speed rescales the velocity so that g(v, v) = 1.
InitialState sceneStart(const Scene& scene);

// The scene limits the simulation imposes: its method and integrator names, and which integrators are
// adaptive (they take "tolerance", the others "step"). The image-size limit is the renderer's to add.
SceneLimits simulationSceneLimits();

}  // namespace sl

// The one step from a scene to a runnable model (MuJoCo's mj_compile: an mjSpec in, a const
// mjModel out). compile() resolves everything a run derives from its scene (the maze and its
// centreline, solved once; the entry port and the rod placed behind it; the reference
// trajectory and the run's duration; the contact geometry; the controller's plant; every force
// module, actuation included) into a Model that nothing changes afterwards. The input Scene is
// never modified: the Model keeps the resolved copy. Everything a run changes lives in the
// Run's State and Workspace, so one compiled Model can drive many runs, in many threads.
#pragma once

#include <memory>

#include "sim/step/model.h"

namespace vascsim {

// Throws InputError (naming scene.file and the JSON path) for a scene that cannot be compiled:
// node indices out of range, a maze whose start and goal do not connect, ...
std::shared_ptr<const Model> compile(const Scene& scene);

}  // namespace vascsim

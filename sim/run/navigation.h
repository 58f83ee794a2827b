// Navigation: what a maze scene adds to a plain rod run (issue 4). The environment with its
// entry port opened, the rod placed straight behind the start so that its tip (the last node)
// sits on the path's start, the reference trajectory, the tip controller's plant model, and the
// force modules the scene asks for: actuation (force, kinematic or field), wall contact,
// friction. The two steps of compile() (sim/run/compile.h) that concern the maze; the Model
// holds the result, immutable afterwards.
#pragma once

#include <memory>
#include <optional>

#include "sim/contact/contact_pairs.h"
#include "sim/contact/contact_params.h"
#include "sim/control/actuation.h"
#include "sim/control/tip_controller.h"
#include "sim/env/centreline.h"
#include "sim/env/environment.h"
#include "sim/env/trajectory.h"
#include "sim/env/wall_distance.h"
#include "sim/step/model.h"

namespace vascsim {

struct Navigation {
  // What the rod moves in, whatever made it: a maze with its entry port cut open, a vessel
  // network or a traced mask, with the inlet, the centreline and the lumen outline.
  Environment environment;
  // Maze scenes only: the maze as generated (or given) before the port was cut, and its route.
  Environment maze;
  MazeRoute route;
  std::optional<Trajectory> trajectory;
  ContactParams contact;
  // The walls' contact geometry, one per run: contact, friction and the gap statistics share it.
  std::shared_ptr<const ContactGeometry> contact_geometry;
  // The paper's contact mode: the walls' distance field its push-out iterations query.
  std::shared_ptr<const WallDistanceField> paper_walls;
  TipPlant plant;
  std::shared_ptr<const Actuation> actuation;  // how the controller's command reaches the rod
};

// Resolves the environment and path of `scene` and places the rod at the entry: overwrites
// scene.shape (start, direction, straight) and the run's duration. compile() calls it on its
// own copy of the scene. Throws InputError if start and goal do not connect.
std::unique_ptr<Navigation> prepare_navigation(Scene& scene);
// Adds the navigation force modules to a Model built from the prepared scene, and fills the
// parts of `navigation` that depend on the compiled rod (contact parameters, plant model).
void add_navigation_modules(const Scene& scene, Navigation& navigation, Model& model);

}  // namespace vascsim

// Model: the constant description of a run (MuJoCo's mjModel): the compiled rod, kinematic
// boundary conditions, solver settings, the force modules the scene switched on and, for a maze
// scene, the navigation (environment, trajectory, contact geometry, plant). Made by compile()
// (sim/run/compile.h); step(), solve_static() and Run only read it.
//
// Adding a force kind needs no change here or in the stepper: a ForceModule that compile()
// (build_model for loads, add_navigation_modules for navigation forces) pushes onto `forces`.
#pragma once

#include <memory>
#include <vector>

#include "sim/rod/rod_model.h"
#include "sim/scene/scene.h"
#include "sim/step/force_module.h"
#include "sim/step/state.h"

namespace vascsim {

// A node held on a prescribed path: x(t) = origin + velocity t + amplitude sin(2 pi frequency t).
// Clamped and pinned nodes are the case velocity = amplitude = 0.
struct NodeConstraint {
  int node = 0;
  Vec2 origin = Vec2::Zero();     // m
  Vec2 velocity = Vec2::Zero();   // m/s
  Vec2 amplitude = Vec2::Zero();  // m
  double frequency = 0.0;         // Hz
  // Which coordinates are held: both for a clamp, a pin or a prescribed motion; one for a support
  // (a roller holds y and lets x slide, a slider the reverse).
  bool hold_x = true, hold_y = true;
  // Proximal advancement (AdvanceSpec): moved by its fed length along feed_direction.
  AdvanceSpec feed;                    // none unless feed.enabled()
  Vec2 feed_direction = Vec2::Zero();  // unit
  Vec2 position(double t) const;
  Vec2 rate(double t) const;      // dx/dt, m/s
};

struct Navigation;  // sim/run/navigation.h

struct Model {
  Scene scene;  // the scene as resolved by compile() (run duration, rod placed at the entry)
  std::shared_ptr<const Navigation> navigation;  // null for a rod in free space
  RodModel rod;
  SolverSpec solver;
  std::vector<NodeConstraint> constraints;  // each node at most once
  // Shared, immutable: copying a Model shares its modules, whose per-run data live in Workspace.
  std::vector<std::shared_ptr<const ForceModule>> forces;

  int nodes() const { return rod.nodes; }
  int dofs() const { return 2 * rod.nodes; }
};

// The rod part of compile(): the scene's rod, shape, boundary, loads and solver sections, without
// navigation (tests of the rod alone build on it). Throws InputError (naming scene.file and the
// JSON path) for node indices out of range or a node constrained twice.
Model build_model(const Scene& scene);
// The state at t = 0: the initial shape at rest, constrained nodes moving with their prescription.
State initial_state(const Model& model);
// Resolves a node index that may count from the tip (-1 = last); returns -1 if out of range.
int resolve_node(int node, int nodes);

}  // namespace vascsim

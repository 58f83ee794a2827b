#include "sim/run/navigation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/contact/paper_contact.h"
#include "sim/contact/wall_contact.h"
#include "sim/env/centreline.h"
#include "sim/env/entry_port.h"
#include "sim/env/vessel_environment.h"
#include "sim/rod/loads.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

std::string label_of(const Scene& scene) { return scene.file.empty() ? std::string("built-in scene") : scene.file; }

// The drive moves its grip on the rod (nodes 0 and 1, held) straight along the inlet, and nothing
// stops it at a wall: a held node inside one has no finite wall force (a feed on past a dead end
// once the whole rod is in takes the grip there). Walks the grip along the fed lengths the run
// reaches, each probe as far on as the gap lets it (a gap changes no faster than the grip
// moves), and refuses the first probe in a wall.
void refuse_a_feed_into_a_wall(const Scene& scene, const Navigation& nav, const Model& model) {
  const AdvanceSpec& feed = scene.control.advance;
  double shortest = feed.fed_length(scene.run.duration), longest = shortest;  // m
  for (const auto& [t, s] : feed.points)
    if (t <= scene.run.duration) {
      shortest = std::min(shortest, s);
      longest = std::max(longest, s);
    }
  const double radius = model.rod.outer_radius;
  const Vec2 inward = nav.environment.inlet.inward;
  const Eigen::Vector4d grip = model.rod.x_initial.head<4>();
  for (const double end : {longest, shortest})
    for (double s = 0.0;;) {
      Eigen::VectorXd x = grip;
      x.segment<2>(0) += s * inward;
      x.segment<2>(2) += s * inward;
      const double gap = nav.contact_geometry->min_gap(x, 4.0 * radius);
      if (gap <= 0.0) {
        char text[400];
        std::snprintf(text, sizeof text,
                      ": /control/advance: the drive holds the rod's root (nodes 0 and 1) and moves it along the "
                      "inlet; at a fed length of %.4g m (the run feeds %.4g to %.4g m) the root reaches a wall (the rod "
                      "is %g m long): feed less, or make the run shorter",
                      s, shortest, longest, scene.rod.length);
        throw InputError(label_of(scene) + text);
      }
      if (s == end) break;
      // Never a probe shorter than 1 % of the rod's radius (a grip along a wall would take
      // forever): a wall is at least 2 radii deep to the grip, so only a grazing touch is missed,
      // which Newton then reports as a held node inside a wall.
      const double probe = std::max(std::min(gap, 4.0 * radius), 1e-2 * radius);
      s = end > 0.0 ? std::min(end, s + probe) : std::max(end, s - probe);
    }
}

// A rod that cannot fit the lumen, or that the entry leaves inside a wall, would blow up at the
// first step ("the residual is not finite"): say what does not fit instead.
void refuse_what_does_not_fit(const Scene& scene, const Navigation& nav, const Model& model) {
  char text[400];
  const double diameter = 2.0 * model.rod.outer_radius;
  const Environment& env = nav.environment;
  if (scene.environment == EnvironmentKind::kMaze) {
    if (env.lumen_width > 0.0 && env.lumen_width <= diameter) {
      std::snprintf(text, sizeof text, ": /maze/lumen_width: the lumen (%g mm) must be wider than the rod (%g mm across, /rod/outer_radius)",
                    1e3 * env.lumen_width, 1e3 * diameter);
      throw InputError(label_of(scene) + text);
    }
  } else {
    // The narrowest place on the route, e.g. a stenosis, must let the rod through.
    const auto narrowest = std::min_element(env.centreline_radius.begin(), env.centreline_radius.end());
    // Within 1e-9 counts as equal: a stenosis leaving exactly the rod's width came out 4 nm wider.
    if (narrowest != env.centreline_radius.end() && 2.0 * *narrowest <= diameter * (1 + 1e-9)) {
      const Vec2& at = env.centreline[static_cast<std::size_t>(narrowest - env.centreline_radius.begin())];
      std::snprintf(text, sizeof text, ": /vessels: the lumen on the route narrows to %g mm across at (%g, %g) m, "
                    "not wider than the rod (%g mm across, /rod/outer_radius)", 2e3 * *narrowest, at.x(), at.y(), 1e3 * diameter);
      throw InputError(label_of(scene) + text);
    }
  }
  const double gap = nav.contact_geometry->min_gap(model.rod.x_initial, std::max(env.lumen_width, diameter));
  if (gap <= 0.0 && scene.environment == EnvironmentKind::kVessels) {
    std::snprintf(text, sizeof text,
                  ": /vessels: the rod starts %g mm inside a wall: it lies straight behind the start along the "
                  "inlet for its length (%g m); choose a start where the vessel runs straight into the network "
                  "(for a mask, /vessels/mask/start on the inlet) or a shorter rod",
                  -1e3 * gap, scene.rod.length);
    throw InputError(label_of(scene) + text);
  }
  if (gap <= 0.0) {
    std::snprintf(text, sizeof text,
                  ": /maze: the rod starts %g mm inside a wall: it lies straight behind the start for its length "
                  "(%g m) and the entry is cut only through walls within that length and thinner than the gaps "
                  "between channels; use cells whose walls are near the start (a smaller maze or larger lumens) "
                  "or a longer rod",
                  -1e3 * gap, scene.rod.length);
    throw InputError(label_of(scene) + text);
  }
  if (scene.control.advance.enabled()) refuse_a_feed_into_a_wall(scene, nav, model);
}

// The maze's own environment, then its route, then the port cut into it along the route's first leg.
void prepare_maze(const Scene& scene, Navigation& nav) {
  nav.maze = build_environment(scene.maze);
  nav.route = solve_route(nav.maze, scene.maze, scene.path);
  Environment& env = nav.environment;
  env.inlet = open_entry(nav.maze, nav.route.corners, scene.rod.length, env);
  env.lumen = {{env.bounds.min, Vec2(env.bounds.max.x(), env.bounds.min.y()), env.bounds.max,
                Vec2(env.bounds.min.x(), env.bounds.max.y())}};
  env.centreline = nav.route.corners;
  env.centreline_radius.assign(env.centreline.size(), 0.5 * env.lumen_width);
  env.goal_radius = 0.5 * env.lumen_width;
}

}  // namespace

std::unique_ptr<Navigation> prepare_navigation(Scene& scene) {
  auto nav = std::make_unique<Navigation>();
  try {
    if (scene.environment == EnvironmentKind::kMaze) prepare_maze(scene, *nav);
    else {
      // A drive that pulls the rod back draws its root further out along the introducer.
      double retraction = 0.0;  // m
      for (const auto& point : scene.control.advance.points) retraction = std::max(retraction, -point.second);
      nav->environment = build_vessel_environment(scene.vessels, scene.rod.length + retraction);
      for (double& r : nav->environment.corner_radius) r = std::min(r, scene.path.corner_radius);
    }
  } catch (const InputError& e) {
    // The environment code knows the JSON path, not the file.
    throw InputError(label_of(scene) + ": " + e.what());
  }
  const Environment& env = nav->environment;
  if (env.corner_radius.empty())
    nav->trajectory.emplace(env.centreline, scene.path.corner_radius, scene.path.speed, scene.path.ramp_time);
  else
    nav->trajectory.emplace(env.centreline, env.corner_radius, scene.path.speed, scene.path.ramp_time);
  scene.run.duration = scene.run.duration_for(nav->trajectory->duration());
  scene.run.duration_from_path = false;
  // The rod lies straight behind the start, root first: node 0 outside the network, the tip (last
  // node) on the path's start, heading into the first leg.
  scene.shape.start = env.inlet.tip - scene.rod.length * env.inlet.inward;
  scene.shape.direction = std::atan2(env.inlet.inward.y(), env.inlet.inward.x());
  scene.shape.initial_curvature = 0.0;
  return nav;
}

void add_navigation_modules(const Scene& scene, Navigation& nav, Model& model) {
  nav.contact = resolve_contact_params(scene.contact, model.rod);
  // The feedforward accelerates the actuated nodes' mass and cancels the drag the scene models:
  // the tip heads along the path, so with drag on every node it meets the tangential coefficient.
  const int n = model.nodes();
  const int actuated = std::min(scene.control.actuated_nodes, n);
  double mass = 0.0;
  for (int k = 0; k < actuated; ++k) mass += model.rod.mass[n - 1 - k];
  nav.plant.mass = mass;
  if (scene.loads.drag.enabled)
    nav.plant.drag_coefficient = QuadraticDragModule(model.rod, scene.loads.drag).tangential_coefficients()[n - 1];

  if (scene.control.advance.enabled()) {
    // The drive grips the rod's first two nodes and moves them along the inlet.
    for (const auto& c : model.constraints)
      if (c.node <= 1)
        throw InputError(label_of(scene) + ": /control/advance: the drive holds nodes 0 and 1, and the boundary already constrains node " +
                         std::to_string(c.node));
    for (int node : {0, 1}) {
      NodeConstraint c;
      c.node = node;
      c.origin = model.rod.x_initial.segment<2>(2 * node);
      c.feed = scene.control.advance;
      c.feed_direction = nav.environment.inlet.inward;
      model.constraints.push_back(c);
    }
  }
  nav.actuation = make_actuation(scene.control);
  for (auto& module : nav.actuation->modules(n)) model.forces.push_back(std::move(module));
  // A kinematic tip's motion is imposed: a force on it would move nothing and only be logged.
  if (scene.control.disturbance.amplitude > 0.0 && scene.control.disturbance.kind == DisturbanceKind::kForce &&
      scene.control.mode != ActuationMode::kKinematic) {
    PointLoadSpec load;
    load.node = n - 1;
    load.force = scene.control.disturbance.amplitude * scene.control.disturbance.direction;
    load.profile = LoadProfile::kSine;
    load.frequency = scene.control.disturbance.omega / (2.0 * M_PI);
    model.forces.push_back(std::make_unique<PointLoadModule>(n, std::vector<PointLoadSpec>{load}));
  }
  nav.contact_geometry = make_contact_geometry(nav.environment.walls, model.rod, nav.contact);
  refuse_what_does_not_fit(scene, nav, model);
  if (scene.contact.mode == ContactMode::kImplicit) {
    model.forces.push_back(std::make_unique<WallContactModule>(nav.contact_geometry, nav.contact));
    if (nav.contact.friction > 0.0)
      model.forces.push_back(std::make_unique<WallFrictionModule>(nav.contact_geometry, nav.contact));
  } else if (scene.contact.mode == ContactMode::kPaper) {
    // The paper's penalty: wall forces decided between Newton solves (Run), applied as controls.
    nav.paper_walls = std::make_shared<const WallDistanceField>(nav.environment.walls, 8.0 * model.rod.outer_radius);
    model.forces.push_back(std::make_unique<ExplicitWallForceModule>(n));
  }
}

}  // namespace vascsim

#include "sim/step/model.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "sim/contact/self_contact.h"
#include "sim/rod/loads.h"
#include "sim/scene/input_error.h"

namespace vascsim {

Vec2 NodeConstraint::position(double t) const {
  const Vec2 fed = feed.enabled() ? Vec2(feed.fed_length(t) * feed_direction) : Vec2::Zero();
  return origin + velocity * t + amplitude * std::sin(2.0 * M_PI * frequency * t) + fed;
}

Vec2 NodeConstraint::rate(double t) const {
  const Vec2 fed = feed.enabled() ? Vec2(feed.speed(t) * feed_direction) : Vec2::Zero();
  return velocity + amplitude * (2.0 * M_PI * frequency * std::cos(2.0 * M_PI * frequency * t)) + fed;
}

int resolve_node(int node, int nodes) {
  const int i = node < 0 ? node + nodes : node;
  return i >= 0 && i < nodes ? i : -1;
}

namespace {

int checked_node(const Scene& scene, int node, const std::string& pointer) {
  const int i = resolve_node(node, scene.rod.nodes);
  if (i < 0)
    throw InputError(scene.file + ": " + pointer + ": expected a node index in [" + std::to_string(-scene.rod.nodes) +
                     ", " + std::to_string(scene.rod.nodes - 1) + "], got " + std::to_string(node));
  return i;
}

}  // namespace

Model build_model(const Scene& scene) {
  Model model;
  const BoundarySpec& bc = scene.boundary;
  model.rod = build_rod_model(scene.rod, scene.shape, bc.clamp);
  model.solver = scene.solver;
  const int n = model.rod.nodes;

  std::vector<char> used(static_cast<std::size_t>(n), 0);
  auto constrain = [&](const NodeConstraint& c, const std::string& pointer) {
    if (used[static_cast<std::size_t>(c.node)])
      throw InputError(scene.file + ": " + pointer + ": node " + std::to_string(c.node) + " is already constrained");
    used[static_cast<std::size_t>(c.node)] = 1;
    model.constraints.push_back(c);
  };
  auto fixed = [&](int node) {
    NodeConstraint c;
    c.node = node;
    c.origin = model.rod.x_initial.segment<2>(2 * node);
    return c;
  };
  if (bc.clamp != ClampKind::kNone) {
    constrain(fixed(0), "/boundary/clamp");
    constrain(fixed(1), "/boundary/clamp");
  }
  for (std::size_t k = 0; k < bc.pinned.size(); ++k) {
    const std::string pointer = "/boundary/pinned/" + std::to_string(k);
    constrain(fixed(checked_node(scene, bc.pinned[k], pointer)), pointer);
  }
  for (std::size_t k = 0; k < bc.supports.size(); ++k) {
    const std::string pointer = "/boundary/supports/" + std::to_string(k);
    NodeConstraint c = fixed(checked_node(scene, bc.supports[k].node, pointer + "/node"));
    c.hold_x = bc.supports[k].axis == SupportAxis::kX;
    c.hold_y = !c.hold_x;
    constrain(c, pointer);
  }
  for (std::size_t k = 0; k < bc.prescribed.size(); ++k) {
    const std::string pointer = "/boundary/prescribed/" + std::to_string(k);
    const auto& p = bc.prescribed[k];
    NodeConstraint c = fixed(checked_node(scene, p.node, pointer + "/node"));
    c.velocity = p.velocity;
    c.amplitude = p.amplitude;
    c.frequency = p.frequency;
    constrain(c, pointer);
  }

  const LoadSpec& loads = scene.loads;
  // Bodies first: their mass is the rod's to every module after (gravity acts on it too).
  bool body_drag = false;
  for (std::size_t k = 0; k < loads.bodies.size(); ++k) {
    const BodySpec& b = loads.bodies[k];
    model.rod.mass[checked_node(scene, b.node, "/loads/bodies/" + std::to_string(k) + "/node")] += b.mass;
    body_drag = body_drag || b.linear_drag > 0.0 || b.quadratic_drag > 0.0;
  }
  if (loads.gravity.enabled) model.forces.push_back(std::make_unique<GravityModule>(model.rod, loads.gravity.acceleration));
  if (!loads.point_loads.empty()) {
    for (std::size_t k = 0; k < loads.point_loads.size(); ++k)
      checked_node(scene, loads.point_loads[k].node, "/loads/point/" + std::to_string(k) + "/node");
    model.forces.push_back(std::make_unique<PointLoadModule>(n, loads.point_loads));
  }
  if (loads.damping.enabled && loads.damping.coefficient > 0.0)
    model.forces.push_back(std::make_unique<ViscousDampingModule>(model.rod, loads.damping.coefficient));
  if (loads.drag.enabled) model.forces.push_back(std::make_unique<QuadraticDragModule>(model.rod, loads.drag));
  if (loads.magnet.enabled) model.forces.push_back(std::make_unique<MagnetLoadModule>(n, loads.magnet));
  if (body_drag) model.forces.push_back(std::make_unique<BodyDragModule>(n, loads.bodies));
  if (scene.contact.self) {
    auto self = std::make_unique<SelfContactModule>(model.rod, resolve_contact_params(scene.contact, model.rod));
    // A rod that starts overlapping itself (a shape coiled tighter than its thickness) has no
    // barrier to start from: said here, not as a blow-up at t = 0.
    if (const auto overlap = self->first_overlap(model.rod.x_initial)) {
      char text[320];
      std::snprintf(text, sizeof text,
                    ": /contact/self: the rod starts overlapping itself (node %d is %.3g mm from the edge of nodes %d and %d, "
                    "less than its thickness %.3g mm, /rod/outer_radius): give it a starting shape that does not cross "
                    "itself (/shape/initial_curvature) or turn self-contact off",
                    overlap->node, 1e3 * overlap->distance, overlap->edge, overlap->edge + 1, 1e3 * self->thickness());
      throw InputError(scene.file + text);
    }
    model.forces.push_back(std::move(self));
  }
  return model;
}

State initial_state(const Model& model) {
  State s;
  s.t = 0.0;
  s.x = model.rod.x_initial;
  s.v = Eigen::VectorXd::Zero(model.dofs());
  for (const auto& c : model.constraints)
    for (int axis = 0; axis < 2; ++axis)
      if (axis == 0 ? c.hold_x : c.hold_y) {
        s.x[2 * c.node + axis] = c.position(0.0)[axis];
        s.v[2 * c.node + axis] = c.rate(0.0)[axis];
      }
  return s;
}

}  // namespace vascsim

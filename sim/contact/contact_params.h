// Resolved wall-contact parameters: the scene's ContactSpec with its automatic defaults filled in
// from the rod, so that a scene needs no tuning (docs/contact.md explains the choices).
#pragma once

#include "sim/rod/rod_model.h"
#include "sim/scene/scene.h"

namespace vascsim {

struct ContactParams {
  double rod_radius = 0.0;     // m, contact happens at the rod's outer surface
  double g_hat = 0.0;          // m, barrier activation distance
  double kappa = 0.0;          // N, barrier force scale
  double friction = 0.0;       // -, Coulomb mu
  double slip_velocity = 0.0;  // m/s, friction regularisation
};

// g_hat defaults to a quarter of the outer radius: the rod never visibly floats off a wall, and
// at most a quarter radius of its surface is a "soft layer". kappa defaults to EI / (0.1 L)^2,
// the force that bends the rod over a tenth of its length, the scale of the contact forces the
// rod's own stiffness creates at maze corners; a push much larger than kappa only moves the
// contact closer to the wall (the barrier is unbounded), never through it.
inline ContactParams resolve_contact_params(const ContactSpec& spec, const RodModel& rod) {
  ContactParams p;
  p.rod_radius = rod.outer_radius;
  p.g_hat = spec.activation_distance > 0.0 ? spec.activation_distance : 0.25 * rod.outer_radius;
  const double bend_length = 0.1 * rod.length;
  p.kappa = spec.stiffness > 0.0 ? spec.stiffness : rod.ei / (bend_length * bend_length);
  p.friction = spec.friction;
  p.slip_velocity = spec.slip_velocity;
  return p;
}

}  // namespace vascsim

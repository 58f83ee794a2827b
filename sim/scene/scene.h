// The scene: an immutable description of one run (environment, rod, loads, solver, output), as
// plain structs. Every default of the scene file lives here, in the member initialisers, and
// docs/scenes.md lists them; a scene file only overrides them. The io layer fills these from
// JSON and validates ranges; the simulation compiles them into a Model and never changes them.
// All quantities are SI.
#pragma once

#include <algorithm>
#include <cmath>

#include <cstdint>
#include <string>
#include <vector>

#include "sim/env/geometry.h"

namespace vascsim {

// The vascular-mimicking environment: a generated perfect maze (paper II.A) or explicit walls.
struct MazeSpec {
  bool explicit_walls = false;  // true: `walls` below; false: generate rows x cols from `seed`
  int rows = 5;
  int cols = 5;
  double width = 1.0;          // m, x extent
  double height = 1.0;         // m, y extent
  double lumen_width = 0.1;    // m, channel width; wall thickness = cell pitch - lumen width
  std::uint64_t seed = 1;      // maze generator seed
  // Explicit environment (scenes/paper_maze.json): segments with a thickness, start and goal.
  std::vector<WallSegment> walls;
  Vec2 start = Vec2(0.9, 0.9);  // m, used with explicit walls; generated mazes use cell centres
  Vec2 goal = Vec2(0.1, 0.1);   // m
  double grid_pitch = 0.2;      // m, cell size of the explicit-walls path grid
};

// A vessel network (issue 12), the alternative to a maze: a centreline graph of named nodes and
// segments, each a tube whose radius tapers linearly between the points where it is given, with
// stenoses and aneurysm sacs on segments; or a binary image of the lumen (`mask`). The lumen is the
// union of the tubes and sacs (sim/env/vessel_lumen.h). Conventions: docs/environment.md.
struct VesselNodeSpec {
  std::string name;
  Vec2 position = Vec2::Zero();  // m
};
// A local narrowing centred `at` metres along the segment from its `from` node: the radius falls
// smoothly (a raised cosine over `length`) to `fraction` of the tube's radius there.
struct StenosisSpec {
  double at = 0.0;        // m, arc length from the segment's first node
  double length = 0.1;    // m, the whole narrowed stretch
  double fraction = 0.5;  // -, radius left at the centre (0.5: a 50 % narrowing)
};
// A saccular aneurysm: a disc of `radius` beside the segment, `at` metres along it, on the `left`
// (or right, looking from the first node) side, overlapping the tube so that its mouth (the neck)
// is `neck` metres wide where it crosses the tube's wall.
struct AneurysmSpec {
  double at = 0.0;      // m, arc length from the segment's first node
  bool left = true;     // side, looking along the segment
  double radius = 0.1;  // m
  double neck = 0.05;   // m, width of the opening, <= 2 radius
};
struct VesselSegmentSpec {
  std::string from, to;           // node names
  std::vector<Vec2> via;          // m, interior centreline points, in order
  // m: two values (at from and to, tapering linearly with arc length) or one per point
  // (from, every via point, to).
  std::vector<double> radius;
  std::vector<StenosisSpec> stenoses;
  std::vector<AneurysmSpec> aneurysms;
};
// A lumen traced from an image: white lumen on black, greyscale thresholded (sim/env/vessel_mask.h).
struct VesselMaskSpec {
  std::string file;          // PNG path as written in the scene (resolved against the scene's folder)
  std::string resolved;      // the path opened (set by the scene reader)
  double pixel_size = 1e-3;  // m, edge of one pixel
  double threshold = 0.5;    // -, grey level (0 black .. 1 white) at the lumen's boundary
  Vec2 start = Vec2::Zero(); // m, from the image's bottom-left corner
  Vec2 goal = Vec2::Zero();  // m
  // The image as read (by the scene reader): grey levels 0..255, row-major, row 0 at the top.
  int width = 0, height = 0;  // px
  std::vector<std::uint8_t> grey;
  std::string pixel_hash;  // of the size and grey levels (set by the scene reader; io::mask_pixel_hash)
};
struct VesselsSpec {
  bool from_mask = false;  // true: `mask`; false: the graph below
  std::vector<VesselNodeSpec> nodes;
  std::vector<VesselSegmentSpec> segments;
  std::string start, goal;          // node names; start must end one segment only (the inlet)
  std::vector<std::string> route;   // node names start..goal; empty: the shortest route
  VesselMaskSpec mask;
};
enum class EnvironmentKind { kMaze, kVessels };

enum class PathSolver { kWallFollower, kBreadthFirst };

// The ideal trajectory: lumen centreline from start to goal, traversed at constant speed.
struct PathSpec {
  PathSolver solver = PathSolver::kWallFollower;
  // m, 0 keeps sharp corners. Vessel scenes: a cap on what each corner's lumen allows, by default
  // none (infinity, which the canonical scene leaves out).
  double corner_radius = 0.05;
  double speed = 0.05;          // m/s, tip reference speed along the path
  double ramp_time = 0.0;       // s, from rest to `speed` and back to rest at the end; 0: the
                                // paper's constant speed from t = 0 (trajectory.h)
};

// The robot: a hollow circular PDMS rod, paper Table I.
struct RodSpec {
  int nodes = 50;
  double length = 0.5;            // m
  double outer_radius = 2e-3;     // m
  double inner_radius = 1e-3;     // m
  double youngs_modulus = 1.47e6; // Pa
  double poisson_ratio = 0.48;    // -, for the shear modulus G = E / (2 (1 + nu)) (0.497 MPa)
  double density = 980.0;         // kg/m^3
};

// Initial and rest shape of the rod (sim/rod/rod_model.cpp places the nodes). The rod starts at
// `start` (the root; the clamp centre with a centred clamp), its first edge heading along
// `direction`, and is an arc of `initial_curvature` (0: straight; large values coil it or fold
// it back on itself).
struct ShapeSpec {
  Vec2 start = Vec2(0.0, 0.0);     // m, root of the rod
  double direction = 0.0;          // rad, heading of the first edge, from +x counter-clockwise
  double initial_curvature = 0.0;  // 1/m, positive turns left
  double rest_curvature = 0.0;     // 1/m, natural curvature of the unloaded rod
};

// Kinematic boundary conditions. Node indices count from 0 at the root; negative ones from the
// tip (-1 is the tip node).
enum class ClampKind {
  kNone,
  kFirstEdge,  // nodes 0 and 1 fixed, node 0 at the root (first-order accurate, docs/references.md section 0)
  kCentred,    // nodes 0 and 1 fixed at -dl/2 and +dl/2 about the root; edge dl = L/(N-1.5)
};
// x(t) = x(0) + velocity t + amplitude sin(2 pi frequency t): a node driven kinematically.
struct PrescribedMotionSpec {
  int node = -1;
  Vec2 velocity = Vec2::Zero();   // m/s
  Vec2 amplitude = Vec2::Zero();  // m
  double frequency = 0.0;         // Hz
};
// A node held in one coordinate at its initial value, free in the other: a roller on a
// horizontal guide holds y (axis kY), a slider in a vertical slot holds x (axis kX).
enum class SupportAxis { kX, kY };
struct SupportSpec {
  int node = -1;
  SupportAxis axis = SupportAxis::kY;  // the coordinate held
};
struct BoundarySpec {
  ClampKind clamp = ClampKind::kNone;
  std::vector<int> pinned;  // nodes held at their initial position (free to rotate)
  std::vector<SupportSpec> supports;
  std::vector<PrescribedMotionSpec> prescribed;
  bool empty() const { return clamp == ClampKind::kNone && pinned.empty() && supports.empty() && prescribed.empty(); }
};

// Loads. Each kind is a force module that exists in the Model only when switched on.
enum class LoadProfile {
  kConstant,
  kRamp,  // value * min(1, t / ramp_time)
  kSine,  // value * sin(2 pi frequency t + phase)
};
// A dead force on a node and/or a dead moment on the edge ending at the node (edge 0 for node 0).
struct PointLoadSpec {
  int node = -1;
  Vec2 force = Vec2::Zero();  // N
  double moment = 0.0;        // N m, counter-clockwise
  LoadProfile profile = LoadProfile::kConstant;
  double ramp_time = 1.0;     // s
  double frequency = 1.0;     // Hz
  double phase = 0.0;         // rad
};
struct GravitySpec {
  bool enabled = false;  // off: the maze lies in the horizontal plane
  Vec2 acceleration = Vec2(0.0, -9.81);  // m/s^2
};
// f_i = -coefficient * dl_i * v_i (dl_i the node's Voronoi length).
struct DampingSpec {
  bool enabled = false;
  double coefficient = 0.0;  // N s/m^2, per metre of rod
};
enum class DragArea {
  kNodes,        // every node, broadside projected area 2 r_o dl_i
  kTipFrontal,   // the tip node only, frontal area pi r_o^2 (the paper)
};
// Quadratic fluid drag f = -1/2 rho |v| v A Cd (paper II.C), with its Jacobian in Newton.
struct DragSpec {
  bool enabled = false;
  double fluid_density = 1025.0;    // kg/m^3, blood
  double drag_coefficient = 1.0536; // -, paper; with kNodes the cross-flow (normal) coefficient
  // -, kNodes only: flow along the rod's axis, referred to the same area 2 r_o dl_i. About pi times
  // the laminar skin-friction coefficient 1.328 / sqrt(Re_L) of a 0.5 m rod at 0.05 m/s in blood
  // (Re_L ~ 7000, Cf ~ 0.016): a catheter slides along its axis far more easily than sideways.
  double tangential_coefficient = 0.05;
  DragArea area = DragArea::kNodes;
};
// A magnet on the distal edge in a uniform field set by the scene, with no controller: the basic
// experiment of magnetic-rod papers (tip angle against field angle and strength). The field has
// strength B(t) = field * min(1, t / ramp_time) (ramp_time 0: constant) and direction
// angle + rotation_rate * t from +x. A uniform field exerts no net force, only the torque
// m x B on the magnet, whose moment points along the distal edge.
struct MagnetSpec {
  bool enabled = false;
  double moment = 0.01;        // A m^2
  double field = 0.01;         // T
  double angle = 1.5707963267948966;  // rad, from +x, counter-clockwise
  double ramp_time = 0.0;      // s
  double rotation_rate = 0.0;  // rad/s
  Vec2 field_at(double t) const;  // T
};
inline Vec2 MagnetSpec::field_at(double t) const {
  const double strength = ramp_time > 0.0 ? field * std::min(1.0, std::max(0.0, t) / ramp_time) : field;
  const double a = angle + rotation_rate * t;
  return strength * Vec2(std::cos(a), std::sin(a));
}
// A lumped body on a node: extra mass (e.g. the tip magnet's) with its own drag, linear
// (Stokes: a bead in a viscous fluid, 6 pi mu r) and/or quadratic (1/2 rho Cd A at higher
// Reynolds numbers): f = -linear_drag v - quadratic_drag |v| v. Its mass also feels gravity.
struct BodySpec {
  int node = -1;
  double mass = 0.0;            // kg
  double linear_drag = 0.0;     // N s/m
  double quadratic_drag = 0.0;  // kg/m
};
struct LoadSpec {
  GravitySpec gravity;
  DampingSpec damping;
  DragSpec drag;
  std::vector<PointLoadSpec> point_loads;
  MagnetSpec magnet;
  std::vector<BodySpec> bodies;
};

// Time integration and Newton settings. A preset fills the scheme, the step control and the
// tolerances (docs/accuracy.md measured the trade); fields given in the scene override the preset.
enum class Scheme { kBackwardEuler, kBdf2 };
enum class SolveMode { kDynamic, kStatic };
// How the step size is chosen (docs/solver.md, "Step size"):
enum class StepControl {
  kError,  // from a local error estimate against rtol/atol (PI controller); Newton failures retry smaller
  kRetry,  // fixed dt; a step whose Newton fails is retried with dt/2, down to dt / 2^max_halvings
  kOff,    // fixed dt; a failed step ends the run
};
struct SolverSpec {
  SolveMode mode = SolveMode::kDynamic;  // static: load-stepped equilibrium under the loads at t = 0
  std::string preset = "balanced";       // "fast", "balanced", "accurate"
  Scheme scheme = Scheme::kBdf2;
  StepControl adaptive = StepControl::kRetry;
  double dt = 1e-3;                      // s: the step (kRetry, kOff); the first step (kError)
  // kError: a step is accepted when every integrated degree of freedom's estimated local error is
  // within atol + rtol * scale (positions: m, scale the rod length; velocities: m/s, scale the
  // largest node speed at either end of the step).
  double rtol = 1e-4;                    // -
  double atol_position = 1e-6;           // m
  double atol_velocity = 1e-5;           // m/s
  double dt_min = 1e-8;                  // s, kError: a step that needs less fails the run
  // s, kError: no step is chosen shorter; a step at the floor is kept whatever its error (counted:
  // summary.json warnings.step_over_tolerance). 0: no floor.
  double dt_floor = 0.0;
  // s and steps, kError: a floor on the mean step. Steps shorter than dt_mean_min are taken only
  // while the run has credit (at most mean_burst steps, earned by longer steps), so no stretch of
  // T seconds takes more than T / dt_mean_min + mean_burst steps; without credit dt_mean_min is
  // the floor. 0: none. The presets set both floors, so an undamped rod rattling on a wall has a
  // bounded cost while brief impacts are resolved (sim/step/step_budget.h, docs/accuracy.md).
  double dt_mean_min = 0.0;
  double mean_burst = 0.0;
  double dt_max = 0.02;                  // s, kError: largest step (breakpoints also end steps; frames are interpolated)
  // kError: Newton also stops when its next correction, estimated with the last factorisation
  // and then applied, is within this share of the step's error tolerance in every position and
  // implied velocity (CVODE's test; sim/step/newton.cpp). 0: the residual test alone.
  double newton_stop_share = 0.3;
  double rel_tol = 1e-6;                 // Newton: |residual|_inf <= rel_tol * force scale
  double abs_tol = 0.0;                  // N, Newton: or |residual|_inf <= abs_tol (0: off)
  double step_tol = 1e-12;               // Newton: or |dx|_inf <= step_tol * rod length (round-off)
  int max_iterations = 25;
  int max_halvings = 10;                 // Newton failures: retries with half the step
  int load_steps = 10;                   // static mode: initial number of load increments
  bool stable_branch = true;             // static mode: leave an unstable equilibrium for a stable one
};
// The named presets (docs/accuracy.md, "Presets", measured the choice): error-controlled steps
// with floors, so a traversal takes long steps where the rod glides and resolves its impacts
// down to the hard floor (the preset's old fixed step), while the mean floor bounds what rattling
// can cost. A SolverSpec built in code without a preset keeps the fixed
// step above (kRetry, dt 1e-3); scenes read from files always get a preset, "balanced" by default.
inline bool apply_solver_preset(const std::string& name, SolverSpec& s) {
  s.scheme = Scheme::kBdf2;
  s.adaptive = StepControl::kError;
  s.atol_position = 1e-6;
  s.dt_max = 0.02;
  if (name == "fast") { s.dt = s.dt_floor = 4e-3; s.dt_mean_min = 1e-2; s.rtol = 5e-4; s.atol_velocity = 1e-3; s.rel_tol = 1e-4; }
  else if (name == "balanced") { s.dt = s.dt_floor = 1e-3; s.dt_mean_min = 3e-3; s.rtol = 5e-5; s.atol_velocity = 1e-3; s.rel_tol = 1e-5; }
  else if (name == "accurate") { s.dt = s.dt_floor = 2.5e-4; s.dt_mean_min = 7e-4; s.rtol = 1e-5; s.atol_velocity = 1e-4; s.rel_tol = 1e-8; s.dt_max = 5e-3; }
  else return false;
  // Credit for 10 s of simulated time below the mean floor: enough for the impacts of the damped
  // traversal (maze_body_drag keeps the error it has without a mean floor), not for an undamped
  // body's rattling, whose cost it bounds.
  s.mean_burst = 10.0 / s.dt_mean_min;
  s.preset = name;
  return true;
}

// Tip actuation and trajectory following (paper II.C, III.A-B, Algorithm 1). The tip is the last
// rod node; the controller acts only in scenes with a maze.
enum class ActuationMode {
  kNone,       // no tip actuation (a catheter only pushed from its root: control.advance)
  kForce,      // default: magnetic force = feedforward + PD on the tip node(s); the tip moves by dynamics
  kKinematic,  // the paper: the controller's output position is imposed on the tip node
  kField,      // a tip magnet in a uniform field: the field turns the tip (torque m x B), its gradient pulls
};
enum class DisturbanceKind { kForce, kPosition };
// d(t) = amplitude sin(omega t) along `direction` (paper: "2 sin(5 t)"; see docs/navigation.md).
struct DisturbanceSpec {
  DisturbanceKind kind = DisturbanceKind::kForce;
  double amplitude = 2e-3;                         // N (force) or m (position); 0 switches it off
  double omega = 5.0;                              // rad/s
  Vec2 direction = Vec2(0.7071067811865476, 0.7071067811865476);  // unit vector
};
// Proximal advancement, as a catheter drive feeds the rod through the inlet: its first two nodes
// are held and moved along the inlet's direction by the fed length s(t), piecewise linear
// through `points` (t in s, strictly increasing; s in m), constant before the first and after
// the last. The drive's axial force on the rod is logged (feed/force) and summarised.
struct AdvanceSpec {
  std::vector<std::pair<double, double>> points;  // (s, m)
  bool enabled() const { return !points.empty(); }
  double fed_length(double t) const;  // m
  double speed(double t) const;       // m/s, ds/dt (the right-hand one at a corner)
};
inline double AdvanceSpec::fed_length(double t) const {
  if (points.empty()) return 0.0;
  if (t <= points.front().first) return points.front().second;
  for (std::size_t k = 1; k < points.size(); ++k)
    if (t < points[k].first) {
      const auto& [t0, s0] = points[k - 1];
      const auto& [t1, s1] = points[k];
      return s0 + (s1 - s0) * (t - t0) / (t1 - t0);
    }
  return points.back().second;
}
inline double AdvanceSpec::speed(double t) const {
  for (std::size_t k = 1; k < points.size(); ++k)
    if (t >= points[k - 1].first && t < points[k].first)
      return (points[k].second - points[k - 1].second) / (points[k].first - points[k - 1].first);
  return 0.0;
}
struct ControlSpec {
  ActuationMode mode = ActuationMode::kForce;
  AdvanceSpec advance;
  double kp = 4.0;               // force mode: N/m; kinematic mode: - (fraction of the error corrected)
  double kd = 0.4;               // force mode: N s/m; kinematic mode: s (the reader defaults it to 0 there)
  int actuated_nodes = 1;        // 1..3: force spread over this many nodes from the tip (the magnet's length)
  double magnet_moment = 1e-3;   // A m^2, field mode: tip dipole along the tip tangent (m B L / EI ~ 0.6)
  double field_strength = 0.02;  // T, field mode: |B|
  double lead_time = 0.0;        // s, the reference starts this long after the run starts
  DisturbanceSpec disturbance;
};

// Wall contact on every node and edge, at the rod's outer radius (paper II.D, V.B).
enum class ContactMode {
  kNone,
  kImplicit,  // default: IPC barrier inside Newton (sim/contact/barrier.h); never penetrates
  kPaper,     // the paper's iterative penalty: push nodes out by K_f times their depth until none is inside
};
struct ContactSpec {
  ContactMode mode = ContactMode::kImplicit;
  double activation_distance = 0.0;  // m, barrier g_hat; 0: a quarter of the outer radius
  double stiffness = 0.0;            // N, barrier kappa; 0: from the rod's bending stiffness (docs/contact.md)
  double friction = 0.0;             // -, Coulomb coefficient mu (0: frictionless)
  double slip_velocity = 1e-4;       // m/s, friction regularisation: below it friction grows linearly
  double paper_gain = 50.0;          // N/m, K_f of the paper's penalty, per iteration
  int paper_iterations = 50;         // cap on the paper's push-out iterations per step
  bool self = false;                 // rod self-contact (implicit barrier between distant edges), any scene
};

// Output of a run.
struct RunSpec {
  double duration = 10.0;         // s, simulated time
  // A maze scene that names no duration runs until the reference reaches the goal plus
  // kSettleTime (set by the scene reader, resolved by prepare_navigation).
  bool duration_from_path = false;
  static constexpr double kSettleTime = 2.0;  // s
  // s, the duration a run uses when its reference takes path_duration (s).
  double duration_for(double path_duration) const { return duration_from_path ? path_duration + kSettleTime : duration; }
  double output_interval = 0.01;  // s, time between logged frames, >= kMinOutputInterval
  static constexpr double kMinOutputInterval = 1e-6;  // s
};

// A field of the scene file that the scene's own configuration does not use (sim/scene/unused_fields.h).
struct UnusedField {
  std::string pointer;  // JSON pointer of the field, e.g. "/contact/friction"
  std::string why;      // the setting that leaves it unused, e.g. "contact.mode is \"paper\" (...)"
};

struct Scene {
  std::string file;  // where it was read from, for messages; empty for built-in scenes
  std::string name = "scene";
  bool has_environment = true;  // false for scenes in free space ("maze": null), e.g. validation problems
  EnvironmentKind environment = EnvironmentKind::kMaze;  // which of the two below
  MazeSpec maze;
  VesselsSpec vessels;
  PathSpec path;
  RodSpec rod;
  RunSpec run;
  ControlSpec control;
  ContactSpec contact;
  ShapeSpec shape;
  BoundarySpec boundary;
  LoadSpec loads;
  SolverSpec solver;
  // Fields the file gave that this configuration does not use (set by the scene reader, which
  // warns of them; the canonical text never holds them).
  std::vector<UnusedField> unused_given;
};

}  // namespace vascsim

// A run: the loop that advances a State through simulated time, sets the controller's inputs
// before each step, records frames at the output interval and keeps the statistics that
// summary.json reports. It owns no files: frames go to a FrameSink (the command line connects a
// FrameLogWriter), so the loop is testable in memory and the stepper stays free of I/O.
#pragma once

#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/log/frame_log.h"
#include "sim/run/navigation.h"
#include "sim/step/model.h"
#include "sim/step/local_error.h"
#include "sim/step/newton.h"
#include "sim/step/step_budget.h"
#include "sim/step/step_size_controller.h"
#include "sim/step/stepper.h"

namespace vascsim {

// Receives each recorded frame: its time and the values of Run::channels() in order.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void write(double time, const std::vector<double>& values) = 0;
};

// A condition worth knowing that did not stop the run (MuJoCo's mjData.warning): how often, and
// when first. Reported in summary.json rather than printed and lost.
struct WarningCount {
  int count = 0;
  double first_time = std::numeric_limits<double>::quiet_NaN();  // s, start of the step (static: 1)
  void note(double t, int times = 1) {
    if (count == 0) first_time = t;
    count += times;
  }
};

struct RunWarnings {
  WarningCount newton_round_off;      // steps whose Newton stopped at round-off, not at rel_tol
  WarningCount step_retried;          // steps that needed a smaller dt (see rejected_steps)
  WarningCount unresolved_step;       // solver.adaptive "off": steps kept that jumped (a saddle, an edge turned > 0.5 rad)
  WarningCount step_over_tolerance;   // error control: steps at a floor (dt_floor, dt_mean_min) kept over the tolerance
  WarningCount paper_contact_cap;     // paper contact: steps that hit contact.paper_iterations unsettled
  WarningCount unstable_equilibrium;  // static mode: the equilibrium found is unstable
  WarningCount load_path_jumped;      // static mode: increments could not follow the stable branch and jumped
  WarningCount left_unstable;         // static mode: the load path's was, and the solve left it for a stable one
  WarningCount stability_undecided;   // static mode: the stiffness's eigenvalue nearest zero is within its round-off
  WarningCount large_axial_strain;    // frames with an edge stretched or squashed past kLargeAxialStrain
};

// An edge's axial strain |l / l0 - 1| past which the rod is warned of: a drive or load stronger
// than the rod (a catheter fed hard into a dead end was squashed to 40 % of its length), past
// what its linear stretching model and a real catheter bear.
constexpr double kLargeAxialStrain = 0.1;

struct RunStatistics {
  int steps = 0;
  long long newton_iterations = 0;   // of the committed steps' accepted solves
  // Every iteration the run did: also those of attempts retried shorter (Newton failure or error
  // control) and of the paper contact's re-solves. The run's cost is in these.
  long long newton_iterations_all = 0;
  int newton_iterations_max = 0;     // in one step
  int rejected_steps = 0;            // attempts retried with a smaller dt (Newton failed)
  int error_rejected_steps = 0;      // error control: converged steps over the tolerance, retried shorter
  int steps_cut_to_frames = 0;       // error control: steps retried to end on a frame that interpolation would put into a wall
  double error_max = 0.0;            // error control: largest accepted error estimate / tolerance (above the floor)
  double error_max_at_floor = 0.0;   // error control: the same of the steps kept over the tolerance at the floor
  double dt_min = std::numeric_limits<double>::infinity();  // s, shortest step taken
  double dt_max = 0.0;               // s, longest step taken
  std::size_t frames = 0;
  double axial_strain_max = 0.0;     // largest |l / l0 - 1| of an edge in a recorded frame
  double simulated_time = 0.0;       // s
  double wall_time = 0.0;            // s
  bool failed = false;
  std::string failure;
  // Who ended the run before its duration (Run::run's `stop_reason`, e.g. "SIGINT (Ctrl-C)"):
  // then `failed`, and the frames end where it stopped, not where the physics did.
  std::string stopped_by;
  // Navigation scenes only.
  bool goal_reached = false;
  double goal_time = std::numeric_limits<double>::quiet_NaN();  // s
  double tip_error_rms = 0.0;        // m, over all steps
  double tip_error_max = 0.0;        // m
  double actuation_force_max = 0.0;  // N, |magnetic force| on the tip
  double actuation_force_mean = 0.0; // N
  double feed_force_max = 0.0;       // N, control.advance: |the drive's push along the inlet|
  double feed_force_mean = 0.0;      // N, its time average
  double contact_force_max = 0.0;    // N, largest per-node wall force
  double min_gap = std::numeric_limits<double>::infinity();  // m, rod surface to wall surface
  double max_penetration = 0.0;      // m, max(0, -min_gap)
  std::vector<double> contact_time;  // (N), s, time each node spent touching a wall
  int paper_contact_iterations_max = 0;
  RunWarnings warnings;
};

class Run {
 public:
  // A run of a compiled model (sim/run/compile.h), which it shares and never changes.
  explicit Run(std::shared_ptr<const Model> model);

  // Frame log channels this run records, in order.
  const std::vector<LogChannel>& channels() const { return channels_; }
  const Model& model() const { return *model_; }
  const Scene& scene() const { return model_->scene; }
  const State& state() const { return state_; }
  const Navigation* navigation() const { return model_->navigation.get(); }
  const RunStatistics& statistics() const { return stats_; }
  // The frames a run that completes writes: 2 for a static solve; else t = 0, every output
  // interval, and one at the duration if it falls between two (as output_time spaces them).
  double planned_frames() const;

  // Runs until scene.run.duration (or the first failure), writing a frame at t = 0 and every
  // output interval. `progress` (may be empty) is called after each frame with t.
  // Returns false if the simulation failed; the statistics say why, and every frame computed
  // before the failure has been written.
  // In static mode (scene solver.mode) it instead records the unloaded rod at t = 0 and the
  // equilibrium under the full loads at t = 1 (time stands for the load scale).
  // `stop_reason` (may be empty) is asked between steps; a non-empty answer (who asks, e.g.
  // "SIGINT (Ctrl-C)") ends the run there as a failure that statistics().stopped_by names, with
  // every frame computed so far written. A static solve asks before each load increment.
  bool run(FrameSink& sink, const std::function<void(double t)>& progress = {},
           const std::function<std::string()>& stop_reason = {});

 private:
  // The controller's inputs for the next step (remembers the command for the log).
  Controls controls_for_step(double dt);
  // One converged step of dt (Newton retries may shorten it), not yet counted; false (the run's
  // failure recorded) if it could not be taken.
  bool attempt(double dt, Controls& controls, StepReport& report);
  // Counts the step just taken in the statistics.
  void commit(const StepReport& report, const Controls& controls);
  bool advance(double dt);
  double advance_controlled(double dt, std::size_t next_frame);
  double shortest_step() const;  // s, error control: the shortest step allowed now (dt_min or a floor)
  // s, the time of frame `frame` (0: the start); the last is at the run's duration.
  double output_time(std::size_t frame) const;
  // Error control: whether every frame from `frame` on that falls inside the step just taken
  // (from `start` to state_) can be interpolated, that is, keeps every barrier's gap open.
  bool frames_interpolable(const State& start, const Controls& controls, std::size_t frame) const;
  NewtonStopTolerance newton_stop() const;
  bool solve_equilibrium(FrameSink& sink, const std::function<std::string()>& stop_reason);
  // Writes a frame: state_ itself or a state inside the last step (error control).
  void record(FrameSink& sink, const State& frame);
  // Force channel `name` (one of force_channels_) at a solved state (state_ or step_start_), with
  // the controls of the step that ended there. Cached for the newest two states, so that the
  // statistics and the frames evaluate each channel once per step end.
  const Eigen::VectorXd& solved_force(const std::string& name, const State& at, const Controls& controls);
  void update_statistics(double dt, const Controls& controls);
  double feed_force() const;  // N, control.advance
  // A navigation run whose tip is driven (control.mode other than "none").
  bool tip_controlled() const { return navigation_ && scene_.control.mode != ActuationMode::kNone; }
  // The force of every module writing channel `name` at a solved state `at` (state_ or step_start_).
  Eigen::VectorXd channel_force(const std::string& name, const Controls& controls, const State& at) const;
  // What the log and the statistics report for channel `name`: the modules' force, with the
  // actuation's own estimate for the magnetic force where it has no module.
  Eigen::VectorXd logged_force(const std::string& name, const Controls& controls, const State& at) const;

  std::shared_ptr<const Model> model_;
  const Scene& scene_;            // model_->scene
  const Navigation* navigation_;  // model_->navigation, or null
  std::optional<TipController> controller_;
  std::optional<StepSizeController> step_size_;      // error control only
  std::optional<StepBudget> step_budget_;            // error control only
  LocalErrorWeights error_weights_;
  std::vector<double> breakpoints_;                  // s, error control: where the reference's velocity or acceleration jumps
  State state_;
  State step_start_;                                 // error control: where the last step started, for frames inside it
  Controls step_start_controls_;                     // error control: the controls of the step that ended at step_start_
  State attempt_start_;                              // error control: where the step being tried started
  State paper_start_;                                // paper contact: where the step being re-solved started
  NewtonWarmStart paper_warm_start_;                 // paper contact: where the last re-solve of the step ended
  struct SolvedForces {
    double t = 0.0;                         // s
    std::vector<Eigen::VectorXd> channels;  // by force_channels_ index, empty until evaluated; none: unused entry
  };
  SolvedForces solved_forces_[2];
  Workspace workspace_;
  std::vector<LogChannel> channels_;
  std::vector<std::string> force_channels_;          // distinct module channels, in log order
  std::vector<NodeForce> wall_forces_;               // paper contact mode, carried between steps
  TipCommand last_command_;
  Controls last_controls_;                           // of the last committed step, for the frames
  RunStatistics stats_;
  double error_square_time_ = 0.0;                   // m^2 s
  double actuation_time_ = 0.0;                      // N s
  double feed_impulse_ = 0.0;                        // N s
  double feed_force_at_step_start_ = 0.0;            // N, feed_force() solved at step_start_ (0 before any step)
  double feed_force_at_step_end_ = 0.0;              // N, and at state_
};

}  // namespace vascsim

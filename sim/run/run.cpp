#include "sim/run/run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/contact/paper_contact.h"
#include "sim/contact/wall_contact.h"
#include "sim/log/channel_names.h"
#include "sim/step/dense_output.h"
#include "sim/step/local_error.h"
#include "sim/step/statics.h"
#include "sim/step/stepper.h"

namespace vascsim {

namespace {

using Clock = std::chrono::steady_clock;

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The edge stretched or squashed the most: its index and its strain l / l0 - 1.
struct EdgeStrain {
  Eigen::Index edge = 0;
  double strain = 0.0;
};
EdgeStrain largest_axial_strain(const RodModel& rod, const Eigen::VectorXd& x) {
  EdgeStrain largest;
  for (Eigen::Index e = 0; e < rod.rest_length.size(); ++e) {
    const double strain = (x.segment<2>(2 * e + 2) - x.segment<2>(2 * e)).norm() / rod.rest_length[e] - 1.0;
    if (std::abs(strain) > std::abs(largest.strain)) largest = {e, strain};
  }
  return largest;
}

}  // namespace

Run::Run(std::shared_ptr<const Model> model)
    : model_(std::move(model)),
      scene_(model_->scene),
      navigation_(model_->navigation.get()),
      state_(initial_state(*model_)),
      workspace_(*model_) {
  const int n = model_->nodes();
  if (model_->solver.adaptive == StepControl::kError) {
    step_size_.emplace(model_->solver.dt_max);
    step_budget_.emplace(model_->solver.dt_floor, model_->solver.dt_mean_min, model_->solver.mean_burst);
    error_weights_ = {model_->solver.rtol, model_->solver.atol_position, model_->solver.atol_velocity, scene_.rod.length};
  }
  if (navigation_) {
    controller_.emplace(scene_.control, *navigation_->trajectory, navigation_->plant);
    stats_.contact_time.assign(static_cast<std::size_t>(n), 0.0);
    // A step ends 1 ns before each jump: forces are evaluated at the step's end, which must still
    // see the values before it; the next step, starting afresh, sees those after.
    if (step_size_) {
      for (const double b : navigation_->trajectory->breakpoints())
        if (b + scene_.control.lead_time > 2e-9) breakpoints_.push_back(b + scene_.control.lead_time - 1e-9);
      for (const auto& point : scene_.control.advance.points)  // the feed's speed jumps there
        if (point.first > 2e-9) breakpoints_.push_back(point.first - 1e-9);
      std::sort(breakpoints_.begin(), breakpoints_.end());
      // Two jumps at one time (the reference's ramp ending as the feed stops) are one breakpoint:
      // a second would ask for a step of length 0.
      breakpoints_.erase(std::unique(breakpoints_.begin(), breakpoints_.end(),
                                     [](double a, double b) { return b - a < 2e-9; }),
                         breakpoints_.end());
    }
  }
  const std::uint32_t node_values = static_cast<std::uint32_t>(2 * n);
  channels_.push_back({channel::kPosition, "m", ChannelLayout::kNodeVectors, node_values});
  channels_.push_back({channel::kVelocity, "m/s", ChannelLayout::kNodeVectors, node_values});
  for (const auto& f : model_->forces)
    if (!contains(force_channels_, f->channel())) force_channels_.push_back(f->channel());
  // Every run that steers its tip logs the magnetic force, also when its actuation has no force
  // module; a run that does not (control.mode "none": a catheter only pushed from its root) logs
  // no magnetic force, target or tracking error, which would only be zeros and a distance to a
  // target nothing follows.
  if (tip_controlled() && !contains(force_channels_, channel::kActuationForce))
    force_channels_.push_back(channel::kActuationForce);
  for (const auto& name : force_channels_) channels_.push_back({name, "N", ChannelLayout::kNodeVectors, node_values});
  if (tip_controlled()) {
    channels_.push_back({channel::kTipReference, "m", ChannelLayout::kVector, 2});
    channels_.push_back({channel::kTipError, "m", ChannelLayout::kScalars, 1});
  }
  if (navigation_ && scene_.control.advance.enabled()) {
    channels_.push_back({channel::kFeedForce, "N", ChannelLayout::kScalars, 1});
    channels_.push_back({channel::kFeedLength, "m", ChannelLayout::kScalars, 1});
  }
}

Controls Run::controls_for_step(double dt) {
  Controls controls;
  controls.time = state_.t;
  if (!controller_) return controls;
  const int tip = model_->nodes() - 1;
  last_command_ = controller_->command(state_.t, dt, state_.position(tip), state_.velocity(tip));
  ActuationStep step;
  step.dt = dt;
  step.nodes = model_->nodes();
  step.tip = state_.position(tip);
  step.tip_offset = controller_->position_disturbance(state_.t + dt);
  navigation_->actuation->set_controls(last_command_, step, controls);
  controls.wall_forces = wall_forces_;
  return controls;
}

bool Run::attempt(double dt, Controls& controls, StepReport& report) {
  const double t_start = state_.t;  // warnings are dated by the step's start
  controls = controls_for_step(dt);
  if (navigation_ && navigation_->paper_walls) {
    // The paper's contact: re-solve the step with updated wall forces until no node is inside.
    // Its start is copied into a member that keeps its storage.
    State& start = paper_start_;
    start = state_;
    int rejected = 0;  // over all the re-solves
    for (int k = 1;; ++k) {
      report = step(*model_, state_, workspace_, controls, dt, newton_stop(), k > 1 ? &paper_warm_start_ : nullptr);
      stats_.newton_iterations_all += report.total_iterations;
      rejected += report.rejected;
      if (!report.ok) break;
      const PaperContactUpdate u = paper_contact_update(*navigation_->paper_walls, model_->rod.outer_radius, scene_.contact.paper_gain,
                                                        state_.x, wall_forces_);
      stats_.paper_contact_iterations_max = std::max(stats_.paper_contact_iterations_max, k);
      if (u.settled) break;
      if (k >= scene_.contact.paper_iterations) {
        stats_.warnings.paper_contact_cap.note(t_start);
        break;
      }
      paper_warm_start_.x = state_.x;  // the next re-solve starts where this one ended
      paper_warm_start_.dt = report.dt;
      state_ = start;
      controls.wall_forces = wall_forces_;
    }
    report.rejected = rejected;
  } else {
    report = step(*model_, state_, workspace_, controls, dt, newton_stop());
    stats_.newton_iterations_all += report.total_iterations;
  }
  stats_.rejected_steps += report.rejected;
  if (report.rejected > 0) stats_.warnings.step_retried.note(t_start);
  if (!report.ok) {
    stats_.failed = true;
    stats_.failure = report.failure;
    return false;
  }
  if (!state_.x.allFinite() || !state_.v.allFinite()) {
    stats_.failed = true;
    char text[80];
    std::snprintf(text, sizeof text, "the state became non-finite at t = %.9g s", state_.t);
    stats_.failure = text;
    return false;
  }
  if (report.round_off_stop) stats_.warnings.newton_round_off.note(t_start);
  if (report.unresolved) stats_.warnings.unresolved_step.note(t_start);
  return true;
}

void Run::commit(const StepReport& report, const Controls& controls) {
  ++stats_.steps;
  stats_.newton_iterations += report.iterations;
  stats_.newton_iterations_max = std::max(stats_.newton_iterations_max, report.iterations);
  stats_.dt_min = std::min(stats_.dt_min, report.dt);
  stats_.dt_max = std::max(stats_.dt_max, report.dt);
  last_controls_ = controls;
  update_statistics(report.dt, controls);
}

bool Run::advance(double dt) {
  Controls controls;
  StepReport report;
  if (!attempt(dt, controls, report)) return false;
  commit(report, controls);
  return true;
}

// Error control: the step is kept if its estimated local error is within tolerance, otherwise
// the state goes back and a shorter step is tried. `dt` is the step the controller proposed
// (already cut to the next breakpoint); returns the step it proposes next, 0 on failure.
double Run::advance_controlled(double dt, std::size_t next_frame) {
  // Copied into a member that keeps its storage: a State is six vectors, copied at every step.
  State& before = attempt_start_;
  before = state_;
  const std::vector<NodeForce> wall_forces_before = wall_forces_;
  double h = dt;
  for (;;) {
    Controls controls;
    StepReport report;
    if (!attempt(h, controls, report)) return 0.0;
    // A Newton retry may have shortened the step: the estimate uses the step taken.
    const int order = step_order(model_->solver.scheme, before, report.dt);
    // Positions: error per unit step, the tolerance per second of simulated time, so that a run's
    // accumulated error stays near its duration times the tolerance whatever the step count
    // (error per step would let it grow as the tolerance tightens). Velocities: error per step,
    // because theirs carries the solve's own error in x divided by h, which no shorter step
    // reduces (docs/solver.md, "Step size").
    const LocalError local = local_error(before, state_, order, workspace_.fixed, error_weights_);
    const double err = local.estimated() ? std::max(local.position / report.dt, local.velocity) : -1.0;
    // A step no longer than the floor in force is kept whatever its error, and counted: the
    // presets trade resolving an undamped body's every bounce for a bounded cost (docs/accuracy.md).
    const double floor = step_budget_->floor();
    const bool at_floor = report.dt <= floor * (1 + 1e-12);
    if ((err <= 1.0 || at_floor) && !frames_interpolable(before, controls, next_frame)) {
      // A frame inside the step would put the rod into a wall: land on the frame's time instead.
      ++stats_.steps_cut_to_frames;
      h = output_time(next_frame) - before.t;
      state_ = before;
      wall_forces_ = wall_forces_before;
      continue;
    }
    if (err <= 1.0 || at_floor) {
      if (err > 1.0) {
        stats_.warnings.step_over_tolerance.note(before.t);
        stats_.error_max_at_floor = std::max(stats_.error_max_at_floor, err);
      }
      step_start_controls_ = last_controls_;
      commit(report, controls);
      step_budget_->spend(report.dt);
      error_weights_.speed = std::max(error_weights_.speed, state_.v.lpNorm<Eigen::Infinity>());
      if (err <= 1.0) stats_.error_max = std::max(stats_.error_max, err);
      std::swap(step_start_, attempt_start_);
      // The floor after this step: it may have spent the last credit, or earned some.
      return err < 0 ? report.dt : step_size_->accepted(report.dt, err, order, shortest_step());
    }
    if (report.dt <= model_->solver.dt_min * (1 + 1e-12)) {
      stats_.failed = true;
      char message[240];
      std::snprintf(message, sizeof message,
                    "at t = %.9g s the local error is %.3g times the tolerance at the smallest step, solver.dt_min = %.3g s "
                    "(raise the tolerance or lower dt_min)",
                    before.t, err, model_->solver.dt_min);
      stats_.failure = message;
      state_ = before;
      return 0.0;
    }
    ++stats_.error_rejected_steps;
    h = step_size_->rejected(report.dt, err, order, shortest_step());
    state_ = before;
    wall_forces_ = wall_forces_before;
  }
}

NewtonStopTolerance Run::newton_stop() const {
  // The tolerances local_error() holds the step to, scaled by the share (positions: per second).
  if (!step_size_) return {};
  const double share = model_->solver.newton_stop_share;
  const LocalErrorWeights& w = error_weights_;
  return {share * (w.atol_position + w.rtol * w.length), share * (w.atol_velocity + w.rtol * w.speed)};
}

double Run::output_time(std::size_t frame) const {
  return std::min(scene_.run.duration, static_cast<double>(frame) * scene_.run.output_interval);
}

double Run::planned_frames() const {
  if (scene_.solver.mode == SolveMode::kStatic) return 2;
  // The last frame is the first k whose k * interval reaches the duration, found by the product
  // output_time compares, not by the quotient's rounding (0.03 / 0.01 is 2.9999999999999996).
  const double interval = scene_.run.output_interval, duration = scene_.run.duration;
  // A step or two either way at most (bounded: past 2^53 frames an increment changes nothing).
  double last = std::floor(duration / interval);
  for (int k = 0; k < 4 && last * interval < duration; ++k) ++last;
  for (int k = 0; k < 4 && last > 0 && (last - 1) * interval >= duration; ++k) --last;
  return last + 1;
}

bool Run::frames_interpolable(const State& start, const Controls& controls, std::size_t frame) const {
  for (double t_out = output_time(frame); t_out < state_.t * (1.0 - 1e-12); t_out = output_time(++frame)) {
    const State at = interpolate_in_step(start, state_, t_out);
    const ForceContext ctx = ForceContext::at(at, controls);
    for (std::size_t k = 0; k < model_->forces.size(); ++k)
      if (!model_->forces[k]->defined_at(module_context(ctx, workspace_, k))) return false;
  }
  return true;
}

double Run::shortest_step() const { return std::max(model_->solver.dt_min, step_budget_->floor()); }

Eigen::VectorXd Run::channel_force(const std::string& name, const Controls& controls, const State& at) const {
  const ForceContext ctx = ForceContext::at(at, controls);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model_->dofs());
  for (std::size_t k = 0; k < model_->forces.size(); ++k)
    if (model_->forces[k]->channel() == name) model_->forces[k]->add(module_context(ctx, workspace_, k), f, nullptr);
  return f;
}

Eigen::VectorXd Run::logged_force(const std::string& name, const Controls& controls, const State& at) const {
  Eigen::VectorXd f = channel_force(name, controls, at);
  if (navigation_ && name == channel::kActuationForce) navigation_->actuation->logged_force(last_command_, f);
  return f;
}

double Run::feed_force() const {
  // The reactions of the last solve, which is the committed step's: the force the drive's two
  // held nodes exert on the rod, along the inlet (positive: pushing the rod in).
  const Vec2 inward = navigation_->environment.inlet.inward;
  return (workspace_.reaction.segment<2>(0) + workspace_.reaction.segment<2>(2)).dot(inward);
}

void Run::update_statistics(double dt, const Controls& controls) {
  stats_.simulated_time = state_.t;
  if (!navigation_) return;
  if (scene_.control.advance.enabled()) {
    const double f = feed_force();
    feed_force_at_step_start_ = feed_force_at_step_end_;
    feed_force_at_step_end_ = f;
    stats_.feed_force_max = std::max(stats_.feed_force_max, std::abs(f));
    feed_impulse_ += std::abs(f) * dt;
    stats_.feed_force_mean = feed_impulse_ / std::max(state_.t, 1e-300);
  }
  const int n = model_->nodes();
  const Vec2 tip = state_.position(n - 1);
  const double error = (navigation_->trajectory->position(controller_->reference_time(state_.t)) - tip).norm();
  stats_.tip_error_max = std::max(stats_.tip_error_max, error);
  error_square_time_ += error * error * dt;
  stats_.tip_error_rms = std::sqrt(error_square_time_ / std::max(state_.t, 1e-300));
  if (tip_controlled()) {
    // The magnetic force as applied at the end of the step (the servo is implicit).
    const Vec2 actuation = solved_force(channel::kActuationForce, state_, controls).reshaped(2, n).rowwise().sum();
    stats_.actuation_force_max = std::max(stats_.actuation_force_max, actuation.norm());
    actuation_time_ += actuation.norm() * dt;
    stats_.actuation_force_mean = actuation_time_ / std::max(state_.t, 1e-300);
  }
  if (!stats_.goal_reached && (tip - navigation_->environment.goal).norm() <= 0.5 * navigation_->environment.goal_radius) {
    stats_.goal_reached = true;
    stats_.goal_time = state_.t;
  }
  // Contact: gaps, time in contact and the largest per-node wall force.
  // Gaps beyond the barrier's reach are not contact: only pairs within it are visited.
  const double gap = navigation_->contact_geometry->min_pair_gap(
      state_.x, workspace_.shared->of<ContactNeighboursCache>(navigation_->contact_geometry.get()).lists);
  stats_.min_gap = std::min(stats_.min_gap, gap);
  stats_.max_penetration = std::max(stats_.max_penetration, -stats_.min_gap);
  if (!std::isfinite(gap) && !navigation_->paper_walls) return;  // touching nothing: no wall force
  if (!contains(force_channels_, channel::kContactForce)) return;
  const Eigen::VectorXd& wall = solved_force(channel::kContactForce, state_, controls);
  for (int i = 0; i < n; ++i) {
    const double magnitude = wall.segment<2>(2 * i).norm();
    stats_.contact_force_max = std::max(stats_.contact_force_max, magnitude);
    if (magnitude > 0.0) stats_.contact_time[static_cast<std::size_t>(i)] += dt;
  }
}

const Eigen::VectorXd& Run::solved_force(const std::string& name, const State& at, const Controls& controls) {
  SolvedForces* entry = nullptr;
  for (SolvedForces& cached : solved_forces_)
    if (cached.t == at.t && !cached.channels.empty()) entry = &cached;
  if (!entry) {
    // Keep the newest two: the end of one step is the start of the next.
    solved_forces_[0] = std::move(solved_forces_[1]);
    solved_forces_[1] = {at.t, std::vector<Eigen::VectorXd>(force_channels_.size())};
    entry = &solved_forces_[1];
  }
  const std::size_t c = static_cast<std::size_t>(std::find(force_channels_.begin(), force_channels_.end(), name) - force_channels_.begin());
  Eigen::VectorXd& force = entry->channels.at(c);
  if (force.size() == 0) force = logged_force(name, controls, at);
  return force;
}

void Run::record(FrameSink& sink, const State& frame) {
  // A frame inside a step holds its forces interpolated linearly between the step's ends, where
  // they were solved, not evaluated at the interpolated positions: a barrier's force is so steep
  // in the gap that the interpolant's small position error made spikes (74 mN on maze_default
  // at balanced, where no solved state exceeds 19 mN).
  std::vector<double> values;
  values.reserve(channels_.size() * frame.x.size());
  values.insert(values.end(), frame.x.data(), frame.x.data() + frame.x.size());
  values.insert(values.end(), frame.v.data(), frame.v.data() + frame.v.size());
  const bool at_step_end = frame.t == state_.t;
  const double s = at_step_end ? 1.0 : (frame.t - step_start_.t) / (state_.t - step_start_.t);  // share of the step
  for (const std::string& name : force_channels_) {
    if (at_step_end) {
      const Eigen::VectorXd& force = solved_force(name, state_, last_controls_);
      values.insert(values.end(), force.data(), force.data() + force.size());
    } else {
      // Start first, then end: the end stays cached for the next step's start.
      const Eigen::VectorXd start = solved_force(name, step_start_, step_start_controls_);
      const Eigen::VectorXd force = (1.0 - s) * start + s * solved_force(name, state_, last_controls_);
      values.insert(values.end(), force.data(), force.data() + force.size());
    }
  }
  if (tip_controlled()) {
    const Vec2 reference = navigation_->trajectory->position(controller_->reference_time(frame.t));
    values.push_back(reference.x());
    values.push_back(reference.y());
    values.push_back((reference - frame.position(model_->nodes() - 1)).norm());
  }
  if (navigation_ && scene_.control.advance.enabled()) {
    // The drive's reaction, solved at the step's ends, interpolated in between like the forces.
    values.push_back((1.0 - s) * feed_force_at_step_start_ + s * feed_force_at_step_end_);
    values.push_back(scene_.control.advance.fed_length(frame.t));
  }
  sink.write(frame.t, values);
  ++stats_.frames;
  // Checked on the frames, not every step: the strain of a rod pushed too hard builds up slowly.
  const double strain = std::abs(largest_axial_strain(model_->rod, frame.x).strain);
  stats_.axial_strain_max = std::max(stats_.axial_strain_max, strain);
  if (strain > kLargeAxialStrain) stats_.warnings.large_axial_strain.note(frame.t);
}

bool Run::solve_equilibrium(FrameSink& sink, const std::function<std::string()>& stop_reason) {
  const auto wall_start = Clock::now();
  record(sink, state_);
  const StaticReport report = solve_static(*model_, state_, workspace_, last_controls_, stop_reason);
  stats_.steps = report.increments;
  stats_.rejected_steps = report.rejected + report.stability_cuts;
  stats_.newton_iterations = report.iterations;  // of every increment, failed ones too
  stats_.newton_iterations_all = report.iterations;
  stats_.newton_iterations_max = report.iterations;
  if (report.ok && report.negative_pivots > 0) stats_.warnings.unstable_equilibrium.note(1.0);
  if (report.ok && report.left_unstable) stats_.warnings.left_unstable.note(1.0);
  if (report.ok && report.branch_jumps > 0) stats_.warnings.load_path_jumped.note(report.first_jump_load, report.branch_jumps);
  if (report.ok && report.stability_undecided) stats_.warnings.stability_undecided.note(1.0);
  if (report.ok) {
    // The load scale plays the part of time: 0 unloaded, 1 in equilibrium (docs/frame-log.md).
    state_.t = 1.0;
    stats_.simulated_time = state_.t;
    record(sink, state_);
  } else {
    stats_.failed = true;
    stats_.failure = "static equilibrium: " + report.failure;
    stats_.stopped_by = report.stopped_by;
  }
  stats_.wall_time = std::chrono::duration<double>(Clock::now() - wall_start).count();
  return report.ok;
}

bool Run::run(FrameSink& sink, const std::function<void(double)>& progress,
              const std::function<std::string()>& stop_reason) {
  if (model_->solver.mode == SolveMode::kStatic) return solve_equilibrium(sink, stop_reason);
  const auto wall_start = Clock::now();
  const double duration = scene_.run.duration;
  const bool controlled = model_->solver.adaptive == StepControl::kError;
  // Error control: the controller's next step, first the scene's dt (no longer than dt_max).
  double proposed = controlled ? std::min(model_->solver.dt, model_->solver.dt_max) : model_->solver.dt;
  record(sink, state_);
  std::size_t next_frame = 1, next_break = 0;
  bool ok = true, frames_done = false;
  while (state_.t < duration * (1.0 - 1e-12)) {
    if (stop_reason) {
      if (std::string who = stop_reason(); !who.empty()) {
        char text[160];
        std::snprintf(text, sizeof text, "stopped by %s at t = %.6g s, before the run's end (%.6g s)", who.c_str(),
                      state_.t, duration);
        stats_.failed = true;
        stats_.failure = text;
        stats_.stopped_by = std::move(who);
        ok = false;
        break;
      }
    }
    if (!controlled) {
      // Fixed steps land exactly on output times, so that frames are evenly spaced.
      const double h = std::min(proposed, output_time(next_frame) - state_.t);
      if (!advance(h)) {
        ok = false;
        break;
      }
    } else {
      // Error control steps over output times (their frames come from the step's interpolant,
      // sim/step/dense_output.h) but ends a step where the controller's inputs jump
      // (breakpoints_) and at the end of the run, halving the distance rather than leave a sliver.
      while (next_break < breakpoints_.size() && breakpoints_[next_break] <= state_.t * (1.0 + 1e-12)) ++next_break;
      const bool at_break = next_break < breakpoints_.size() && breakpoints_[next_break] < duration;
      const double stop = at_break ? breakpoints_[next_break] : duration;
      const double remaining = stop - state_.t;
      double h = std::min(proposed, remaining);
      if (h < remaining && h > 0.5 * remaining) h = 0.5 * remaining;
      const int rejections = stats_.error_rejected_steps;
      const double next = advance_controlled(h, next_frame);
      if (next <= 0.0) {
        ok = false;
        break;
      }
      // A step cut short (a breakpoint, the end, a frame) does not shrink the ones after it.
      proposed = h < proposed && stats_.error_rejected_steps == rejections ? std::max(next, proposed) : next;
      if (state_.h_prev < 1e-3 * proposed) {
        // A sliver (a step cut to a frame just after a breakpoint) predicts nothing: its
        // difference quotients are round-off. The history starts again after it.
        state_.h_prev = state_.h_prev2 = 0.0;
      }
      if (at_break && state_.t >= stop * (1.0 - 1e-12)) {
        // The history before a jump predicts nothing after it: start again from one step of
        // backward Euler, no longer than the first step of the run.
        ++next_break;
        state_.h_prev = state_.h_prev2 = 0.0;
        proposed = std::min(proposed, model_->solver.dt);
      }
    }
    // The frames this step reached: at its end, or inside it (error control only).
    for (double t_out = output_time(next_frame); !frames_done && t_out <= state_.t * (1.0 + 1e-12);
         t_out = output_time(++next_frame)) {
      if (t_out >= state_.t * (1.0 - 1e-12)) record(sink, state_);
      else record(sink, interpolate_in_step(step_start_, state_, t_out));
      if (progress) progress(t_out);
      frames_done = t_out >= duration;
    }
  }
  if (!ok && stats_.stopped_by.empty()) {
    // A step that fails on a rod stretched or squashed far past its linear model fails for the
    // load more than for the step (a feed into a dead end squashed a rod by 84 %, then Newton
    // failed): the message says so, where the warnings only count it.
    const EdgeStrain largest = largest_axial_strain(model_->rod, state_.x);
    if (std::abs(largest.strain) > kLargeAxialStrain) {
      char text[240];
      std::snprintf(text, sizeof text,
                    "; at t = %.6g s, the last state computed, edge %d of the rod was %s to %.3g %% of its rest length: "
                    "a drive or load stronger than the rod",
                    state_.t, static_cast<int>(largest.edge), largest.strain < 0 ? "squashed" : "stretched",
                    100.0 * (1.0 + largest.strain));
      stats_.failure += text;
    }
  }
  stats_.wall_time = std::chrono::duration<double>(Clock::now() - wall_start).count();
  return ok;
}

}  // namespace vascsim

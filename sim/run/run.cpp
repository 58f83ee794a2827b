#include "sim/run/run.h"

#include <algorithm>
#include <cmath>

#include "sim/contact/paper_contact.h"
#include "sim/log/channel_names.h"
#include "sim/step/statics.h"
#include "sim/step/stepper.h"

namespace vascsim {

namespace {

using Clock = std::chrono::steady_clock;

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

Run::Run(std::shared_ptr<const Model> model)
    : model_(std::move(model)),
      scene_(model_->scene),
      navigation_(model_->navigation.get()),
      state_(initial_state(*model_)),
      workspace_(*model_) {
  const int n = model_->nodes();
  if (navigation_) {
    controller_.emplace(scene_.control, *navigation_->trajectory, navigation_->plant);
    stats_.contact_time.assign(static_cast<std::size_t>(n), 0.0);
  }
  const std::uint32_t node_values = static_cast<std::uint32_t>(2 * n);
  channels_.push_back({channel::kPosition, "m", ChannelLayout::kNodeVectors, node_values});
  channels_.push_back({channel::kVelocity, "m/s", ChannelLayout::kNodeVectors, node_values});
  for (const auto& f : model_->forces)
    if (!contains(force_channels_, f->channel())) force_channels_.push_back(f->channel());
  // Every navigation run logs its magnetic force, also when its actuation has no force module.
  if (navigation_ && !contains(force_channels_, channel::kActuationForce)) force_channels_.push_back(channel::kActuationForce);
  for (const auto& name : force_channels_) channels_.push_back({name, "N", ChannelLayout::kNodeVectors, node_values});
  if (navigation_) {
    channels_.push_back({channel::kTipReference, "m", ChannelLayout::kVector, 2});
    channels_.push_back({channel::kTipError, "m", ChannelLayout::kScalars, 1});
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
  step.reference_now = navigation_->trajectory->position(controller_->reference_time(state_.t));
  step.tip_offset = controller_->position_disturbance(state_.t + dt);
  navigation_->actuation->set_controls(last_command_, step, controls);
  controls.wall_forces = wall_forces_;
  return controls;
}

bool Run::advance(double dt) {
  const double t_start = state_.t;  // warnings are dated by the step's start
  Controls controls = controls_for_step(dt);
  StepReport report;
  if (navigation_ && navigation_->paper_walls) {
    // The paper's contact: re-solve the step with updated wall forces until no node is inside.
    const State start = state_;
    for (int k = 1;; ++k) {
      report = step(*model_, state_, workspace_, controls, dt);
      if (!report.ok) break;
      const PaperContactUpdate u = paper_contact_update(*navigation_->paper_walls, model_->rod.outer_radius, scene_.contact.paper_gain,
                                                        state_.x, wall_forces_);
      stats_.paper_contact_iterations_max = std::max(stats_.paper_contact_iterations_max, k);
      if (u.settled) break;
      if (k >= scene_.contact.paper_iterations) {
        stats_.warnings.paper_contact_cap.note(t_start);
        break;
      }
      state_ = start;
      controls.wall_forces = wall_forces_;
    }
  } else {
    report = step(*model_, state_, workspace_, controls, dt);
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
    stats_.failure = "the state became non-finite at t = " + std::to_string(state_.t) + " s";
    return false;
  }
  if (report.round_off_stop) stats_.warnings.newton_round_off.note(t_start);
  ++stats_.steps;
  stats_.newton_iterations += report.iterations;
  stats_.newton_iterations_max = std::max(stats_.newton_iterations_max, report.iterations);
  last_controls_ = controls;
  update_statistics(report.dt, controls);
  return true;
}

Eigen::VectorXd Run::channel_force(const std::string& name, const Controls& controls) const {
  const ForceContext ctx = ForceContext::at(state_, controls);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model_->dofs());
  for (std::size_t k = 0; k < model_->forces.size(); ++k)
    if (model_->forces[k]->channel() == name) model_->forces[k]->add(module_context(ctx, workspace_, k), f, nullptr);
  return f;
}

Eigen::VectorXd Run::logged_force(const std::string& name, const Controls& controls) const {
  Eigen::VectorXd f = channel_force(name, controls);
  if (navigation_ && name == channel::kActuationForce) navigation_->actuation->logged_force(last_command_, f);
  return f;
}

void Run::update_statistics(double dt, const Controls& controls) {
  stats_.simulated_time = state_.t;
  if (!navigation_) return;
  const int n = model_->nodes();
  const Vec2 tip = state_.position(n - 1);
  const double error = (navigation_->trajectory->position(controller_->reference_time(state_.t)) - tip).norm();
  stats_.tip_error_max = std::max(stats_.tip_error_max, error);
  error_square_time_ += error * error * dt;
  stats_.tip_error_rms = std::sqrt(error_square_time_ / std::max(state_.t, 1e-300));
  // The magnetic force as applied at the end of the step (the servo is implicit).
  const Vec2 actuation = logged_force(channel::kActuationForce, controls).reshaped(2, n).rowwise().sum();
  stats_.actuation_force_max = std::max(stats_.actuation_force_max, actuation.norm());
  actuation_time_ += actuation.norm() * dt;
  stats_.actuation_force_mean = actuation_time_ / std::max(state_.t, 1e-300);
  if (!stats_.goal_reached && (tip - navigation_->environment.goal).norm() <= 0.5 * navigation_->environment.goal_radius) {
    stats_.goal_reached = true;
    stats_.goal_time = state_.t;
  }
  // Contact: gaps, time in contact and the largest per-node wall force.
  // Gaps beyond the barrier's reach are not contact: only pairs within it are visited.
  double gap = std::numeric_limits<double>::infinity();
  navigation_->contact_geometry->for_each_pair(
      state_.x, false, [&](const ContactPair& pair) { gap = std::min(gap, pair.gap); }, probe_neighbours_);
  stats_.min_gap = std::min(stats_.min_gap, gap);
  stats_.max_penetration = std::max(stats_.max_penetration, -stats_.min_gap);
  if (!std::isfinite(gap) && !navigation_->paper_walls) return;  // touching nothing: no wall force
  const Eigen::VectorXd wall = channel_force(channel::kContactForce, controls);
  for (int i = 0; i < n; ++i) {
    const double magnitude = wall.segment<2>(2 * i).norm();
    stats_.contact_force_max = std::max(stats_.contact_force_max, magnitude);
    if (magnitude > 0.0) stats_.contact_time[static_cast<std::size_t>(i)] += dt;
  }
}

void Run::record(FrameSink& sink) {
  std::vector<double> values;
  values.reserve(channels_.size() * state_.x.size());
  values.insert(values.end(), state_.x.data(), state_.x.data() + state_.x.size());
  values.insert(values.end(), state_.v.data(), state_.v.data() + state_.v.size());
  for (const auto& name : force_channels_) {
    const Eigen::VectorXd f = logged_force(name, last_controls_);
    values.insert(values.end(), f.data(), f.data() + f.size());
  }
  if (navigation_) {
    const Vec2 reference = navigation_->trajectory->position(controller_->reference_time(state_.t));
    values.push_back(reference.x());
    values.push_back(reference.y());
    values.push_back((reference - state_.position(model_->nodes() - 1)).norm());
  }
  sink.write(state_.t, values);
  ++stats_.frames;
}

bool Run::solve_equilibrium(FrameSink& sink) {
  const auto wall_start = Clock::now();
  record(sink);
  const StaticReport report = solve_static(*model_, state_, workspace_, last_controls_);
  stats_.steps = report.increments;
  stats_.rejected_steps = report.rejected;
  stats_.newton_iterations = report.iterations;
  stats_.newton_iterations_max = report.iterations;
  if (report.ok && report.negative_pivots > 0) stats_.warnings.unstable_equilibrium.note(1.0);
  if (report.ok && report.left_unstable) stats_.warnings.left_unstable.note(1.0);
  if (report.ok) {
    // The load scale plays the part of time: 0 unloaded, 1 in equilibrium (docs/frame-log.md).
    state_.t = 1.0;
    stats_.simulated_time = state_.t;
    record(sink);
  } else {
    stats_.failed = true;
    stats_.failure = "static equilibrium: " + report.failure;
  }
  stats_.wall_time = std::chrono::duration<double>(Clock::now() - wall_start).count();
  return report.ok;
}

bool Run::run(FrameSink& sink, const std::function<void(double)>& progress) {
  if (model_->solver.mode == SolveMode::kStatic) return solve_equilibrium(sink);
  const auto wall_start = Clock::now();
  const double duration = scene_.run.duration;
  const double interval = scene_.run.output_interval;
  const double dt = model_->solver.dt;
  record(sink);
  std::size_t next_frame = 1;
  bool ok = true;
  while (state_.t < duration * (1.0 - 1e-12)) {
    // Steps land exactly on output times so that frames are evenly spaced.
    const double next_output = std::min(duration, static_cast<double>(next_frame) * interval);
    const double h = std::min(dt, next_output - state_.t);
    if (!advance(h)) {
      ok = false;
      break;
    }
    if (state_.t >= next_output * (1.0 - 1e-12)) {
      record(sink);
      ++next_frame;
      if (progress) progress(state_.t);
    }
  }
  stats_.wall_time = std::chrono::duration<double>(Clock::now() - wall_start).count();
  return ok;
}

}  // namespace vascsim

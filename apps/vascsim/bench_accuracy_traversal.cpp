#include "apps/vascsim/bench_accuracy_traversal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "apps/vascsim/equal_error_cost.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"

namespace vascsim::cli {

namespace {

// Keeps every frame's node positions (the first channel of a frame).
class PositionRecorder : public FrameSink {
 public:
  explicit PositionRecorder(int nodes) : dofs_(2 * static_cast<std::size_t>(nodes)) {}
  void write(double, const std::vector<double>& values) override {
    frames_.emplace_back(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(dofs_));
  }
  const std::vector<std::vector<double>>& frames() const { return frames_; }

 private:
  std::size_t dofs_;
  std::vector<std::vector<double>> frames_;
};

double largest_node_distance(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b) {
  double worst = 0.0;
  for (std::size_t f = 0; f < std::min(a.size(), b.size()); ++f)
    for (std::size_t d = 0; d + 1 < a[f].size(); d += 2)
      worst = std::max(worst, std::hypot(a[f][d] - b[f][d], a[f][d + 1] - b[f][d + 1]));
  return worst;
}

struct Setting {
  std::string label;
  bool fixed;
  std::function<void(SolverSpec&)> apply;
};

std::vector<Setting> settings() {
  std::vector<Setting> s;
  for (double dt : {1e-2, 5e-3, 4e-3, 2e-3, 1e-3, 2.5e-4}) {
    char label[32];
    std::snprintf(label, sizeof label, "fixed %.2g", dt);
    s.push_back({label, true, [dt](SolverSpec& v) {
                   v.adaptive = StepControl::kRetry;
                   v.dt = dt;
                 }});
  }
  // The same with the fast preset's looser Newton tolerance: a fixed step as long as fast's
  // floor is as accurate with it and cheaper, so the comparison with fast must offer it.
  for (double dt : {5e-3, 4e-3}) {
    char label[32];
    std::snprintf(label, sizeof label, "fixed %.2g tol 1e-4", dt);
    s.push_back({label, true, [dt](SolverSpec& v) {
                   v.adaptive = StepControl::kRetry;
                   v.dt = dt;
                   v.rel_tol = 1e-4;
                 }});
  }
  for (const char* preset : {"fast", "balanced", "accurate"})
    s.push_back({std::string("preset ") + preset, false, [preset](SolverSpec& v) { apply_solver_preset(preset, v); }});
  // Error control alone: the balanced preset's other settings, no floors.
  for (double rtol : {1e-3, 3e-4, 1e-4, 3e-5}) {
    char label[32];
    std::snprintf(label, sizeof label, "error %.2g", rtol);
    s.push_back({label, false, [rtol](SolverSpec& v) {
                   apply_solver_preset("balanced", v);
                   v.rtol = rtol;
                   v.dt_floor = v.dt_mean_min = 0.0;
                 }});
  }
  // The reference: a 100x smaller tolerance than the balanced preset's, with a floor 8x below its
  // (without one an undamped body's every bounce would be followed for hours).
  s.push_back({"reference", false, [](SolverSpec& v) {
                 apply_solver_preset("balanced", v);
                 v.rtol = 1.5e-6;
                 v.atol_velocity = 1e-5;
                 v.dt = v.dt_floor = 1.25e-4;
                 v.dt_mean_min = 0.0;
               }});
  return s;
}

TraversalRow run_setting(const Scene& base, const Setting& setting, std::vector<std::vector<double>>& frames) {
  Scene scene = base;
  setting.apply(scene.solver);
  PositionRecorder recorder(scene.rod.nodes);
  Run run(compile(scene));
  TraversalRow row;
  row.ok = run.run(recorder);
  const RunStatistics& s = run.statistics();
  row.scene = base.name;
  row.stepping = setting.label;
  row.fixed = setting.fixed;
  row.steps = s.steps;
  row.mean_dt = s.steps ? s.simulated_time / s.steps : 0.0;
  row.newton_per_step = s.steps ? static_cast<double>(s.newton_iterations) / s.steps : 0.0;
  row.wall_time = s.wall_time;
  row.real_time = s.wall_time > 0 ? s.simulated_time / s.wall_time : 0.0;
  row.goal_time = s.goal_reached ? s.goal_time : std::numeric_limits<double>::quiet_NaN();
  row.tip_rms = s.tip_error_rms;
  row.tip_max = s.tip_error_max;
  row.contact_force_max = s.contact_force_max;
  row.steps_over_tolerance = s.warnings.step_over_tolerance.count;
  frames = recorder.frames();
  return row;
}

}  // namespace

std::vector<TraversalRow> traversal_rows(const Scene& base, const std::function<void(const TraversalRow&)>& progress) {
  // The reference first, so that every other row can be reported as soon as it is run.
  const std::vector<Setting> all = settings();
  std::vector<std::vector<double>> reference_frames, frames;
  TraversalRow reference = run_setting(base, all.back(), reference_frames);
  std::vector<TraversalRow> rows;
  for (std::size_t k = 0; k + 1 < all.size(); ++k) {
    rows.push_back(run_setting(base, all[k], frames));
    rows.back().body_deviation = largest_node_distance(frames, reference_frames);
    if (progress) progress(rows.back());
  }
  reference.body_deviation = 0.0;
  rows.push_back(reference);
  if (progress) progress(reference);
  return rows;
}

std::vector<TraversalRow> mean_over_mazes(const std::vector<std::vector<TraversalRow>>& rows_by_maze) {
  std::vector<TraversalRow> mean = rows_by_maze.at(0);
  const double mazes = static_cast<double>(rows_by_maze.size());
  for (std::size_t r = 0; r < mean.size(); ++r) {
    TraversalRow& m = mean[r];
    m.scene += " x" + std::to_string(rows_by_maze.size());
    double steps = 0.0, simulated = 0.0;
    m.mean_dt = m.newton_per_step = m.wall_time = m.body_deviation = m.goal_time = m.tip_rms = m.tip_max = 0.0;
    m.contact_force_max = 0.0;
    m.steps_over_tolerance = 0;
    for (const auto& rows : rows_by_maze) {
      const TraversalRow& one = rows.at(r);
      steps += one.steps;
      simulated += one.steps * one.mean_dt;
      m.newton_per_step += one.newton_per_step * one.steps;
      m.wall_time += one.wall_time;
      m.body_deviation += one.body_deviation / mazes;
      m.goal_time += one.goal_time / mazes;  // NaN if some maze's goal was not reached
      m.tip_rms += one.tip_rms / mazes;
      m.tip_max += one.tip_max / mazes;
      m.contact_force_max = std::max(m.contact_force_max, one.contact_force_max);
      m.steps_over_tolerance += one.steps_over_tolerance;
      m.ok = m.ok && one.ok;
    }
    m.steps = static_cast<int>(std::lround(steps / mazes));
    m.mean_dt = steps > 0 ? simulated / steps : 0.0;
    m.newton_per_step = steps > 0 ? m.newton_per_step / steps : 0.0;
    m.real_time = m.wall_time > 0 ? simulated / m.wall_time : 0.0;
  }
  return mean;
}

void print_traversal_header() {
  std::printf("%-20s %-20s %9s %7s %6s %9s %9s %10s %8s %15s %10s %8s\n", "scene", "stepping", "mean dt", "steps", "iter",
              "wall [s]", "real-time", "body [mm]", "goal [s]", "tip rms/max mm", "contact N", "floored");
}

void print_traversal_row(const TraversalRow& r) {
  std::printf("%-20s %-20s %9.2e %7d %6.2f %9.3f %8.0fx %10.3f %8.3f %7.3f/%-7.3f %10.4f %8d%s\n", r.scene.c_str(),
              r.stepping.c_str(), r.mean_dt, r.steps, r.newton_per_step, r.wall_time, r.real_time, 1e3 * r.body_deviation,
              r.goal_time, 1e3 * r.tip_rms, 1e3 * r.tip_max, r.contact_force_max, r.steps_over_tolerance,
              r.ok ? "" : "  FAILED");
}

void print_traversal_comparison(const std::vector<TraversalRow>& rows) {
  std::vector<TraversalRow> sorted;
  for (const auto& r : rows)
    if (r.ok && r.stepping != "reference") sorted.push_back(r);
  std::sort(sorted.begin(), sorted.end(), [](const TraversalRow& a, const TraversalRow& b) { return a.wall_time < b.wall_time; });
  std::printf("\nPareto front (%s, body deviation against wall time):\n", rows.empty() ? "" : rows[0].scene.c_str());
  print_traversal_header();
  double best = INFINITY;
  for (const auto& r : sorted)
    if (r.body_deviation < best) {
      best = r.body_deviation;
      print_traversal_row(r);
    }
  std::vector<ErrorCost> fixed_runs;
  for (const auto& f : sorted)
    if (f.fixed) fixed_runs.push_back({f.body_deviation, f.wall_time});
  std::printf("\nAgainst the fastest fixed step of equal or smaller body deviation (and a fixed step of equal deviation,\n"
              "interpolated log-log along the fixed steps' front):\n");
  for (const auto& a : sorted) {
    if (a.fixed) continue;
    const TraversalRow* fixed = nullptr;
    for (const auto& f : sorted)
      if (f.fixed && f.body_deviation <= a.body_deviation && (!fixed || f.wall_time < fixed->wall_time)) fixed = &f;
    const double interpolated = wall_time_at_error(fixed_runs, a.body_deviation);
    char at_equal_error[64] = "";
    if (std::isfinite(interpolated))
      std::snprintf(at_equal_error, sizeof at_equal_error, "; at equal deviation %.3f s, %.2fx", interpolated,
                    interpolated / a.wall_time);
    if (fixed)
      std::printf("  %-20s %.3f mm in %.3f s   %-20s %.3f mm in %.3f s   %.2fx faster%s\n", a.stepping.c_str(),
                  1e3 * a.body_deviation, a.wall_time, fixed->stepping.c_str(), 1e3 * fixed->body_deviation,
                  fixed->wall_time, fixed->wall_time / a.wall_time, at_equal_error);
    else
      std::printf("  %-20s %.3f mm in %.3f s   no fixed step as accurate\n", a.stepping.c_str(), 1e3 * a.body_deviation,
                  a.wall_time);
  }
}

}  // namespace vascsim::cli

// vascsim bench accuracy: the speed-accuracy trade of the rod core, measured on reference
// problems with known answers, over time step, node count, Newton tolerance and scheme.
//   dynamic: the paper's rod as a cantilever (centred clamp) under a suddenly applied small tip
//     load (alpha = P L^2/EI = 0.01, linear regime). Euler-Bernoulli modal superposition gives
//     y_tip(t) = sum_n 4 P L^3 / (EI (beta_n L)^4) (1 - cos w_n t) (docs/references.md sections
//     1 and 2; mode shapes normalised so that the integral of phi^2 is L and |phi(L)| = 2).
//     Error: the largest |y_tip - exact| over t = 0.1, 0.2, .. T, relative to P L^3 / (3 EI).
//   static: the elastica at alpha = 1 (docs/references.md section 1 table) against N.
//   traversals: the shipped maze scenes, whole runs at fixed steps, presets and tolerances
//     (bench_accuracy_traversal.h).
// Prints tables and Pareto fronts (no faster run is more accurate), writes all rows as CSV.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

#include "apps/vascsim/bench_accuracy_traversal.h"
#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "apps/vascsim/equal_error_cost.h"
#include "sim/io/output_file.h"
#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/scene/input_error.h"
#include "sim/step/model.h"
#include "sim/step/statics.h"
#include "sim/step/stepper.h"

namespace vascsim::cli {

namespace {

using Clock = std::chrono::steady_clock;

struct Row {
  std::string problem;
  std::string scheme;
  double dt = 0.0;
  int nodes = 0;
  double rel_tol = 0.0;
  double error = 0.0;       // relative
  double wall_time = 0.0;   // s
  double iterations = 0.0;  // Newton iterations per step (or in total for statics)
  bool ok = true;
};

// Roots of cos x cosh x = -1 (clamped-free); beyond the fourth, (2n - 1) pi / 2 to double precision.
double beta_l(int n) {
  static const double first[4] = {1.8751040687119611, 4.6940911329741745, 7.8547574382376126, 10.995540734875467};
  return n < 4 ? first[n] : (2 * n + 1) * M_PI / 2;
}

Scene cantilever(int nodes, Scheme scheme, double dt, double rel_tol, double p) {
  Scene s;
  s.has_environment = false;
  s.rod.nodes = nodes;
  s.boundary.clamp = ClampKind::kCentred;
  s.solver.scheme = scheme;
  s.solver.dt = dt;
  s.solver.rel_tol = rel_tol;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, -p);
  s.loads.point_loads.push_back(tip);
  return s;
}

// The dynamic problem's load and its exact tip deflection (modal superposition, 40 modes).
struct StepLoadReference {
  double p = 0.0, y_static = 0.0, ei = 0.0, l = 0.0, rho_a = 0.0;
  StepLoadReference() {
    const RodSpec rod;
    const double ro2 = rod.outer_radius * rod.outer_radius, ri2 = rod.inner_radius * rod.inner_radius;
    ei = rod.youngs_modulus * M_PI * (ro2 * ro2 - ri2 * ri2) / 4, l = rod.length;
    rho_a = rod.density * M_PI * (ro2 - ri2);
    p = 0.01 * ei / (l * l);
    y_static = p * l * l * l / (3 * ei);
  }
  double tip(double t) const {
    double y = 0.0;
    for (int n = 0; n < 40; ++n) {
      const double b = beta_l(n);
      const double w = b * b * std::sqrt(ei / (rho_a * std::pow(l, 4)));
      y += 4 * p * l * l * l / (ei * std::pow(b, 4)) * (1 - std::cos(w * t));
    }
    return -y;
  }
};

// The dynamic problem with the solver settings `apply` makes (a fixed step, error control, a
// preset), run through Run so that the step-size controller, output cuts and statistics are the
// product's. "dt" is the mean step taken.
Row controlled_row(int nodes, const std::string& name, const std::function<void(SolverSpec&)>& apply, double duration) {
  const StepLoadReference ref;
  Scene scene = cantilever(nodes, Scheme::kBdf2, 1e-4, 1e-6, ref.p);
  apply(scene.solver);
  scene.run.duration = duration;
  scene.run.output_interval = 0.1;
  Row row;
  row.problem = "cantilever_step_load";
  row.scheme = name;
  row.nodes = nodes;
  row.rel_tol = scene.solver.rel_tol;
  struct TipError : FrameSink {
    const StepLoadReference* ref;
    int tip_y;
    double worst = 0.0;
    void write(double t, const std::vector<double>& values) override {
      worst = std::max(worst, std::abs(values[static_cast<std::size_t>(tip_y)] - ref->tip(t)) / ref->y_static);
    }
  } sink;
  sink.ref = &ref;
  sink.tip_y = 2 * nodes - 1;  // position is the first channel
  Run run(compile(scene));
  row.ok = run.run(sink);
  const RunStatistics& s = run.statistics();
  row.error = sink.worst;
  row.wall_time = s.wall_time;
  row.dt = s.steps ? s.simulated_time / s.steps : 0.0;
  row.iterations = s.steps ? static_cast<double>(s.newton_iterations) / s.steps : 0.0;
  return row;
}

// At a fixed step, through Run like the controlled rows, so that both pay for the same output
// and statistics.
Row dynamic_row(int nodes, Scheme scheme, double dt, double rel_tol, double duration) {
  Row row = controlled_row(nodes, scheme == Scheme::kBdf2 ? "bdf2" : "backward_euler", [&](SolverSpec& s) {
    s.scheme = scheme;
    s.adaptive = StepControl::kOff;
    s.dt = dt;
    s.rel_tol = rel_tol;
  }, duration);
  row.dt = dt;
  return row;
}

Row adaptive_row(int nodes, Scheme scheme, double rtol, double rel_tol, double duration) {
  char name[64];
  std::snprintf(name, sizeof name, "%s/err %.0e", scheme == Scheme::kBdf2 ? "bdf2" : "backward_euler", rtol);
  return controlled_row(nodes, name, [&](SolverSpec& s) {
    s.scheme = scheme;
    s.rel_tol = rel_tol;
    s.adaptive = StepControl::kError;
    s.rtol = rtol;
  }, duration);
}

// A solver preset as it stands (docs/accuracy.md, "Presets").
Row preset_row(int nodes, const std::string& preset, double duration) {
  return controlled_row(nodes, "bdf2/preset " + preset, [&](SolverSpec& s) { apply_solver_preset(preset, s); }, duration);
}

Row static_row(int nodes, double rel_tol) {
  Row row;
  row.problem = "elastica_alpha_1";
  row.scheme = "static";
  row.nodes = nodes;
  row.rel_tol = rel_tol;
  const RodSpec rod;
  const double ro2 = rod.outer_radius * rod.outer_radius, ri2 = rod.inner_radius * rod.inner_radius;
  const double ei = rod.youngs_modulus * M_PI * (ro2 * ro2 - ri2 * ri2) / 4, l = rod.length;
  Scene scene = cantilever(nodes, Scheme::kBackwardEuler, 1e-3, rel_tol, ei / (l * l));
  scene.solver.mode = SolveMode::kStatic;
  const Model model = *compile(scene);
  State state = initial_state(model);
  Workspace ws(model);
  const auto start = Clock::now();
  const StaticReport r = solve_static(model, state, ws, Controls{});
  row.wall_time = std::chrono::duration<double>(Clock::now() - start).count();
  row.ok = r.ok;
  row.iterations = r.iterations;
  row.error = std::abs(-state.x[2 * nodes - 1] / l - 0.30172077) / 0.30172077;
  return row;
}

void print_row(const Row& r) {
  std::printf("%-22s %-28s %9.2e %6d %8.0e %11.3e %11.4f %8.2f%s\n", r.problem.c_str(), r.scheme.c_str(), r.dt, r.nodes,
              r.rel_tol, r.error, r.wall_time, r.iterations, r.ok ? "" : "  FAILED");
}

void print_header() {
  std::printf("%-22s %-28s %9s %6s %8s %11s %11s %8s\n", "problem", "scheme", "dt [s]", "N", "rel_tol", "error",
              "wall [s]", "iter");
}

}  // namespace

int run_bench_accuracy(int argc, char** argv) {
  const std::vector<OptionSpec> options = {
      {"csv", "FILE", "write every row as CSV (default accuracy.csv)"},
      {"duration", "T", "simulated time of the dynamic problem, s (default 10: one period of mode 1)"},
      {"quick", "", "a small sweep (for tests): no traversals"},
      {"scenes", "DIR", "where maze_body_drag.json and maze_default.json are (default scenes)"},
      {"seeds", "K", "also run maze_body_drag on the next K - 1 maze seeds and compare the settings on the mean over the K mazes (default 1)"},
      {"traversal-csv", "FILE", "write the traversal rows as CSV (default traversal.csv)"},
      {"help", "", "this text"},
  };
  const Args args(argc, argv, 3, options);
  if (args.flag("help")) {
    std::printf("usage: vascsim bench accuracy [options]\n\n%s", format_options(options).c_str());
    return 0;
  }
  const std::string csv = args.value("csv").value_or("accuracy.csv");
  const double duration = args.number("duration", 10.0, 0.1, 1e3);
  const bool quick = args.flag("quick");
  const std::string scenes = args.value("scenes").value_or("scenes");
  const std::string traversal_csv = args.value("traversal-csv").value_or("traversal.csv");
  const int seeds = static_cast<int>(args.integer("seeds", 1, 1, 100));
  // The outputs are checked before minutes of runs, and written whole when they are done.
  check_replaceable_output(csv, true, {});
  if (!quick) {
    check_replaceable_output(traversal_csv, true, {});
    const std::string damped = scenes + "/maze_body_drag.json";
    const Scene scene = read_scene_file(damped);
    read_scene_file(scenes + "/maze_default.json");
    if (seeds > 1 && (scene.environment != EnvironmentKind::kMaze || scene.maze.explicit_walls))
      throw InputError("--seeds: " + damped + " has no generated maze whose seed could change");
  }

  std::vector<Row> rows;
  // Steps up to 0.1 s (a hundredth of the first mode's period): a controlled run that may take
  // long steps is compared with fixed steps as long as its own.
  std::vector<double> dts = {1e-1, 5e-2, 2e-2, 1e-2, 4e-3, 1e-3, 2.5e-4};
  std::vector<int> node_counts = {21, 41, 81};
  std::vector<double> tols = {1e-4, 1e-6, 1e-9};
  if (quick) {
    dts = {1e-2, 4e-3};
    node_counts = {21};
    tols = {1e-6};
  }
  print_header();
  for (Scheme scheme : {Scheme::kBackwardEuler, Scheme::kBdf2})
    for (int n : node_counts)
      for (double dt : dts)
        for (double tol : tols) {
          rows.push_back(dynamic_row(n, scheme, dt, tol, quick ? 0.5 : duration));
          print_row(rows.back());
        }
  for (Scheme scheme : {Scheme::kBackwardEuler, Scheme::kBdf2})
    for (int n : node_counts)
      for (double rtol : quick ? std::vector<double>{1e-4} : std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6}) {
        rows.push_back(adaptive_row(n, scheme, rtol, 1e-6, quick ? 0.5 : duration));
        print_row(rows.back());
      }
  for (int n : node_counts)
    for (const char* preset : {"fast", "balanced", "accurate"}) {
      rows.push_back(preset_row(n, preset, quick ? 0.5 : duration));
      print_row(rows.back());
      // The presets' dt_max (0.02 s) raised: does error control win once it may take long steps?
      rows.push_back(controlled_row(n, std::string("bdf2/preset ") + preset + " dt_max 0.1", [&](SolverSpec& s) {
        apply_solver_preset(preset, s);
        s.dt_max = 0.1;
      }, quick ? 0.5 : duration));
      print_row(rows.back());
    }
  for (int n : quick ? std::vector<int>{11, 21} : std::vector<int>{11, 21, 41, 81, 161}) {
    rows.push_back(static_row(n, 1e-10));
    print_row(rows.back());
  }

  // Pareto front of the dynamic problem: sorted by wall time, keep a run only if it is more
  // accurate than every faster one.
  std::vector<Row> dynamic;
  for (const auto& r : rows)
    if (r.problem == "cantilever_step_load" && r.ok) dynamic.push_back(r);
  std::sort(dynamic.begin(), dynamic.end(), [](const Row& a, const Row& b) { return a.wall_time < b.wall_time; });
  std::printf("\nPareto front (cantilever_step_load):\n");
  print_header();
  double best = INFINITY;
  for (const auto& r : dynamic)
    if (r.error < best) {
      best = r.error;
      print_row(r);
    }

  // Error control against fixed steps: for each error-controlled run, the fastest fixed-step run
  // (same N) that is at least as accurate, and how much longer it takes.
  std::printf("\nError control against the best fixed step of equal or smaller error (same N):\n");
  std::printf("%-28s %6s %11s %11s   %-28s %11s %8s %15s\n", "controlled", "N", "error", "wall [s]", "best fixed (scheme, dt)",
              "wall [s]", "speedup", "at equal error");
  for (const auto& a : dynamic) {
    if (a.scheme.find("/err") == std::string::npos && a.scheme.find("/preset") == std::string::npos) continue;
    const Row* best_fixed = nullptr;
    for (const auto& f : dynamic)
      if (f.scheme.find('/') == std::string::npos && f.nodes == a.nodes && f.error <= a.error &&
          (!best_fixed || f.wall_time < best_fixed->wall_time))
        best_fixed = &f;
    char fixed[64] = "none as accurate";
    if (best_fixed) std::snprintf(fixed, sizeof fixed, "%s, %.2g", best_fixed->scheme.c_str(), best_fixed->dt);
    // The fixed runs of the same N, both schemes, every Newton tolerance: a fixed step of exactly
    // this error (equal_error_cost.h).
    std::vector<ErrorCost> fixed_runs;
    for (const auto& f : dynamic)
      if (f.scheme.find('/') == std::string::npos && f.nodes == a.nodes) fixed_runs.push_back({f.error, f.wall_time});
    const double at_equal_error = wall_time_at_error(fixed_runs, a.error);
    char equal[32] = "-";
    if (std::isfinite(at_equal_error)) std::snprintf(equal, sizeof equal, "%.2fx", at_equal_error / a.wall_time);
    std::printf("%-28s %6d %11.3e %11.4f   %-28s %11s %8s %15s\n", a.scheme.c_str(), a.nodes, a.error, a.wall_time, fixed,
                best_fixed ? std::to_string(best_fixed->wall_time).substr(0, 7).c_str() : "-",
                best_fixed ? (std::to_string(best_fixed->wall_time / a.wall_time).substr(0, 5) + "x").c_str() : "-", equal);
  }

  std::string table = "problem,scheme,dt,nodes,rel_tol,error,wall_time,iterations,ok\n";
  char line[300];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%s,%s,%.6g,%d,%.3g,%.6e,%.6e,%.4g,%d\n", r.problem.c_str(), r.scheme.c_str(),
                  r.dt, r.nodes, r.rel_tol, r.error, r.wall_time, r.iterations, r.ok ? 1 : 0);
    table += line;
  }
  write_file_atomically(csv, table);
  std::printf("\nwrote %s\n", csv.c_str());
  if (quick) return 0;

  // The maze traversals (bench_accuracy_traversal.h): 26 runs, about a minute.
  std::string traversal_table =
      "scene,stepping,mean_dt,steps,newton_per_step,wall_time,real_time,body_deviation_m,goal_time,tip_rms_m,"
      "tip_max_m,contact_force_max_N,steps_over_tolerance,ok,maze_seed\n";
  const auto add_to_table = [&](const std::vector<TraversalRow>& traversal, std::uint64_t seed) {
    for (const auto& r : traversal) {
      std::snprintf(line, sizeof line, "%s,%s,%.6g,%d,%.4g,%.6e,%.6g,%.6e,%.6f,%.6e,%.6e,%.6e,%d,%d,%llu\n", r.scene.c_str(),
                    r.stepping.c_str(), r.mean_dt, r.steps, r.newton_per_step, r.wall_time, r.real_time, r.body_deviation,
                    r.goal_time, r.tip_rms, r.tip_max, r.contact_force_max, r.steps_over_tolerance, r.ok ? 1 : 0,
                    static_cast<unsigned long long>(seed));
      traversal_table += line;
    }
  };
  for (const char* name : {"maze_body_drag", "maze_default"}) {
    std::printf("\nTraversal of %s/%s.json (48 s; body deviation against the reference run):\n", scenes.c_str(), name);
    print_traversal_header();
    Scene scene = read_scene_file(scenes + "/" + name + ".json");
    std::vector<std::vector<TraversalRow>> by_maze = {traversal_rows(scene, [](const TraversalRow& r) { print_traversal_row(r); })};
    print_traversal_comparison(by_maze[0]);
    add_to_table(by_maze[0], scene.maze.seed);
    if (seeds == 1 || std::string(name) != "maze_body_drag") continue;
    // The same settings on more mazes, each against a reference of its own.
    const std::uint64_t first_seed = scene.maze.seed;
    for (int k = 1; k < seeds; ++k) {
      scene.maze.seed = first_seed + static_cast<std::uint64_t>(k);
      std::printf("\n%s on maze seed %llu:\n", name, static_cast<unsigned long long>(scene.maze.seed));
      print_traversal_header();
      by_maze.push_back(traversal_rows(scene, [](const TraversalRow& r) { print_traversal_row(r); }));
      add_to_table(by_maze.back(), scene.maze.seed);
    }
    std::printf("\n%s over maze seeds %llu..%llu (body deviation: the mean of each maze's largest; wall time: the sum):\n",
                name, static_cast<unsigned long long>(first_seed), static_cast<unsigned long long>(scene.maze.seed));
    print_traversal_header();
    const std::vector<TraversalRow> mean = mean_over_mazes(by_maze);
    for (const auto& r : mean) print_traversal_row(r);
    print_traversal_comparison(mean);
  }
  write_file_atomically(traversal_csv, traversal_table);
  std::printf("\nwrote %s\n", traversal_csv.c_str());
  return 0;
}

}  // namespace vascsim::cli

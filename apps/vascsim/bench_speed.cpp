// vascsim bench speed: cost of the rod core. For N from 10 to 100000: one Newton iteration
// (assembly of residual and banded Jacobian + LDL^T factorisation + solve), per iteration and per
// node, to show the linear scaling; and full backward Euler steps of the paper's rod (Table I,
// 0.5 m, dt = 1e-3, free motion under a small tip force), in steps per second, for the issue 3
// targets (>= 60000 steps/s at N = 50, >= 15000 at N = 200); and one whole run at N = 10^5 (the
// run loop, retries and frames included), whose cost per Newton iteration should match the
// sweep's (issue 16 item 5d: a pivot test that rejected well-posed steps made it take minutes).
// Prints numbers; asserts nothing.
#include <chrono>
#include <cstdio>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/step/banded_ldlt.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/stepper.h"

namespace vascsim::cli {

namespace {

using Clock = std::chrono::steady_clock;

Scene paper_rod(int nodes, Scheme scheme) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = nodes;
  scene.solver.scheme = scheme;
  scene.solver.dt = 1e-3;
  scene.solver.rel_tol = 1e-6;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, 1e-4);  // N, small: the tip swings a few centimetres in 1 s
  scene.loads.point_loads.push_back(tip);
  return scene;
}

// Seconds per Newton iteration, repeated for at least `budget` seconds.
double time_iteration(int nodes, double budget, bool block) {
  Scene scene = paper_rod(nodes, Scheme::kBackwardEuler);
  scene.shape.initial_curvature = 2.0;  // bent: every element does real work
  const Model model = *compile(scene);
  const State state = initial_state(model);
  Workspace ws(model);
  ws.x_hat = state.x;
  ws.v_hat = state.v;
  ws.x = state.x;
  NewtonProblem p;
  p.c = 1.0 / model.solver.dt;
  long long reps = 0;
  const auto start = Clock::now();
  double elapsed = 0.0;
  do {
    for (int k = 0; k < 10; ++k) {
      assemble(model, p, ws.x, ws, true);
      ws.dx = -ws.residual;
      if (block) {
        banded_block_ldlt_factor(ws.jacobian);
        banded_block_ldlt_solve(ws.jacobian, ws.dx);
      } else {
        banded_ldlt_factor(ws.jacobian);
        banded_ldlt_solve(ws.jacobian, ws.dx);
      }
    }
    reps += 10;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < budget);
  return elapsed / static_cast<double>(reps);
}

struct StepTiming {
  double steps_per_second = 0.0;
  double iterations_per_step = 0.0;
  bool ok = true;
};

StepTiming time_steps(int nodes, Scheme scheme, double simulated) {
  const Model model = *compile(paper_rod(nodes, scheme));
  State state = initial_state(model);
  Workspace ws(model);
  const Controls controls;
  const int steps = static_cast<int>(simulated / model.solver.dt + 0.5);
  long long iterations = 0;
  StepTiming t;
  const auto start = Clock::now();
  for (int i = 0; i < steps; ++i) {
    const StepReport r = step(model, state, ws, controls, model.solver.dt);
    if (!r.ok) {
      t.ok = false;
      break;
    }
    iterations += r.total_iterations;
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  t.steps_per_second = steps / elapsed;
  t.iterations_per_step = static_cast<double>(iterations) / steps;
  return t;
}

class DiscardSink : public FrameSink {
 public:
  void write(double, const std::vector<double>&) override {}
};

struct RunTiming {
  double wall = 0.0;  // s
  RunStatistics stats;
};

// The issue 16 case: a centred-clamp cantilever of `nodes` nodes under a 1e-5 N tip load, the
// balanced preset, `duration` simulated seconds, frames every 0.01 s, through Run.
RunTiming time_run(int nodes, double duration) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = nodes;
  scene.boundary.clamp = ClampKind::kCentred;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, -1e-5);
  scene.loads.point_loads.push_back(tip);
  scene.run.duration = duration;
  scene.run.duration_from_path = false;
  scene.run.output_interval = 0.01;
  Run run(compile(scene));
  DiscardSink sink;
  const auto start = Clock::now();
  run.run(sink);
  RunTiming t;
  t.wall = std::chrono::duration<double>(Clock::now() - start).count();
  t.stats = run.statistics();
  return t;
}

}  // namespace

int run_bench_speed(int argc, char** argv) {
  const std::vector<OptionSpec> options = {
      {"max-nodes", "N", "largest N of the iteration sweep (default 100000)"},
      {"seconds", "T", "simulated time of the step benchmark (default 10)"},
      {"help", "", "this text"},
  };
  const Args args(argc, argv, 3, options);
  if (args.flag("help")) {
    std::printf("usage: vascsim bench speed [options]\n\n%s", format_options(options).c_str());
    return 0;
  }
  const long long max_nodes = args.integer("max-nodes", 100000, 10, 10000000);
  const double seconds = args.number("seconds", 10.0, 0.001, 1e4);

  std::printf("Newton iteration (assembly + banded LDL^T + solve), paper rod, bent;\n"
              "Newton uses the 2x2-block factorisation, the scalar one is its reference\n");
  std::printf("%10s %14s %14s %22s\n", "N", "us/iteration", "ns/node", "scalar LDL^T ns/node");
  double iteration_at_run_size = 0.0;  // s, the block iteration at kRunNodes
  constexpr long long kRunNodes = 100000;
  for (long long n : {10LL, 30LL, 100LL, 300LL, 1000LL, 3000LL, 10000LL, 30000LL, 100000LL, 300000LL, 1000000LL}) {
    if (n > max_nodes) break;
    const double tb = time_iteration(static_cast<int>(n), 0.3, true);
    const double t = time_iteration(static_cast<int>(n), 0.3, false);
    if (n == kRunNodes) iteration_at_run_size = tb;
    std::printf("%10lld %14.3f %14.1f %22.1f\n", n, tb * 1e6, tb * 1e9 / static_cast<double>(n),
                t * 1e9 / static_cast<double>(n));
  }
  if (max_nodes >= kRunNodes) {
    // Each Newton iteration of a run also assembles once more for its line search's trial point,
    // and a frame copies the state: expect somewhat more than one sweep iteration per iteration.
    constexpr double kRunTime = 0.05;  // s simulated
    const RunTiming r = time_run(static_cast<int>(kRunNodes), kRunTime);
    const double per_iteration = r.stats.newton_iterations_all > 0 ? r.wall / static_cast<double>(r.stats.newton_iterations_all) : 0.0;
    std::printf("\nWhole run: centred-clamp cantilever, 1e-5 N tip load, balanced preset, %.3g s simulated\n", kRunTime);
    std::printf("%10s %8s %10s %12s %12s %14s %22s\n", "N", "steps", "rejected", "iterations", "wall s", "ms/iteration",
                "sweep ms/iteration");
    std::printf("%10lld %8d %10d %12lld %12.3f %14.2f %22.2f%s\n", kRunNodes, r.stats.steps, r.stats.rejected_steps,
                r.stats.newton_iterations_all, r.wall, per_iteration * 1e3, iteration_at_run_size * 1e3,
                r.stats.failed ? "  (the run failed)" : "");
  }
  std::printf("\nPaper rod, free motion under a 1e-4 N tip force, dt = 1e-3 s, %.3g s simulated\n", seconds);
  std::printf("%10s %8s %14s %16s %12s\n", "scheme", "N", "steps/s", "iterations/step", "x real time");
  for (Scheme scheme : {Scheme::kBackwardEuler, Scheme::kBdf2}) {
    for (int n : {50, 200, 1000}) {
      const StepTiming t = time_steps(n, scheme, seconds);
      std::printf("%10s %8d %14.0f %16.2f %12.1f%s\n", scheme == Scheme::kBdf2 ? "bdf2" : "backward_euler", n,
                  t.steps_per_second, t.iterations_per_step, t.steps_per_second * 1e-3, t.ok ? "" : "  (a step failed)");
    }
  }
  return 0;
}

}  // namespace vascsim::cli

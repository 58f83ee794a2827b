// `vascsim bench traversal`: wall time and real-time factor of a full maze traversal (issue 4),
// for each solver preset, without writing a log. Numbers go to stdout; nothing is asserted.
#include <chrono>
#include <cstdio>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"

namespace vascsim::cli {

namespace {

const std::vector<OptionSpec> kOptions = {
    {"scene", "FILE", "scene to traverse (default scenes/maze_default.json)"},
    {"repeat", "K", "runs per preset; the fastest is reported (default 3)"},
    {"help", "", "show this help"},
};

class DiscardSink : public FrameSink {
 public:
  void write(double, const std::vector<double>&) override {}
};

}  // namespace

int run_bench_traversal(int argc, char** argv) {
  Args args(argc, argv, 3, kOptions);
  if (args.flag("help")) {
    std::printf("usage: vascsim bench traversal [--scene FILE] [--repeat K]\n\noptions:\n%s",
                format_options(kOptions).c_str());
    return 0;
  }
  const std::string file = args.value("scene").value_or("scenes/maze_default.json");
  const int repeat = static_cast<int>(args.integer("repeat", 3, 1, 100));
  const Scene base = read_scene_file(file);
  if (!base.has_environment) throw UsageError("scene " + file + " has no maze to traverse");
  std::printf("traversal of %s (one core, frames not written)\n", file.c_str());
  // "newton" counts the committed steps' iterations; "all tries" adds those of attempts that were
  // rejected and retried shorter, the work the wall time paid for.
  std::printf("%-9s %10s %8s %9s %10s %11s %10s %8s %12s\n", "preset", "simulated", "steps", "newton", "all tries",
              "wall [s]", "real-time", "goal", "tip rms [mm]");
  for (const char* preset : {"fast", "balanced", "accurate"}) {
    Scene scene = base;
    apply_solver_preset(preset, scene.solver);
    double best = 1e300;
    RunStatistics stats;
    for (int k = 0; k < repeat; ++k) {
      Run run(compile(scene));
      DiscardSink sink;
      run.run(sink);
      if (run.statistics().wall_time < best) {
        best = run.statistics().wall_time;
        stats = run.statistics();
      }
    }
    std::printf("%-9s %9.2fs %8d %9lld %10lld %11.3f %9.1fx %8s %12.3f%s\n", preset, stats.simulated_time,
                stats.steps, stats.newton_iterations, stats.newton_iterations_all, best, stats.simulated_time / best,
                stats.goal_reached ? "yes" : "NO", 1e3 * stats.tip_error_rms,
                stats.failed ? ("  FAILED: " + stats.failure).c_str() : "");
  }
  return 0;
}

}  // namespace vascsim::cli

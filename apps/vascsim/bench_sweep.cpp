// `vascsim bench sweep`: what a sweep costs beyond its runs (issue 13: under 50 ms a run), and
// whether local --jobs 2 keeps both cores busy. Nothing is asserted; numbers go to stdout.
//
// Overhead: 100 tiny runs (a 5-node rod in free space, 10 steps: the run itself is well under a
// millisecond) through the whole path: reading and expanding the sweep file, checking every
// scene and writing the manifest and the run scenes; one `vascsim run` process per run, one at
// a time (forked, the default, and exec'd, --exec, for comparison); and the merge (tables,
// and the figures apart). The overhead per run is all of that, less the runs' own simulation
// time (summary.json wall_time), over the number of runs.
//
// Utilisation: maze runs of a fraction of a second each, --jobs 2: the CPU time of the run
// processes over the wall time times the two slots.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "apps/sweep/sweep_directory.h"
#include "apps/sweep/sweep_merge.h"
#include "apps/sweep/sweep_runner.h"
#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "sim/io/sweep_expand.h"
#include "sim/io/sweep_outcome.h"
#include "sim/io/sweep_spec.h"
#include "sim/scene/input_error.h"

namespace vascsim::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::vector<OptionSpec> kOptions = {
    {"runs", "N", "tiny runs of the overhead measurement (default 100)"},
    {"scene", "FILE", "scene of the utilisation measurement (default scenes/maze_default.json)"},
    {"busy-runs", "N", "runs of the utilisation measurement (default 12)"},
    {"duration", "T", "simulated time of each utilisation run in s (default 20)"},
    {"dir", "DIR", "where to write the sweeps (default: a new folder in the temporary directory, removed after)"},
    {"help", "", "show this help"},
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void write(const fs::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) throw InputError(path.string() + ": cannot write");
}

struct Phase {
  double expand = 0, run = 0, merge_tables = 0, merge_plots = 0, simulation = 0, processes = 0;
  sweep::RunnerReport report;
};

// One sweep from its file to its merged table; times of each phase.
Phase measure(const fs::path& sweep_file, const fs::path& out, int jobs, bool exec) {
  Phase p;
  auto t = Clock::now();
  std::ifstream f(sweep_file, std::ios::binary);
  std::ostringstream text;
  text << f.rdbuf();
  const SweepPlan plan = expand_sweep(read_sweep_text(text.str(), sweep_file.string()));
  bool resumed = false;
  const sweep::SweepDirectory dir = sweep::prepare_sweep_directory(plan, text.str(), out.string(), false, resumed);
  p.expand = seconds_since(t);

  sweep::RunnerOptions options;
  options.jobs = jobs;
  options.quiet = true;
  options.progress = false;
  if (!exec) options.run_command = run_command_line;
  for (std::size_t i = 0; i < dir.manifest.runs.size(); ++i) options.selection.push_back(i);
  t = Clock::now();
  p.report = sweep::run_sweep_entries(dir, options);
  p.run = seconds_since(t);
  if (p.report.failed) throw InputError(out.string() + ": " + std::to_string(p.report.failed) + " benchmark runs failed");
  for (std::size_t i = 0; i < dir.manifest.runs.size(); ++i) {
    const RunOutcome o = read_run_outcome(sweep::run_directory(dir, i));
    p.simulation += o.wall_time;
    p.processes += o.process.wall_time;
  }
  t = Clock::now();
  sweep::merge_sweep(dir, false, false);
  p.merge_tables = seconds_since(t);
  t = Clock::now();
  sweep::merge_sweep(dir, true, true);
  p.merge_plots = seconds_since(t) - p.merge_tables;
  return p;
}

}  // namespace

int run_bench_sweep(int argc, char** argv) {
  Args args(argc, argv, 3, kOptions);
  if (args.flag("help")) {
    std::printf("usage: vascsim bench sweep [--runs N] [--scene FILE] [--busy-runs N] [--duration T] [--dir DIR]\n\n"
                "options:\n%s",
                format_options(kOptions).c_str());
    return 0;
  }
  const long long runs = args.integer("runs", 100, 1, 100000);
  const long long busy_runs = args.integer("busy-runs", 12, 2, 10000);
  const double duration = args.number("duration", 20.0, 1e-3, 1e4);
  const std::string scene = fs::absolute(args.value("scene").value_or("scenes/maze_default.json")).string();
  const bool own_dir = !args.value("dir");
  const fs::path root = own_dir ? fs::temp_directory_path() / ("vascsim_bench_sweep_" + std::to_string(::getpid()))
                                : fs::path(*args.value("dir"));
  std::error_code ec;
  if (fs::exists(root, ec) && !fs::is_empty(root, ec)) throw InputError(root.string() + ": not empty");
  fs::create_directories(root, ec);

  write(root / "tiny.json", R"({"format": "vascsim-scene/1", "name": "tiny", "maze": null,
  "rod": {"nodes": 5, "length": 0.1}, "loads": {"point": [{"node": 4, "force": [0, 1e-4]}]},
  "run": {"duration": 0.01, "output_interval": 0.01}})");
  write(root / "tiny_sweep.json", R"({"format": "vascsim-sweep/1", "scene": "tiny.json",
  "axes": {"/loads/point/0/force/1": {"from": 1e-5, "to": 1e-4, "count": )" + std::to_string(runs) + "}}}");

  std::printf("sweep overhead: %lld tiny runs (5-node rod, 10 steps), one at a time; %d cores here\n", runs,
              sweep::available_cores());
  std::printf("%-8s %10s %10s %10s %10s %12s %12s %14s\n", "start", "expand", "runs", "merge", "plots", "simulation",
              "run process", "overhead/run");
  std::printf("%-8s %10s %10s %10s %10s %12s %12s %14s\n", "", "ms", "ms", "ms", "ms", "ms", "ms/run", "ms");
  for (const bool exec : {false, true}) {
    const Phase p = measure(root / "tiny_sweep.json", root / (exec ? "tiny_exec" : "tiny_fork"), 1, exec);
    const double n = static_cast<double>(runs);
    const double overhead = (p.expand + p.run + p.merge_tables - p.simulation) / n;
    std::printf("%-8s %10.1f %10.1f %10.1f %10.1f %12.2f %12.2f %14.2f\n", exec ? "exec" : "fork", 1e3 * p.expand,
                1e3 * p.run, 1e3 * p.merge_tables, 1e3 * p.merge_plots, 1e3 * p.simulation, 1e3 * p.processes / n,
                1e3 * overhead);
  }
  std::printf("(overhead/run: expand + runs + merge tables - the runs' own simulation time, over the runs;\n"
              " run process: a run's process from fork to exit as its status.json records it; plots are\n"
              " drawn once per axis, not per run, so they are listed apart)\n\n");

  write(root / "busy_sweep.json", R"({"format": "vascsim-sweep/1", "scene": ")" + scene + R"(",
  "axes": {"/maze/seed": {"from": 1, "to": )" + std::to_string(busy_runs) + R"(}},
  "overrides": {"/run/duration": )" + std::to_string(duration) + "}}");
  const Phase busy = measure(root / "busy_sweep.json", root / "busy", 2, false);
  std::printf("utilisation: %lld runs of %s for %g s simulated, --jobs 2\n", busy_runs, scene.c_str(), duration);
  std::printf("  wall %.2f s, CPU time of the runs %.2f s: %.0f%% of 2 job slots (mean run %.0f ms)\n",
              busy.report.wall_time, busy.report.cpu_time, 100 * busy.report.utilisation(),
              1e3 * busy.processes / static_cast<double>(busy_runs));
  if (own_dir) fs::remove_all(root, ec);
  return 0;
}

}  // namespace vascsim::cli

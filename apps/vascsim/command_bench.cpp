#include <cstdio>
#include <cstring>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"

namespace vascsim::cli {

namespace {

// One entry per benchmark; each lives in bench_<name>.cpp. argv[2] is the benchmark name.
struct Benchmark {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);
};

const std::vector<Benchmark>& benchmarks() {
  static const std::vector<Benchmark> table = {
      {"speed", "rod core: time per Newton iteration and per step, N = 10 .. 100000", run_bench_speed},
      {"accuracy", "error against wall time: rod references over dt, N, tolerance, scheme and preset; the maze traversals (CSV)", run_bench_accuracy},
      {"traversal", "full maze traversal: wall time and real-time factor per preset", run_bench_traversal},
      {"sweep", "sweep overhead per run (expand, process start, merge) on 100 tiny runs; --jobs 2 utilisation", run_bench_sweep},
#if defined(VASCSIM_HAVE_RENDER) || defined(VASCSIM_RENDER_PROGRAM)
      {"render", "renderer frames/s at 720p and 1080p, MP4 and PNG", run_bench_render},
      {"replay", "replay server: frame latency from a client, open time and memory on a 10^6-frame log", run_bench_replay},
#endif
  };
  return table;
}

}  // namespace

int run_bench_command(int argc, char** argv) {
  if (argc < 3 || !std::strcmp(argv[2], "--help")) {
    std::printf("usage: vascsim bench <benchmark> [options]   (vascsim bench <benchmark> --help)\n\nbenchmarks:\n");
    for (const auto& b : benchmarks()) std::printf("  %-10s %s\n", b.name, b.summary);
    return argc < 3 ? 2 : 0;
  }
  for (const auto& b : benchmarks())
    if (!std::strcmp(b.name, argv[2])) return b.run(argc, argv);
  throw UsageError(std::string("unknown benchmark '") + argv[2] + "'");
}

}  // namespace vascsim::cli

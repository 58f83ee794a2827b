// The subcommand table. Each subcommand lives in its own command_<name>.cpp and parses its own
// options with cli::Args; it throws UsageError or InputError for the user's mistakes.
#pragma once

#include <vector>

#include "apps/vascsim/renderer_program.h"
#include "sim/scene/scene.h"

namespace vascsim::cli {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);  // argv[1] is the command name
};

const std::vector<Command>& commands();
// Warns on stderr, as `vascsim <command>`, of each field the scene file gave that its
// configuration does not use (sim/scene/unused_fields.h).
void warn_unused_fields(const char* command, const Scene& scene);
// What main does: --version, --help, or the subcommand argv[1], its errors printed and turned
// into exit codes (2 for usage and input errors, 3 for internal ones). The sweep runs
// `vascsim run` through it in forked children.
int run_command_line(int argc, char** argv);

int run_maze_command(int argc, char** argv);
int run_vessels_command(int argc, char** argv);
int run_export_command(int argc, char** argv);
int run_run_command(int argc, char** argv);
int run_sweep_command(int argc, char** argv);
int run_bench_command(int argc, char** argv);
int run_bench_traversal(int argc, char** argv);
int run_bench_speed(int argc, char** argv);
int run_bench_accuracy(int argc, char** argv);
int run_bench_sweep(int argc, char** argv);
#if defined(VASCSIM_HAVE_RENDER)
int run_render_command(int argc, char** argv);
int run_diff_command(int argc, char** argv);
int run_replay_command(int argc, char** argv);
int run_bench_replay(int argc, char** argv);
int run_bench_render(int argc, char** argv);
#elif defined(VASCSIM_RENDER_PROGRAM)
// This program has no renderer: the commands that draw hand their command line over to
// vascsim-render, which has (apps/vascsim/renderer_program.h).
inline int run_render_command(int argc, char** argv) { return run_in_renderer(argc, argv); }
inline int run_diff_command(int argc, char** argv) { return run_in_renderer(argc, argv); }
inline int run_replay_command(int argc, char** argv) { return run_in_renderer(argc, argv); }
inline int run_bench_replay(int argc, char** argv) { return run_in_renderer(argc, argv); }
inline int run_bench_render(int argc, char** argv) { return run_in_renderer(argc, argv); }
#endif

}  // namespace vascsim::cli

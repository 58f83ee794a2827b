#include "apps/vascsim/commands.h"

namespace vascsim::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"maze", "generate and solve a maze; write walls and path as JSON", run_maze_command},
      {"vessels", "build and route a vessel network; write lumen, walls and path as JSON", run_vessels_command},
      {"run", "simulate a scene; stream the frame log and write summary.json", run_run_command},
      {"export", "write a run's frame log as CSV files (MATLAB, Excel, R)", run_export_command},
      {"bench", "measure speed and accuracy (vascsim bench --help)", run_bench_command},
#ifdef VASCSIM_HAVE_RENDER
      {"render", "render a run's frame log to MP4, PNG frames and plots", run_render_command},
      {"diff", "compare two PNG images (golden-image tests)", run_diff_command},
      {"replay", "serve a run (or two) to a web browser: scrub, zoom, compare, export", run_replay_command},
#endif
  };
  return table;
}

}  // namespace vascsim::cli

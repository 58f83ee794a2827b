#include "apps/vascsim/commands.h"

namespace vascsim::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"maze", "generate and solve a maze; write walls and path as JSON", run_maze_command},
      {"bench", "measure speed and accuracy (vascsim bench --help)", run_bench_command},
  };
  return table;
}

}  // namespace vascsim::cli

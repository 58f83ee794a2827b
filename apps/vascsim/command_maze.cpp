#include "apps/vascsim/commands.h"

#include <cstdio>

#include "apps/vascsim/cli_args.h"

namespace vascsim::cli {

int run_maze_command(int argc, char** argv) {
  (void)argc; (void)argv;
  std::fprintf(stderr, "not yet\n");
  return 1;
}

}  // namespace vascsim::cli

// vascsim: the command line. Dispatches to one subcommand per file (command_<name>.cpp).
// Exit codes: 0 success, 1 a completed job whose result is negative (diff over tolerance,
// simulation that diverged), 2 bad input or usage.
#include "apps/vascsim/commands.h"

int main(int argc, char** argv) { return vascsim::cli::run_command_line(argc, argv); }

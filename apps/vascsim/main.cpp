// vascsim: the command line. Dispatches to one subcommand per file (command_<name>.cpp).
// Exit codes: 0 success, 1 a completed job whose result is negative (diff over tolerance,
// simulation that diverged), 2 bad input or usage.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "sim/io/provenance.h"
#include "sim/scene/input_error.h"

namespace {

void print_help() {
  std::printf(
      "vascsim: simulate a magnetically steered soft robot in a 2D vascular network, and render it.\n\n"
      "usage: vascsim <command> [options]   (vascsim <command> --help, or vascsim help <command>, for its options)\n"
      "       vascsim --version\n\n"
      "commands:\n");
  for (const auto& c : vascsim::cli::commands()) std::printf("  %-10s %s\n", c.name, c.summary);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && !std::strcmp(argv[1], "--version")) {
    std::printf("%s\n", vascsim::version_line().c_str());
    return 0;
  }
  // `vascsim help COMMAND` is `vascsim COMMAND --help`, as git and cargo users expect.
  char help_flag[] = "--help";
  char* help_argv[] = {argv[0], argc > 2 ? argv[2] : nullptr, help_flag, nullptr};
  if (argc == 3 && !std::strcmp(argv[1], "help")) {
    argc = 3;
    argv = help_argv;
  }
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    print_help();
    return argc < 2 ? 2 : 0;
  }
  const vascsim::cli::Command* command = nullptr;
  for (const auto& c : vascsim::cli::commands())
    if (!std::strcmp(c.name, argv[1])) command = &c;
  if (!command) {
    std::fprintf(stderr, "vascsim: unknown command '%s' (see vascsim --help)\n", argv[1]);
    return 2;
  }
  try {
    return command->run(argc, argv);
  } catch (const vascsim::cli::UsageError& e) {
    std::fprintf(stderr, "vascsim %s: %s (see vascsim %s --help)\n", command->name, e.what(), command->name);
    return 2;
  } catch (const vascsim::InputError& e) {
    std::fprintf(stderr, "vascsim %s: %s\n", command->name, e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vascsim %s: internal error: %s\n", command->name, e.what());
    return 3;
  }
}

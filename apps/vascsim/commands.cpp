#include "apps/vascsim/commands.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "apps/vascsim/cli_args.h"
#include "sim/io/provenance.h"
#include "sim/scene/input_error.h"

namespace vascsim::cli {

namespace {

void print_help() {
  std::printf(
      "vascsim: simulate a magnetically steered soft robot in a 2D vascular network, and render it.\n\n"
      "usage: vascsim <command> [options]   (vascsim <command> --help, or vascsim help <command>, for its options)\n"
      "       vascsim --version\n\n"
      "commands:\n");
  for (const auto& c : commands()) std::printf("  %-10s %s\n", c.name, c.summary);
}

}  // namespace

void warn_unused_fields(const char* command, const Scene& scene) {
  for (const UnusedField& u : scene.unused_given)
    std::fprintf(stderr, "vascsim %s: warning: %s: %s has no effect here: %s%s\n", command, scene.file.c_str(),
                 u.pointer.c_str(), u.why.c_str(),
                 std::strcmp(command, "run") == 0 ? " (summary.json /unused_fields)" : " (left out of the scene written)");
}

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"maze", "generate and solve a maze; write walls and path as JSON", run_maze_command},
      {"vessels", "build and route a vessel network; write lumen, walls and path as JSON", run_vessels_command},
      {"run", "simulate a scene; stream the frame log and write summary.json", run_run_command},
      {"sweep", "run a parameter sweep locally, with GNU parallel or Slurm; merge its results", run_sweep_command},
      {"export", "write a run's frame log as CSV files (MATLAB, Excel, R)", run_export_command},
      {"bench", "measure speed and accuracy (vascsim bench --help)", run_bench_command},
#if defined(VASCSIM_HAVE_RENDER) || defined(VASCSIM_RENDER_PROGRAM)
      {"render", "render a run's frame log to MP4, PNG frames and plots", run_render_command},
      {"diff", "compare two PNG images (golden-image tests)", run_diff_command},
      {"replay", "serve a run (or two) to a web browser: scrub, zoom, compare, export", run_replay_command},
#endif
  };
  return table;
}

namespace {

int dispatch(int argc, char** argv) {
  if (argc == 2 && !std::strcmp(argv[1], "--version")) {
    std::printf("%s\n", version_line().c_str());
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
  const Command* command = nullptr;
  for (const auto& c : commands())
    if (!std::strcmp(c.name, argv[1])) command = &c;
  if (!command) {
    std::fprintf(stderr, "vascsim: unknown command '%s' (see vascsim --help)\n", argv[1]);
    return 2;
  }
  try {
    return command->run(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "vascsim %s: %s (see vascsim %s --help)\n", command->name, e.what(), command->name);
    return 2;
  } catch (const InputError& e) {
    std::fprintf(stderr, "vascsim %s: %s\n", command->name, e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vascsim %s: internal error: %s\n", command->name, e.what());
    return 3;
  }
}

}  // namespace

int run_command_line(int argc, char** argv) {
  const std::string name = argc >= 2 ? std::string("vascsim ") + argv[1] : "vascsim";
  const int code = dispatch(argc, argv);
  // What a script reads from standard output (a run's result line, a maze's JSON, a sweep's
  // table) lost to a full disk must not end in exit 0, as it would once the buffer is dropped.
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int flush_errno = errno;
  if (!flushed || std::ferror(stdout)) {
    std::fprintf(stderr, "%s: cannot write to standard output (%s)\n", name.c_str(),
                 flush_errno ? std::strerror(flush_errno) : "write error");
    return code == 0 ? 2 : code;
  }
  return code;
}

}  // namespace vascsim::cli

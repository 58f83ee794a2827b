// Runs the vascsim executable from tests and captures its exit code and output, so that the
// command line (not only the library) is what the tests check.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace vascsim::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr interleaved
};

// Runs `VASCSIM_EXE <arguments>` through the shell (arguments are passed verbatim).
CommandResult run_vascsim(const std::string& arguments);
// Runs a shell command line (stdout and stderr captured together).
CommandResult run_shell(const std::string& command_line);
// As run_vascsim, but the process is killed (SIGKILL) after `seconds` if still running.
CommandResult run_vascsim_killed_after(const std::string& arguments, double seconds);
// How start_vascsim starts the command.
struct StartOptions {
  std::string output = "/dev/null";  // the file its stdout and stderr go to
  bool own_process_group = false;    // in a process group (and session) of its own, as a Slurm task's
  int ignored_signal = 0;            // a signal it starts ignoring, as nohup's SIGHUP, or 0
};
// A scene whose run outlasts any test's wait in every build, for tests that signal a running run:
// fixed 10 us steps (about 0.1 s of simulated time per wall second under ASan, a few times that
// in Release) on a free rod, a frame every 10 ms. Error control takes 20 ms steps on a rod at
// rest: a Release build ran the 1000 s of such a scene in about 0.5 s, and it ended before the
// signal came.
inline constexpr const char* kLongRunScene =
    R"({"maze": null, "rod": {"nodes": 40}, "solver": {"dt": 1e-5}, "run": {"duration": 1000, "output_interval": 0.01}})";
// Starts `VASCSIM_EXE <arguments>` without waiting for it, for tests that signal a running
// command. Returns its process id.
pid_t start_vascsim(const std::vector<std::string>& arguments, const StartOptions& options = {});
// Waits until every one of `paths` exists, up to `seconds`; whether they all do.
bool wait_for_files(const std::vector<std::string>& paths, double seconds = 30);
// A fresh, empty temporary directory unique to this test process and `name`.
std::string fresh_temp_dir(const std::string& name);
// Writes `text` to `path`.
void write_text(const std::string& path, const std::string& text);
std::string read_text(const std::string& path);
std::string source_path(const std::string& relative);  // path inside the repository

}  // namespace vascsim::test

// One run of a sweep as one `vascsim run` process: started in the sweep directory (so what it
// prints names runs/<id>/..., the same on every engine and in every DIR), its output going to
// runs/<id>/run.log, and, when it exits, its exit code or signal, wall and CPU time written to
// runs/<id>/status.json (sim/io/sweep_outcome.h). A lock on runs/<id>/.lock, held while the
// process runs, keeps two sweeps (two local runners, a resubmitted array task) from running the
// same entry at once.
//
// The process is forked from the sweep and runs the `vascsim run` command there (`run_command`),
// or execs the vascsim executable. Forking is the default: the forked child starts in about a
// millisecond (vascsim bench sweep), an exec'd one in several (once 40-100 ms, when vascsim still
// loaded the renderer's libraries: apps/vascsim/renderer_program.h).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <functional>
#include <string>

#include "apps/sweep/sweep_directory.h"

namespace vascsim::sweep {

// The running vascsim executable (/proc/self/exe), for the child processes and for the
// command lines written for engines.
std::string vascsim_executable();

class RunProcess {
 public:
  // Takes the run's lock; false (and nothing started) if another process holds it.
  bool lock(const SweepDirectory& sweep, std::size_t index);
  // Starts `vascsim run runs/<id>/scene.json --out runs/<id> --force --quiet`: in a forked child
  // through `run_command` (the command line's dispatcher: argc, argv as main gets them) when it
  // is given, else by exec'ing `exe`. Throws InputError if the process cannot be started.
  // Removes the run's previous status first.
  void start(const std::string& exe, const std::function<int(int, char**)>& run_command);
  pid_t pid() const { return pid_; }
  std::size_t index() const { return index_; }
  // Records how the process ended (`wait_status` from waitpid, its CPU time in s). When
  // `interrupted` (the sweep itself was stopped), nothing is recorded, so the run counts as
  // missing and a resume runs it again. Releases the lock.
  void finish(int wait_status, double cpu_time, bool interrupted);
  double elapsed() const;  // s since start

  RunProcess() = default;
  RunProcess(RunProcess&& other) noexcept;
  RunProcess& operator=(RunProcess&& other) noexcept;
  RunProcess(const RunProcess&) = delete;
  RunProcess& operator=(const RunProcess&) = delete;
  ~RunProcess();

 private:
  std::string sweep_dir_, run_dir_, id_;
  std::size_t index_ = 0;
  int lock_fd_ = -1;
  pid_t pid_ = -1;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace vascsim::sweep

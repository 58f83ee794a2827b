// Runs entries of a sweep directory as local `vascsim run` processes, up to `jobs` at a time:
// the local engine of `vascsim sweep`, and, with one entry, what `--run-index K` does for an
// external engine (GNU parallel, a Slurm array task).
//
// Resume is the default: a run whose summary says it completed is skipped; one that failed is
// skipped unless `retry_failed`; missing ones (never started, interrupted) are run. Ctrl-C
// (SIGINT) or SIGTERM stops cleanly: no new run starts, the running ones are stopped (a terminal
// sends them the SIGINT itself; a signal to the sweep alone is passed on as SIGTERM) and left
// missing, so completed runs stay intact and the next invocation picks up where this one
// stopped.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "apps/sweep/sweep_directory.h"

namespace vascsim::sweep {

struct RunnerOptions {
  int jobs = 1;
  bool retry_failed = false;
  std::vector<std::size_t> selection;  // the entries to consider (all of them, a shard, one)
  bool progress = true;                // counts and ETA on stderr, when it is a terminal
  bool quiet = false;                  // no per-failure and final lines
  // The command line's dispatcher, to run `vascsim run` in forked children (run_process.h);
  // empty: exec the vascsim executable for each run.
  std::function<int(int, char**)> run_command;
};

struct RunnerReport {
  std::size_t selected = 0;        // entries considered
  std::size_t already_done = 0;    // skipped: completed before
  std::size_t already_failed = 0;  // skipped: failed before (no retry_failed)
  std::size_t busy = 0;            // skipped: another process holds the run's lock
  std::vector<std::size_t> busy_entries;  // their indices, to look at again when this runner ends
  std::size_t ran = 0, done = 0, failed = 0;  // started by this invocation, and how they ended
  std::size_t not_started = 0;     // left when interrupted
  bool interrupted = false;
  int signal = 0;                  // the signal that interrupted the sweep
  int jobs = 1;
  double wall_time = 0;            // s, from the first start to the last exit
  double cpu_time = 0;             // s, user + system time of the run processes
  // Share of the job slots the runs kept busy: CPU time over wall time times slots.
  double utilisation() const { return wall_time > 0 ? cpu_time / (wall_time * jobs) : 0.0; }
};

RunnerReport run_sweep_entries(const SweepDirectory& sweep, const RunnerOptions& options);
// The processors this process may run on (sched_getaffinity), the default for --jobs.
int available_cores();
// "/control/kp = 4, /maze/seed = 3" of entry `index`.
std::string describe_entry(const SweepManifest& manifest, std::size_t index);

}  // namespace vascsim::sweep

// The same manifest on external engines: files that make GNU parallel or Slurm run every entry
// of a sweep directory as `vascsim sweep DIR --run-index K`, then merge. vascsim schedules
// nothing itself there; the engines' own resume (parallel's --joblog --resume, resubmitting a
// Slurm array) works because --run-index skips entries that completed.
//
// GNU parallel (DIR/parallel/): jobs.txt (one index per line) and run.sh, the exact command:
//   parallel --jobs N --joblog DIR/parallel/joblog --resume [--sshloginfile HOSTS]
//            --arg-file DIR/parallel/jobs.txt VASCSIM sweep DIR --run-index {}
// Slurm (DIR/slurm/): array.sbatch, one array task per entry (sbatch --array=0-(n-1)%M; arrays
// longer than the cluster's MaxArraySize are split into chunks with an index offset),
// merge.sbatch (`vascsim sweep merge DIR --force`), and submit.sh, which submits the arrays and
// the merge with a dependency on all of them (afterany: failed runs are rows of the table too).
// Paths in these files are absolute: the engines run them from elsewhere, on other hosts that
// must see DIR and the vascsim executable at the same paths (a shared file system).
#pragma once

#include <string>
#include <vector>

#include "apps/sweep/sweep_directory.h"

namespace vascsim::sweep {

struct ParallelOptions {
  int jobs = 0;                // parallel --jobs: slots per host; 0 = one per core on each host
  std::string sshloginfile;    // host list for parallel --sshloginfile, or empty for this host
  bool retry_failed = false;   // the entries re-run failed runs (with parallel --resume-failed)
};

struct SlurmOptions {
  int max_parallel = 0;        // the %M of --array: most tasks running at once; 0 = no limit
  int chunk = 1000;            // most tasks per array (Slurm's default MaxArraySize is 1001)
  std::string partition;       // --partition, or empty for the default
  std::string time_limit;      // --time per task, or empty
  int cpus_per_task = 1;       // a run uses one core
  bool retry_failed = false;
};

// Writes the files and returns the paths written, the command to run first. Refuses to replace
// existing ones unless `force`. Throws InputError.
std::vector<std::string> emit_gnu_parallel(const SweepDirectory& sweep, const ParallelOptions& options, bool force);
std::vector<std::string> emit_slurm(const SweepDirectory& sweep, const SlurmOptions& options, bool force);
// What emit_slurm refuses, checked before a sweep directory `sweep_dir` is made: a partition or
// time that is not one #SBATCH word, a directory or executable path #SBATCH lines cannot name.
void check_slurm_options(const SlurmOptions& options, const std::string& sweep_dir);
// The host list `name` for parallel --sshloginfile as the absolute path run.sh names, found where
// parallel looks when run.sh runs from elsewhere (this directory, then ~/.parallel; '..' and '.'
// are parallel's ~/.parallel/sshloginfile and /etc/parallel/sshloginfile). Throws InputError for
// '-' (run.sh's stdin is not a host list), a file that is missing, unreadable or not a regular
// file, and a list without a host line (parallel would run nothing, silently).
std::string resolve_sshloginfile(const std::string& name);

// `text` quoted for a POSIX shell.
std::string shell_quote(const std::string& text);

}  // namespace vascsim::sweep

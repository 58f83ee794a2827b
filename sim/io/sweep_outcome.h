// What became of one run of a sweep, read from its directory DIR/runs/<id>/: the run's own
// summary.json (written by `vascsim run` when it ends, successful or not) and status.json (written
// by the sweep when the `vascsim run` process exits: its exit code or signal, wall and CPU time,
// host). A run is
//   done     summary.json says ok
//   failed   summary.json says it failed (the simulation diverged, or a signal stopped it that
//            the sweep saw end it: status.json), or the process ended without a summary (bad
//            input, a crash, killed by a signal: status.json says which)
//   missing  neither: never started, or stopped by the sweep's own Ctrl-C or SIGTERM (it records
//            no status of runs it stops; their summary says /stopped_by), or the machine went away
// Resume runs the missing ones; --retry-failed also the failed ones.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vascsim {

// The figures a sweep tabulates from each run's summary, in results.csv column order. All are
// deterministic: the same scene gives the same values on any engine.
struct SweepMetric {
  const char* column;  // results.csv header, with its SI unit: "tip_error_rms_m"
  const char* label;   // for tables and plots: "tip error RMS"
  const char* unit;    // display unit in tables and plots: "mm"
  double scale;        // display value = SI value * scale
  bool whole = false;  // a count (or 0/1): an integer in results.json
};
const std::vector<SweepMetric>& sweep_metrics();
// Indices into sweep_metrics(), for the code that picks figures by meaning.
enum SweepMetricIndex : std::size_t {
  kGoalReached, kGoalTime, kTipErrorRms, kTipErrorMax, kActuationForceMax, kContactForceMax, kFeedForceMax,
  kMaxPenetration, kSteps, kNewtonIterations, kRejectedSteps, kMetricCount
};

struct RunStatusRecord {
  int exit_code = -1;     // of `vascsim run`, or -1 when it was killed
  int signal = 0;         // the signal that killed it, or 0
  double wall_time = 0;   // s, process start to exit (includes process start and reading the scene)
  double cpu_time = 0;    // s, user + system time of the process
  std::string host;
};

struct RunOutcome {
  std::string status = "missing";  // "done", "failed" or "missing"
  std::string failure;             // why it failed (deterministic text; empty unless failed)
  std::vector<double> metrics;     // sweep_metrics() order; NaN where unknown
  // How the tip was steered (summary.json's navigation.control_mode: "none" for a rod only pushed
  // from its root); empty where the run does not navigate or its summary does not say.
  std::string control_mode;
  // Timing: varies from run to run; kept apart (results.csv puts these columns last).
  double wall_time = -1;           // s, the simulation loop (summary.json wall_time), -1 unknown
  double real_time_factor = -1;    // simulated / wall time, -1 unknown
  bool has_status = false;
  RunStatusRecord process;         // from status.json when has_status
};

// Reads DIR/runs/<id>/. Never throws for what a run left behind (a corrupt summary is a failed
// run that says so); throws InputError only if the directory cannot be read at all.
RunOutcome read_run_outcome(const std::string& run_dir);
// status.json's text.
std::string run_status_json(const RunStatusRecord& status);

}  // namespace vascsim

// vascsim sweep: parameter sweeps (docs/sweeps.md). Parses the options and hands over to
// apps/sweep: the sweep directory, the local runner, the files for external engines, the merge.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "apps/sweep/run_process.h"
#include "apps/sweep/sweep_directory.h"
#include "apps/sweep/sweep_emit.h"
#include "apps/sweep/sweep_merge.h"
#include "apps/sweep/sweep_runner.h"
#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "sim/io/output_file.h"
#include "sim/io/sweep_expand.h"
#include "sim/io/sweep_outcome.h"
#include "sim/io/sweep_spec.h"
#include "sim/scene/input_error.h"

namespace vascsim::cli {

namespace {

namespace fs = std::filesystem;

const std::vector<OptionSpec> kOptions = {
    {"out", "DIR", "the sweep directory to make or resume (with a SWEEP file)"},
    {"jobs", "N", "run processes at once (default: the number of cores); with --emit gnu-parallel, slots per host"},
    {"retry-failed", "", "also re-run runs that failed or were killed (default: skip them, run only missing ones)"},
    {"force", "", "replace a directory holding a different sweep (its runs are deleted), or emitted files"},
    {"shard", "I/N", "run only entries with index % N == I (0 <= I < N), for engines vascsim does not know"},
    {"run-index", "K", "run entry K of the manifest only (what an engine calls; needs the sweep DIR)"},
    {"emit", "ENGINE", "write the files for gnu-parallel or slurm into DIR and print the command; run nothing"},
    {"sshloginfile", "FILE", "--emit gnu-parallel: the hosts to run on (parallel --sshloginfile)"},
    {"max-parallel", "M", "--emit slurm: at most M array tasks at once (the %M of --array; default no limit)"},
    {"partition", "P", "--emit slurm: the partition to submit to"},
    {"time", "T", "--emit slurm: time limit per task (sbatch --time, e.g. 0:30:00)"},
    {"dry-run", "", "check the sweep and list its runs; write nothing"},
    {"exec", "", "start each run by exec'ing vascsim (default: fork, which skips loading its libraries again)"},
    {"no-merge", "", "do not merge when every run has ended"},
    {"quiet", "", "no progress line, no per-failure lines, no table"},
    {"help", "", "show this help"},
};

const std::vector<OptionSpec> kMergeOptions = {
    {"force", "", "replace results.csv, results.json and plots from an earlier merge"},
    {"no-plots", "", "only the tables"},
    {"quiet", "", "do not print the summary table"},
    {"help", "", "show this help"},
};

void print_usage() {
  std::printf(
      "usage: vascsim sweep SWEEP.json --out DIR [--jobs N] [--retry-failed] [--shard I/N] [--force]\n"
      "       vascsim sweep DIR [--jobs N] [--retry-failed] [--shard I/N]      resume DIR\n"
      "       vascsim sweep DIR --run-index K [--retry-failed]                 run one entry (engines)\n"
      "       vascsim sweep SWEEP.json --out DIR --emit gnu-parallel [--jobs N] [--sshloginfile FILE]\n"
      "       vascsim sweep SWEEP.json --out DIR --emit slurm [--max-parallel M] [--partition P] [--time T]\n"
      "       vascsim sweep merge DIR [--force] [--no-plots]\n\n"
      "Expands the sweep file (format in docs/sweeps.md) into DIR/manifest.json and one scene per run\n"
      "(DIR/runs/<id>/scene.json), then runs each as its own `vascsim run` process, --jobs at a time.\n"
      "Invoking it again resumes: completed runs are skipped, missing ones run (--retry-failed: failed\n"
      "ones too). Ctrl-C stops cleanly; completed runs stay. When every run has ended it merges:\n"
      "DIR/results.csv, DIR/results.json, DIR/plots/ and a summary table (see vascsim sweep merge).\n"
      "Exit code 0 when every run completed, 1 if any failed or another runner still runs one, 2 for bad\n"
      "input, 130 (143 for SIGTERM) when interrupted.\n\n"
      "options:\n%s",
      format_options(kOptions).c_str());
}

// "I/N" of --shard.
void parse_shard(const std::string& text, std::size_t& i, std::size_t& n) {
  const auto slash = text.find('/');
  try {
    // Digits only: stoll would also take " 0", "+0" or "0x1" (as 0).
    if (slash == std::string::npos || text.find_first_not_of("0123456789/") != std::string::npos)
      throw std::invalid_argument("");
    std::size_t used = 0;
    const long long a = std::stoll(text.substr(0, slash), &used);
    if (used != slash) throw std::invalid_argument("");
    const std::string rest = text.substr(slash + 1);
    const long long b = std::stoll(rest, &used);
    if (used != rest.size() || b < 1 || a < 0 || a >= b || b > 1000000) throw std::invalid_argument("");
    i = static_cast<std::size_t>(a), n = static_cast<std::size_t>(b);
  } catch (const std::exception&) {
    throw UsageError("--shard: expected I/N with 0 <= I < N, such as 0/4, got '" + text + "'");
  }
}

int merge_command(int argc, char** argv) {
  Args args(argc, argv, 3, kMergeOptions);
  if (args.flag("help")) {
    std::printf("usage: vascsim sweep merge DIR [--force] [--no-plots] [--quiet]\n\n"
                "Tabulates every run of the sweep directory DIR: DIR/results.csv and DIR/results.json (one\n"
                "row per run: its overrides, status, the run's figures, then the timing columns), one figure\n"
                "per axis in DIR/plots/, and prints a summary per axis value. Failed and missing runs are rows\n"
                "that say so. Exit code 0 once written, whatever the runs' results.\n\noptions:\n%s",
                format_options(kMergeOptions).c_str());
    return 0;
  }
  if (args.positional().size() != 1) throw UsageError("expected exactly one sweep directory DIR");
#ifdef VASCSIM_RENDER_PROGRAM
  if (!args.flag("no-plots")) return run_in_renderer(argc, argv);  // the plots are drawn there
#endif
  const sweep::SweepDirectory dir = sweep::open_sweep_directory(args.positional().front());
  const sweep::MergeReport report = sweep::merge_sweep(dir, args.flag("force"), !args.flag("no-plots"));
  if (!args.flag("quiet")) std::printf("%s\n", report.table.c_str());
  for (const auto& path : report.written) std::printf("wrote %s\n", path.c_str());
  if (!report.note.empty()) std::printf("%s\n", report.note.c_str());
  return 0;
}

// Merges after a local run when every entry has ended and no earlier merge would be replaced.
void merge_after_run(const sweep::SweepDirectory& dir, bool quiet) {
  for (std::size_t i = 0; i < dir.manifest.runs.size(); ++i)
    if (read_run_outcome(sweep::run_directory(dir, i)).status == "missing") return;
  // Any of them: results.json or a plot left alone (results.csv deleted) made the merge refuse,
  // and the sweep exit 2 after every run had completed.
  if (const auto earlier = sweep::earlier_merge_outputs(dir); !earlier.empty()) {
    std::printf("%s is from an earlier merge: vascsim sweep merge %s --force refreshes the results\n",
                earlier.front().c_str(), dir.dir.c_str());
    return;
  }
#ifdef VASCSIM_RENDER_PROGRAM
  // The plots are drawn by vascsim-render: the merge runs there, as `vascsim sweep merge` would.
  if (!quiet) std::printf("\n");
  std::vector<std::string> merge = {"sweep", "merge", dir.dir};
  if (quiet) merge.push_back("--quiet");
  if (const int status = run_renderer_child(merge); status != 0)
    throw InputError("merging " + dir.dir + " failed (exit code " + std::to_string(status) + "); the runs are kept");
  return;
#endif
  const sweep::MergeReport report = sweep::merge_sweep(dir, false);
  if (!quiet) std::printf("\n%s\n", report.table.c_str());
  for (const auto& path : report.written) std::printf("wrote %s\n", path.c_str());
  if (!report.note.empty()) std::printf("%s\n", report.note.c_str());
}

}  // namespace

int run_sweep_command(int argc, char** argv) {
  if (argc >= 3 && std::string(argv[2]) == "merge") return merge_command(argc, argv);
  Args args(argc, argv, 2, kOptions);
  if (args.flag("help")) {
    print_usage();
    return 0;
  }
  if (args.positional().size() != 1) throw UsageError("expected one SWEEP file or sweep directory DIR");
  const std::string input = args.positional().front();
  const bool quiet = args.flag("quiet");
  const int jobs = static_cast<int>(args.integer("jobs", sweep::available_cores(), 1, 4096));
  const auto emit = args.value("emit");
  if (emit && *emit != "gnu-parallel" && *emit != "slurm")
    throw UsageError("--emit: expected gnu-parallel or slurm, got '" + *emit + "'");
  if (args.value("run-index") && (emit || args.value("shard")))
    throw UsageError("--run-index runs one entry; it does not go with --emit or --shard");
  // An option of another way of running would be ignored: refused, naming what it belongs to.
  const std::string mode = args.value("run-index") ? "--run-index" : emit ? "--emit " + *emit : "a local run";
  const std::vector<std::pair<std::string, std::vector<std::string>>> belongs = {
      {"jobs", {"a local run", "--emit gnu-parallel"}},  {"exec", {"a local run"}},
      {"sshloginfile", {"--emit gnu-parallel"}},           {"max-parallel", {"--emit slurm"}},
      {"partition", {"--emit slurm"}},                     {"time", {"--emit slurm"}},
      {"shard", {"a local run"}},                          {"no-merge", {"a local run"}}};
  for (const auto& [option, modes] : belongs) {
    if (!args.flag(option) || std::find(modes.begin(), modes.end(), mode) != modes.end()) continue;
    std::string list;
    for (const auto& m : modes) list += (list.empty() ? "" : " or ") + m;
    throw UsageError("--" + option + " goes with " + list + ", not with " + mode);
  }

  // Engine options are checked before a sweep directory is made, so a refusal writes nothing.
  sweep::SlurmOptions slurm;
  if (emit && *emit == "slurm") {
    slurm.max_parallel = static_cast<int>(args.integer("max-parallel", 0, 0, 100000));
    slurm.partition = args.value("partition").value_or("");
    slurm.time_limit = args.value("time").value_or("");
    if (args.value("time") && slurm.time_limit.empty()) throw UsageError("--time: expected a Slurm time such as 0:30:00, got ''");
    slurm.retry_failed = args.flag("retry-failed");
    sweep::check_slurm_options(slurm, args.value("out").value_or(input));
  }
  sweep::ParallelOptions parallel;
  if (emit && *emit == "gnu-parallel") {
    parallel.jobs = args.value("jobs") ? jobs : 0;
    if (const auto hosts = args.value("sshloginfile")) parallel.sshloginfile = sweep::resolve_sshloginfile(*hosts);
    parallel.retry_failed = args.flag("retry-failed");
  }

  // The sweep directory: made from a sweep file, or an existing one.
  sweep::SweepDirectory dir;
  std::error_code ec;
  if (fs::is_directory(input, ec)) {
    if (args.value("out")) throw UsageError("--out goes with a SWEEP file; " + input + " is a sweep directory already");
    if (args.flag("dry-run")) throw UsageError("--dry-run checks a SWEEP file");
    dir = sweep::open_sweep_directory(input);
  } else {
    if (args.value("run-index")) throw UsageError("--run-index needs the sweep directory DIR, not the sweep file");
    std::optional<NoticeOnSignal> notice(std::in_place, "vascsim sweep: interrupted while checking the sweep's scenes; nothing was written");
    // Read once: the sweep directory keeps the very text that was checked (a second read could
    // copy a file edited in between, unbounded).
    const std::string sweep_text = read_sweep_file_text(input);
    const SweepSpec spec = read_sweep_text(sweep_text, input);
    const SweepPlan plan = expand_sweep(spec);
    notice.reset();
    for (const SweepUnusedField& u : plan.unused)
      std::fprintf(stderr, "vascsim sweep: warning: %s has no effect in %zu of %zu runs: %s (each run's summary.json /unused_fields)\n",
                   u.pointer.c_str(), u.runs, plan.runs.size(), u.why.c_str());
    if (args.flag("dry-run")) {
      std::printf("sweep %s: %zu run%s of %s, every scene checked\n", spec.name.c_str(), plan.runs.size(),
                  plan.runs.size() == 1 ? "" : "s", spec.scene_path.c_str());
      const SweepManifest m = manifest_of(plan);
      for (std::size_t i = 0; i < m.runs.size(); ++i) std::printf("  %s  %s\n", m.runs[i].id.c_str(), sweep::describe_entry(m, i).c_str());
      return 0;
    }
    const auto out = args.value("out");
    if (!out) throw UsageError("--out DIR is required with a SWEEP file");
    bool resumed = false;
    notice.emplace("vascsim sweep: interrupted while writing the sweep directory " + *out +
                   "; the same command takes it up again");
    dir = sweep::prepare_sweep_directory(plan, sweep_text, *out, args.flag("force"), resumed);
    notice.reset();
    if (!quiet)
      std::printf("sweep %s: %zu run%s in %s%s\n", spec.name.c_str(), plan.runs.size(), plan.runs.size() == 1 ? "" : "s",
                  out->c_str(), resumed ? " (resuming)" : "");
  }
  const std::size_t count = dir.manifest.runs.size();

  if (emit) {
    std::vector<std::string> written;
    if (*emit == "gnu-parallel") {
      written = sweep::emit_gnu_parallel(dir, parallel, args.flag("force"));
      std::printf("wrote %s (%zu %s)\nrun it:   sh %s\nthen:     vascsim sweep merge %s\n", written[1].c_str(), count,
                  count == 1 ? "entry" : "entries", sweep::shell_quote(written[0]).c_str(), sweep::shell_quote(dir.dir).c_str());
    } else {
      written = sweep::emit_slurm(dir, slurm, args.flag("force"));
      std::printf("wrote %s and %s\nsubmit:   bash %s   (the array, then the merge after it)\n", written[1].c_str(),
                  written[2].c_str(), sweep::shell_quote(written[0]).c_str());
    }
    return 0;
  }

  sweep::RunnerOptions options;
  if (!args.flag("exec")) options.run_command = run_command_line;
  options.retry_failed = args.flag("retry-failed");
  options.quiet = quiet;
  options.progress = !quiet;
  if (const auto k = args.value("run-index")) {
    const long long index = args.integer("run-index", 0, 0, static_cast<long long>(count) - 1);
    options.jobs = 1;
    options.progress = false;
    options.selection = {static_cast<std::size_t>(index)};
    const sweep::RunnerReport r = sweep::run_sweep_entries(dir, options);
    const std::string id = dir.manifest.runs[static_cast<std::size_t>(index)].id;
    if (r.interrupted) return 128 + r.signal;
    if (r.already_done) std::printf("run %s: completed before; skipped\n", id.c_str());
    if (r.already_failed)
      std::printf("run %s: failed before; skipped (pass --retry-failed to run it again)\n", id.c_str());
    if (r.done) std::printf("run %s: done in %.2f s\n", id.c_str(), r.wall_time);
    if (r.busy) return 1;
    return r.done || r.already_done ? 0 : 1;
  }

  std::size_t shard = 0, shards = 1;
  if (const auto s = args.value("shard")) parse_shard(*s, shard, shards);
  for (std::size_t i = shard; i < count; i += shards) options.selection.push_back(i);
  options.jobs = jobs;
  const sweep::RunnerReport r = sweep::run_sweep_entries(dir, options);
  if (!quiet) {
    std::printf("sweep: ran %zu of %zu runs (%zu completed before, %zu failed before", r.ran, r.selected, r.already_done,
                r.already_failed);
    if (r.busy) std::printf(", %zu being run by another process", r.busy);
    std::printf(") in %.1f s with %d jobs: %zu done, %zu failed", r.wall_time, r.jobs, r.done, r.failed);
    if (r.interrupted) std::printf(", %zu interrupted", r.ran - r.done - r.failed);
    if (r.ran > 0) std::printf("; utilisation %.0f%% of %d job slots", 100 * r.utilisation(), r.jobs);
    std::printf("\n");
  }
  if (r.interrupted) {
    std::fprintf(stderr, "vascsim sweep: interrupted; %zu runs not completed are left to resume: vascsim sweep %s\n",
                 r.not_started, dir.dir.c_str());
    return 128 + r.signal;
  }
  if (!args.flag("no-merge")) merge_after_run(dir, quiet);
  // Runs another runner held: how they have ended by now (a second runner on one directory that
  // finishes last merged a complete table and exited 1, as if some were still running).
  std::size_t others_failed = 0, others_running = 0;
  for (const std::size_t index : r.busy_entries) {
    const std::string status = read_run_outcome(sweep::run_directory(dir, index)).status;
    others_failed += status == "failed";
    others_running += status == "missing";
  }
  return r.failed + r.already_failed + others_failed + others_running > 0 ? 1 : 0;
}

}  // namespace vascsim::cli

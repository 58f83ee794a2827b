#include "apps/sweep/sweep_emit.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "apps/sweep/run_process.h"
#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"

namespace vascsim::sweep {

namespace {

namespace fs = std::filesystem;

std::string absolute_path(const std::string& path) { return fs::absolute(path).lexically_normal().string(); }

void check_new(const std::vector<std::string>& paths, bool force) {
  for (const auto& p : paths) check_replaceable_output(p, force, {});
}

void write_script(const std::string& path, const std::string& text, bool executable) {
  write_file_atomically(path, text);
  if (executable) ::chmod(path.c_str(), 0755);
}

// Slurm expands '%' in --output patterns and #SBATCH lines end at white space: such paths
// would silently log elsewhere, so they are refused.
void check_slurm_path(const std::string& path) {
  if (path.find_first_of("% \t\n\"'\\") != std::string::npos)
    throw InputError(path + ": a path with spaces, quotes or '%' cannot be named in #SBATCH lines; "
                     "move the sweep directory or the vascsim executable");
}

// A #SBATCH value is one word: the sweep's name (which may hold spaces) with every character but
// letters, digits and "_.+-" as '_'.
std::string slurm_word(const std::string& text) {
  std::string out = text;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && std::string("_.+-").find(c) == std::string::npos) c = '_';
  return out;
}

// Options written into #SBATCH lines verbatim: refused unless they are what sbatch takes, so no
// value can end the line and add a directive or a command.
void check_slurm_option(const std::string& option, const std::string& value, const char* allowed, const char* expected) {
  if (value.find_first_not_of(allowed) != std::string::npos)
    throw InputError("--" + option + ": expected " + expected + ", got '" + value + "'");
}

}  // namespace

std::string shell_quote(const std::string& text) {
  if (!text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=:,+@%") ==
                           std::string::npos)
    return text;
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

namespace {
// parallel's own directory for '..' and relative host-list names: the first that exists of
// $PARALLEL_HOME, $XDG_CONFIG_HOME/parallel, each of $XDG_CONFIG_DIRS/parallel and
// $HOME/.parallel ($HOME defaults to /tmp), else $HOME/.parallel (parallel 20221122's order).
fs::path parallel_config_dir() {
  const auto env = [](const char* name) { const char* v = std::getenv(name); return std::string(v ? v : ""); };
  const std::string home = env("HOME").empty() ? "/tmp" : env("HOME");
  std::vector<std::string> candidates = {env("PARALLEL_HOME"), env("XDG_CONFIG_HOME") + "/parallel"};
  const std::string dirs = env("XDG_CONFIG_DIRS");
  for (std::size_t from = 0; from <= dirs.size();) {
    const std::size_t colon = std::min(dirs.find(':', from), dirs.size());
    candidates.push_back(dirs.substr(from, colon - from) + "/parallel");
    from = colon + 1;
  }
  candidates.push_back(home + "/.parallel");
  std::error_code ec;
  for (const auto& c : candidates)
    if (!c.empty() && fs::is_directory(c, ec)) return c;
  return home + "/.parallel";
}
}  // namespace

std::string resolve_sshloginfile(const std::string& name) {
  const std::string what = "--sshloginfile " + name;
  if (name.empty()) throw InputError("--sshloginfile: expected a host list file, got ''");
  if (name == "-") throw InputError(what + ": run.sh runs later and its standard input is not a host list; give a file");
  const fs::path config = parallel_config_dir();
  fs::path file = name == ".." ? config / "sshloginfile" : name == "." ? fs::path("/etc/parallel/sshloginfile") : fs::path(name);
  std::error_code ec;
  const bool shorthand = name == ".." || name == ".";
  const bool relative = !shorthand && file.is_relative();
  if (relative && !fs::exists(file, ec) && fs::exists(config / file, ec)) file = config / file;
  const std::string path = absolute_path(file.string());
  if (!fs::exists(path, ec))
    throw InputError(what + ": " + path + " does not exist" +
                     (relative ? " (parallel's config directory " + config.string() + " has no such file either)" : ""));
  if (!fs::is_regular_file(path, ec)) throw InputError(what + ": " + path + " is not a file of host lines");
  std::ifstream in(path);
  if (!in) throw InputError(what + ": " + path + " cannot be read");
  // parallel skips lines that are blank or whose first non-blank character is '#'; any other
  // line is a host.
  for (std::string line; std::getline(in, line);) {
    const std::size_t first = line.find_first_not_of(" \t\r\f\v");
    if (first != std::string::npos && line[first] != '#') return path;
  }
  throw InputError(what + ": " + path + " lists no host (only blank lines and '#' comments)");
}

std::vector<std::string> emit_gnu_parallel(const SweepDirectory& sweep, const ParallelOptions& options, bool force) {
  const std::string dir = absolute_path(sweep.dir), exe = vascsim_executable();
  const fs::path out = fs::path(dir) / "parallel";
  const std::string jobs = (out / "jobs.txt").string(), script = (out / "run.sh").string();
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw InputError(out.string() + ": cannot create directory (" + ec.message() + ")");
  check_new({jobs, script}, force);
  std::string list;
  for (const auto& r : sweep.manifest.runs) list += std::to_string(r.index) + "\n";
  // parallel joins its command words and gives them to a shell: the command is one argument,
  // quoted once for run.sh's shell and once inside for parallel's.
  const std::string command = shell_quote(exe) + " sweep " + shell_quote(dir) + " --run-index {}" +
                              (options.retry_failed ? " --retry-failed" : "");
  std::string line = "parallel";
  if (options.jobs > 0) line += " --jobs " + std::to_string(options.jobs);
  // --resume skips the jobs the joblog lists; --resume-failed also re-runs the failed ones.
  line += " --joblog " + shell_quote((out / "joblog").string()) + (options.retry_failed ? " --resume-failed" : " --resume");
  if (!options.sshloginfile.empty()) line += " --sshloginfile " + shell_quote(resolve_sshloginfile(options.sshloginfile));
  line += " --arg-file " + shell_quote(jobs) + " " + shell_quote(command);
  const std::string text =
      "#!/bin/sh\n"
      "# Runs every entry of the sweep '" + sweep.manifest.name + "' (" + std::to_string(sweep.manifest.runs.size()) +
      " runs) with GNU parallel.\n"
      "# Written by vascsim sweep --emit gnu-parallel. Running it again resumes: parallel skips the\n"
      "# jobs its joblog lists (--resume), vascsim skips runs whose summary says they completed.\n"
      "# Then: " + shell_quote(exe) + " sweep merge " + shell_quote(dir) + "\n"
      "exec " + line + "\n";
  write_file_atomically(jobs, list);
  write_script(script, text, true);
  return {script, jobs};
}

namespace {
// Up to three ':'-separated numbers, after an optional "days-"; or no limit.
bool is_slurm_time(const std::string& t) {
  if (t == "UNLIMITED" || t == "INFINITE" || t == "-1") return true;
  const std::size_t dash = t.find('-');
  const std::string days = dash == std::string::npos ? "0" : t.substr(0, dash), rest = t.substr(dash == std::string::npos ? 0 : dash + 1);
  const auto number = [](const std::string& n) { return !n.empty() && n.find_first_not_of("0123456789") == std::string::npos; };
  if (!number(days)) return false;
  int fields = 0;
  for (std::size_t from = 0;; ++fields) {
    const std::size_t colon = rest.find(':', from);
    if (!number(rest.substr(from, colon == std::string::npos ? std::string::npos : colon - from))) return false;
    if (colon == std::string::npos) break;
    from = colon + 1;
  }
  return fields <= 2;
}
}  // namespace

void check_slurm_options(const SlurmOptions& options, const std::string& sweep_dir) {
  check_slurm_option("partition", options.partition, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.,",
                     "partition names (letters, digits, '_', '-', '.', separated by ',')");
  // sbatch's forms: minutes, minutes:seconds, hours:minutes:seconds, days-hours,
  // days-hours:minutes, days-hours:minutes:seconds, and no limit (UNLIMITED, INFINITE or -1).
  if (!options.time_limit.empty() && !is_slurm_time(options.time_limit))
    throw InputError("--time: expected a Slurm time such as 30, 0:30:00, 1-12:00:00 or UNLIMITED, got '" +
                     options.time_limit.substr(0, 40) + "'");
  check_slurm_path(absolute_path(sweep_dir));
  check_slurm_path(vascsim_executable());
}

std::vector<std::string> emit_slurm(const SweepDirectory& sweep, const SlurmOptions& options, bool force) {
  const std::string dir = absolute_path(sweep.dir), exe = vascsim_executable();
  check_slurm_options(options, dir);
  const fs::path out = fs::path(dir) / "slurm";
  const std::string array = (out / "array.sbatch").string(), merge = (out / "merge.sbatch").string(),
                    submit = (out / "submit.sh").string(), logs = (out / "logs").string();
  std::error_code ec;
  fs::create_directories(logs, ec);
  if (ec) throw InputError(logs + ": cannot create directory (" + ec.message() + ")");
  check_new({submit, array, merge}, force);

  const std::size_t n = sweep.manifest.runs.size();
  const std::size_t chunk = static_cast<std::size_t>(std::max(1, options.chunk));
  const std::string throttle = options.max_parallel > 0 ? "%" + std::to_string(options.max_parallel) : "";
  std::string common;
  if (!options.partition.empty()) common += "#SBATCH --partition=" + options.partition + "\n";
  const std::string job = "vascsim-" + slurm_word(sweep.manifest.name);

  std::string a = "#!/bin/bash\n"
                  "# One task of the Slurm job array of the sweep '" + sweep.manifest.name + "': entry\n"
                  "# SLURM_ARRAY_TASK_ID (plus VASCSIM_SWEEP_OFFSET when the sweep is split into arrays of at\n"
                  "# most " + std::to_string(chunk) + ") of " + dir + "/manifest.json. Its own output goes to\n"
                  "# runs/<id>/run.log. Written by vascsim sweep --emit slurm; submit with submit.sh.\n"
                  "#SBATCH --job-name=" + job + "\n"
                  "#SBATCH --array=0-" + std::to_string(std::min(n, chunk) - 1) + throttle + "\n"
                  "#SBATCH --ntasks=1\n"
                  "#SBATCH --cpus-per-task=" + std::to_string(options.cpus_per_task) + "\n"
                  "#SBATCH --output=" + logs + "/run_%A_%a.out\n" + common +
                  (options.time_limit.empty() ? "" : "#SBATCH --time=" + options.time_limit + "\n") +
                  "index=$((SLURM_ARRAY_TASK_ID + ${VASCSIM_SWEEP_OFFSET:-0}))\n"
                  "exec " + shell_quote(exe) + " sweep " + shell_quote(dir) + " --run-index \"$index\"" +
                  (options.retry_failed ? " --retry-failed" : "") + "\n";
  std::string m = "#!/bin/bash\n"
                  "# Merges the sweep '" + sweep.manifest.name + "' once its array tasks have ended (submit.sh adds\n"
                  "# the dependency): results.csv, results.json and plots/ in " + dir + ".\n"
                  "#SBATCH --job-name=" + job + "-merge\n"
                  "#SBATCH --ntasks=1\n"
                  "#SBATCH --output=" + logs + "/merge_%j.out\n" + common +
                  "exec " + shell_quote(exe) + " sweep merge " + shell_quote(dir) + " --force\n";
  std::string s = "#!/bin/bash\n"
                  "# Submits the sweep '" + sweep.manifest.name + "' (" + std::to_string(n) + " runs) to Slurm: the job array, then\n"
                  "# the merge, which waits for every array task to end (afterany: a failed run is a row of the\n"
                  "# table too). Submitting again re-runs only what has not completed. Prints the job ids.\n"
                  "set -euo pipefail\n"
                  "ids=()\n";
  if (n <= chunk) {
    s += "ids+=(\"$(sbatch --parsable " + shell_quote(array) + " | cut -d';' -f1)\")\n";
  } else {
    // Slurm applies an array's %M throttle to that array alone: with --max-parallel, each array
    // waits for the one before it, so no more than M tasks of the sweep run at once.
    for (std::size_t first = 0; first < n; first += chunk) {
      const std::size_t count = std::min(chunk, n - first);
      const std::string after = first > 0 && options.max_parallel > 0 ? " --dependency=afterany:\"${ids[-1]}\"" : "";
      s += "ids+=(\"$(sbatch --parsable --array=0-" + std::to_string(count - 1) + throttle + after +
           " --export=ALL,VASCSIM_SWEEP_OFFSET=" + std::to_string(first) + " " + shell_quote(array) + " | cut -d';' -f1)\")\n";
    }
  }
  s += "dependency=afterany$(printf ':%s' \"${ids[@]}\")\n"
       "merge=$(sbatch --parsable --dependency=\"$dependency\" " + shell_quote(merge) + " | cut -d';' -f1)\n"
       "echo \"array jobs: ${ids[*]}\"\n"
       "echo \"merge job: $merge\"\n"
       "echo \"results: " + dir + "/results.csv when job $merge has ended (squeue -j $merge)\"\n";
  write_script(array, a, false);
  write_script(merge, m, false);
  write_script(submit, s, true);
  return {submit, array, merge};
}

}  // namespace vascsim::sweep

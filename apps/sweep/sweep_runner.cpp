#include "apps/sweep/sweep_runner.h"

#include <sched.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>

#include "apps/sweep/run_process.h"
#include "sim/io/sweep_outcome.h"
#include "sim/io/sweep_results.h"
#include "sim/scene/input_error.h"

namespace vascsim::sweep {

namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

void on_stop(int signal) { g_stop_signal = signal; }
// Wakes wait4 five times a second: to redraw the progress line, and so that a stop signal
// arriving just before wait4 blocks is acted on within 0.2 s rather than when a run ends.
void on_alarm(int) {}

// Installs the handlers for the runner's lifetime, without SA_RESTART so that wait4 returns
// when a signal arrives; restores the previous ones after.
class SignalScope {
 public:
  SignalScope() {
    g_stop_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = on_stop;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
    sa.sa_handler = on_alarm;
    sigaction(SIGALRM, &sa, &old_alarm_);
    itimerval t{};
    t.it_interval.tv_usec = t.it_value.tv_usec = 200000;
    setitimer(ITIMER_REAL, &t, nullptr);
  }
  ~SignalScope() {
    itimerval off{};
    setitimer(ITIMER_REAL, &off, nullptr);
    sigaction(SIGALRM, &old_alarm_, nullptr);
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

 private:
  struct sigaction old_int_ {}, old_term_ {}, old_alarm_ {};
};

std::string clock_text(double seconds) {
  char text[32];
  const long s = static_cast<long>(seconds + 0.5);
  if (s >= 3600) std::snprintf(text, sizeof text, "%ldh%02ldm%02lds", s / 3600, s / 60 % 60, s % 60);
  else if (s >= 60) std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%.1fs", seconds);
  return text;
}

double cpu_seconds(const rusage& ru) {
  return static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

}  // namespace

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  const long n = sysconf(_SC_NPROCESSORS_ONLN);
  return n > 0 ? static_cast<int>(n) : 1;
}

std::string describe_entry(const SweepManifest& m, std::size_t index) {
  std::string out;
  for (std::size_t k = 0; k < m.axes.size(); ++k)
    out += (k ? ", " : "") + m.axes[k].pointer + " = " + sweep_value_text(m.runs[index].values[k]);
  if (m.repeats > 1) out += ", repeat " + std::to_string(m.runs[index].repeat);
  return out;
}

RunnerReport run_sweep_entries(const SweepDirectory& sweep, const RunnerOptions& options) {
  RunnerReport report;
  report.jobs = std::max(1, options.jobs);
  report.selected = options.selection.size();
  std::deque<std::size_t> pending;
  for (std::size_t index : options.selection) {
    const RunOutcome o = read_run_outcome(run_directory(sweep, index));
    if (o.status == "done") ++report.already_done;
    else if (o.status == "failed" && !options.retry_failed) ++report.already_failed;
    else pending.push_back(index);
  }
  // Before anything starts: an edited scene's results would be tabulated under the manifest's
  // values (resuming through the sweep file compares every scene; through DIR it did not).
  for (const std::size_t index : pending) check_run_scene(sweep, index);
  const bool show_progress = options.progress && ::isatty(STDERR_FILENO);
  const std::string exe = vascsim_executable();
  const std::size_t to_run = pending.size();
  std::map<pid_t, RunProcess> running;
  SignalScope signals;
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  bool forwarded = false, progress_shown = false;
  const auto draw_progress = [&] {
    if (!show_progress) return;
    const std::size_t finished = report.done + report.failed;
    const double t = elapsed();
    std::string eta = "ETA --";
    if (finished > 0) eta = "ETA " + clock_text(t / static_cast<double>(finished) * static_cast<double>(to_run - finished));
    std::fprintf(stderr, "\r  sweep: %zu/%zu finished, %zu failed, %zu running, elapsed %s, %s%s   ", finished, to_run,
                 report.failed, running.size(), clock_text(t).c_str(), eta.c_str(),
                 g_stop_signal ? " (stopping)" : "");
    progress_shown = true;
  };

  while (true) {
    while (!g_stop_signal && running.size() < static_cast<std::size_t>(report.jobs) && !pending.empty()) {
      const std::size_t index = pending.front();
      pending.pop_front();
      RunProcess p;
      if (!p.lock(sweep, index)) {
        ++report.busy;
        report.busy_entries.push_back(index);
        if (!options.quiet)
          std::fprintf(stderr, "%srun %s is being run by another process; skipped\n", progress_shown ? "\n" : "",
                       sweep.manifest.runs[index].id.c_str());
        continue;
      }
      // Another runner may have finished it between the first look and the lock.
      const RunOutcome now = read_run_outcome(run_directory(sweep, index));
      if (now.status == "done" || (now.status == "failed" && !options.retry_failed)) {
        ++(now.status == "done" ? report.already_done : report.already_failed);
        if (!options.quiet)
          std::fprintf(stderr, "%srun %s was finished by another process meanwhile; skipped\n", progress_shown ? "\n" : "",
                       sweep.manifest.runs[index].id.c_str());
        continue;
      }
      p.start(exe, options.run_command);
      ++report.ran;
      running.emplace(p.pid(), std::move(p));
    }
    draw_progress();
    if (running.empty()) break;
    if (g_stop_signal && !forwarded) {
      // A terminal's Ctrl-C reaches the whole process group; a signal sent to the sweep alone
      // (kill, scancel, parallel's --termseq) is passed on, so no run is left behind.
      for (auto& [pid, p] : running) ::kill(pid, SIGTERM);
      forwarded = true;
    }
    int status = 0;
    rusage ru{};
    const pid_t pid = ::wait4(-1, &status, 0, &ru);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw InputError(std::string("vascsim sweep: waiting for the run processes failed: ") + std::strerror(errno));
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;  // not one of ours
    RunProcess p = std::move(it->second);
    running.erase(it);
    const bool interrupted = g_stop_signal != 0 && WIFSIGNALED(status) &&
                             (WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGTERM);
    report.cpu_time += cpu_seconds(ru);
    p.finish(status, cpu_seconds(ru), interrupted);
    if (interrupted) continue;
    const RunOutcome o = read_run_outcome(run_directory(sweep, p.index()));
    if (o.status == "done") {
      ++report.done;
    } else {
      ++report.failed;
      if (!options.quiet)
        std::fprintf(stderr, "%srun %s (%s) failed: %s\n", progress_shown ? "\n" : "", sweep.manifest.runs[p.index()].id.c_str(),
                     describe_entry(sweep.manifest, p.index()).c_str(), o.failure.c_str());
      progress_shown = false;
    }
  }
  report.wall_time = elapsed();
  if (progress_shown) std::fprintf(stderr, "\n");
  if (g_stop_signal) {
    report.interrupted = true;
    report.signal = g_stop_signal;
    report.not_started = to_run - report.done - report.failed;
  }
  return report;
}

}  // namespace vascsim::sweep

#include "apps/vascsim/stop_on_signal.h"

#include <time.h>

#include <cstdio>
#include <string>

namespace vascsim::cli {

namespace {

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};
volatile std::sig_atomic_t g_stop_signal = 0;
struct sigaction g_previous[3];  // a copy the handler may read: StopOnSignal's, set before installing
timespec g_first_stop{};          // when the first stop signal came (CLOCK_MONOTONIC); the handler's own

// A Ctrl-C this soon after the first is the same one again, not the user's second: `timeout -s
// INT` sends its signal to the command and then to its process group, so the command gets two
// within microseconds (and, when it handled the first in between, ended without its summary).
// People do not press Ctrl-C twice within 50 ms.
constexpr long long kSameRequestNs = 50'000'000;

long long nanoseconds_since(const timespec& then, const timespec& now) {
  return (static_cast<long long>(now.tv_sec) - then.tv_sec) * 1'000'000'000LL + (now.tv_nsec - then.tv_nsec);
}

extern "C" void request_stop(int signal) {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  if (g_stop_signal == 0) {
    g_first_stop = now;
    g_stop_signal = signal;
    return;
  }
  // A second Ctrl-C: the user does not want to wait for the step to end. Anything else is the
  // same request again: a terminal's Ctrl-C reaches a sweep's runs, which the sweep then sends
  // SIGTERM; Slurm's time limit sends SIGTERM to the sweep and its run, and the sweep passes
  // another on. Those who cannot wait send SIGKILL (Slurm after KillWait).
  if (signal != SIGINT || g_stop_signal != SIGINT) return;
  if (nanoseconds_since(g_first_stop, now) < kSameRequestNs) return;
  for (int k = 0; k < 3; ++k)
    if (kStopSignals[k] == signal) ::sigaction(signal, &g_previous[k], nullptr);  // async-signal-safe
  ::raise(signal);
}

}  // namespace

StopOnSignal::StopOnSignal() {
  g_stop_signal = 0;
  for (int k = 0; k < 3; ++k) ::sigaction(kStopSignals[k], nullptr, &previous_[k]);
  for (int k = 0; k < 3; ++k) g_previous[k] = previous_[k];
  struct sigaction ours {};
  ours.sa_handler = request_stop;
  sigemptyset(&ours.sa_mask);  // one stop signal's handler at a time: they share the globals above
  for (const int signal : kStopSignals) sigaddset(&ours.sa_mask, signal);
  ours.sa_flags = SA_RESTART;
  for (int k = 0; k < 3; ++k) {
    // A signal the process was started ignoring (nohup's SIGHUP) stays ignored.
    if (!(previous_[k].sa_flags & SA_SIGINFO) && previous_[k].sa_handler == SIG_IGN) continue;
    ::sigaction(kStopSignals[k], &ours, nullptr);
  }
}

StopOnSignal::~StopOnSignal() {
  for (int k = 0; k < 3; ++k) ::sigaction(kStopSignals[k], &previous_[k], nullptr);
}

std::string StopOnSignal::reason() const {
  switch (g_stop_signal) {
    case 0: return "";
    case SIGINT: return "SIGINT (Ctrl-C)";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "signal " + std::to_string(static_cast<int>(g_stop_signal));
  }
}

void StopOnSignal::raise_again() {
  const int signal = g_stop_signal;
  if (signal == 0) return;
  std::fflush(nullptr);  // what was printed, also into a pipe or file, before the process ends
  for (int k = 0; k < 3; ++k) ::sigaction(kStopSignals[k], &previous_[k], nullptr);
  ::raise(signal);
}

}  // namespace vascsim::cli

// A run stopped by Ctrl-C, kill or a scheduler's time limit ends as a run that says so: while a
// StopOnSignal lives, the first SIGINT, SIGTERM or SIGHUP only asks the stepper loop to stop
// (Run::run's stop_reason, checked between steps), so `vascsim run` writes its summary (/ok
// false, /stopped_by) and the pictures of the run say "Run stopped" instead of passing for a run
// still being written. A second Ctrl-C ends the process at once (one within 50 ms of the first is
// the same one twice, as `timeout -s INT` sends it); a second SIGTERM (a sweep passing on the one
// Slurm sent to both) does not.
// After the summary, raise_again() ends the process by the signal itself, so a shell, a sweep or
// Slurm still sees a run killed by it.
#pragma once

#include <csignal>
#include <string>

namespace vascsim::cli {

class StopOnSignal {
 public:
  StopOnSignal();
  ~StopOnSignal();  // restores the handlers that were there before
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

  // Who asked the run to stop: "SIGINT (Ctrl-C)", "SIGTERM" or "SIGHUP"; empty while none did.
  std::string reason() const;
  // Restores the earlier handlers and re-sends the signal that asked for the stop to this
  // process (an earlier handler, sim/io/output_file.h's, removes temporaries first); returns only
  // if none did.
  void raise_again();

 private:
  struct sigaction previous_[3] {};
};

}  // namespace vascsim::cli

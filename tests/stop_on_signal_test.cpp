// What each signal does to a run while StopOnSignal lives (apps/vascsim/stop_on_signal.h), in a
// process of its own per case (death tests): the first SIGINT, SIGTERM or SIGHUP only asks the
// run to stop; a second Ctrl-C ends the process at once, while a repeated SIGTERM (a sweep passing
// on Slurm's) does not; a signal the process was started ignoring (nohup's SIGHUP) stays ignored.
// tests/cli_run_test.cpp checks the same through `vascsim run`, where timing allows.
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>

#include "apps/vascsim/stop_on_signal.h"

namespace vascsim::cli {
namespace {

// Ends the child with `code` when `stop` names `expected`, else with 9, so a wrong reason fails.
void exit_if_reason(const StopOnSignal& stop, const char* expected, int code) { ::_exit(stop.reason() == expected ? code : 9); }

// A user's second Ctrl-C comes at least a tenth of a second after the first; `timeout -s INT`
// sends one to the command and again to its process group, microseconds apart: that one is a
// single request (the run ended without its summary when it took it for two).
TEST(StopOnSignalDeathTest, ASecondCtrlCEndsTheProcessAtOnceButNotTheSameOneTwice) {
  EXPECT_EXIT(
      {
        StopOnSignal stop;
        std::raise(SIGINT);
        std::raise(SIGINT);  // as timeout sends it
        if (stop.reason() != "SIGINT (Ctrl-C)") ::_exit(9);
        ::usleep(200000);
        std::raise(SIGINT);
        ::_exit(0);  // not reached: the second Ctrl-C ends the process by SIGINT
      },
      ::testing::KilledBySignal(SIGINT), "");
  EXPECT_EXIT(
      {
        StopOnSignal stop;
        std::raise(SIGINT);
        std::raise(SIGINT);
        exit_if_reason(stop, "SIGINT (Ctrl-C)", 0);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(StopOnSignalDeathTest, ARepeatedSigtermOrALaterCtrlCOnlyAsksAgain) {
  EXPECT_EXIT(
      {
        StopOnSignal stop;
        std::raise(SIGTERM);
        std::raise(SIGTERM);
        std::raise(SIGINT);
        std::raise(SIGHUP);
        exit_if_reason(stop, "SIGTERM", 0);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(StopOnSignalDeathTest, RaiseAgainEndsTheProcessByTheSignalThatAskedForTheStop) {
  EXPECT_EXIT(
      {
        StopOnSignal stop;
        std::raise(SIGHUP);
        if (stop.reason() != "SIGHUP") ::_exit(9);
        stop.raise_again();
        ::_exit(0);
      },
      ::testing::KilledBySignal(SIGHUP), "");
}

TEST(StopOnSignalDeathTest, ASignalStartedIgnoredStaysIgnored) {
  EXPECT_EXIT(
      {
        std::signal(SIGHUP, SIG_IGN);  // as nohup starts a command
        StopOnSignal stop;
        std::raise(SIGHUP);
        exit_if_reason(stop, "", 0);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(StopOnSignalDeathTest, TheHandlersBeforeComeBackWhenItEnds) {
  EXPECT_EXIT(
      {
        { StopOnSignal stop; }
        std::raise(SIGTERM);  // the default action again: the process ends
        ::_exit(0);
      },
      ::testing::KilledBySignal(SIGTERM), "");
}

}  // namespace
}  // namespace vascsim::cli

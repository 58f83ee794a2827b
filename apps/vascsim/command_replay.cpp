// vascsim replay RUN_DIR [RUN_DIR_B]: serves runs to a browser (apps/replay/replay_server.h,
// docs/replay.md). Built only with the renderer.
#ifdef VASCSIM_HAVE_RENDER
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <cstdio>
#include <ctime>
#include <thread>

#include "apps/replay/replay_server.h"
#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"

namespace vascsim::cli {

namespace {

const std::vector<OptionSpec>& replay_options() {
  static const std::vector<OptionSpec> options = {
      {"port", "P", "TCP port (default 0: a free one)"},
      {"host", "H", "address to listen on (default 127.0.0.1; 0.0.0.0 exposes the runs to the network)"},
      {"no-token", "", "accept requests without the access token (trusted machines only)"},
      {"help", "", "show this help"},
  };
  return options;
}

}  // namespace

int run_replay_command(int argc, char** argv) {
  const Args args(argc, argv, 2, replay_options());
  if (args.flag("help")) {
    std::printf(
        "usage: vascsim replay RUN_DIR [RUN_DIR_B] [options]\n\n"
        "Serves a run (or two, to compare) to a web browser: open the printed URL. Stops on Ctrl-C.\n"
        "Over SSH: ssh -L 8517:127.0.0.1:8517 HOST, then vascsim replay RUN --port 8517 there.\n\n%s",
        format_options(replay_options()).c_str());
    return 0;
  }
  if (args.positional().empty() || args.positional().size() > 2)
    throw UsageError("expected RUN_DIR, or RUN_DIR RUN_DIR_B to compare");
  replay::ReplayOptions o;
  o.runs = args.positional();
  o.port = static_cast<int>(args.integer("port", 0, 0, 65535));
  o.host = args.value("host").value_or("127.0.0.1");
  if (o.host.empty()) throw UsageError("--host: expected an address such as 127.0.0.1 or ::1, got ''");
  o.require_token = !args.flag("no-token");

  // SIGINT and SIGTERM are taken by one waiting thread, not by a handler that could interrupt
  // the server anywhere: block them before any thread starts, so every thread inherits the mask.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  replay::ReplayServer server(o);
  if (!replay::is_loopback(o.host))
    std::fprintf(stderr, "vascsim replay: listening on %s: anyone who can reach this address %s\n", o.host.c_str(),
                 o.require_token ? "and has the token can see these runs" : "can see these runs (no token!)");
  std::printf("replay: %s\n", server.url().c_str());
  std::fflush(stdout);

  std::atomic<bool> served{false};
  std::thread waiter([&] {
    const timespec poll{0, 200 * 1000 * 1000};
    while (!served) {
      if (sigtimedwait(&stop_signals, nullptr, &poll) > 0) break;
    }
    server.stop();
  });
  server.serve();
  served = true;
  waiter.join();
  return 0;
}

}  // namespace vascsim::cli

#endif  // VASCSIM_HAVE_RENDER

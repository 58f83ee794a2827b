// vascsim bench replay: the replay server measured from an HTTP client on this machine.
// Frame latency (render + PNG encode + HTTP) while scrubbing a run at 1280x720 (a synthetic
// default-sized maze unless --run names a real run), playback rate (requests back to back), and
// on a synthetic 10^6-frame log: the time to open it, the first requests that build the lazy
// caches, and the process's peak memory. Prints numbers; asserts nothing.
#ifdef VASCSIM_HAVE_RENDER
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <thread>

#include "apps/replay/replay_server.h"
#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "render/synthetic_log.h"
#include "sim/scene/input_error.h"

// Last: its system headers' macros break Eigen's templates when included first.
#include <httplib.h>

namespace vascsim::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[static_cast<std::size_t>(p * (v.size() - 1))];
}

// A server on a free port, served from a thread, with a client bound to it.
struct LocalServer {
  explicit LocalServer(const std::string& run) : server(replay::ReplayOptions{{run}, "127.0.0.1", 0, true}) {
    thread = std::thread([this] { server.serve(); });
    client = std::make_unique<httplib::Client>("127.0.0.1", server.port());
    client->set_read_timeout(120);
  }
  ~LocalServer() {
    server.stop();
    thread.join();
  }
  // GET path?query&token=..., returns the status; throws if no answer.
  int get(const std::string& path_and_query) {
    const char sep = path_and_query.find('?') == std::string::npos ? '?' : '&';
    const auto r = client->Get((path_and_query + sep + "token=" + server.token()).c_str());
    if (!r) throw InputError("bench replay: no answer to " + path_and_query);
    return r->status;
  }
  replay::ReplayServer server;
  std::thread thread;
  std::unique_ptr<httplib::Client> client;
};

// Frame latency and playback rate while scrubbing `run` (or a synthetic default-sized maze).
void bench_scrub(std::string run, const fs::path& dir, int requests) {
  if (run.empty()) {
    render::SyntheticLogSpec spec;  // the default maze's size: 5x5 cells, a 50-node rod, 48 s at 100 frames/s
    spec.nodes = 50;
    spec.frames = 4800;
    spec.duration = 48;
    spec.speed = 0.002;
    run = (dir / "scrub.vlog").string();
    render::write_synthetic_log(run, spec);
  }
  std::printf("frame latency: %s, 1280x720, %d requests from an HTTP client on this machine\n", run.c_str(), requests);
  {
    LocalServer s(run);
    s.get("/api/frame.png?t=0");  // warm up: GL context, caches
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> any(0.0, 48.0);
    std::vector<double> scrub, play;
    for (int k = 0; k < requests; ++k) {
      const auto start = Clock::now();
      if (s.get("/api/frame.png?width=1280&height=720&t=" + std::to_string(any(rng))) != 200)
        throw InputError("bench replay: a frame request failed");
      scrub.push_back(ms_since(start));
    }
    // The page's plot readouts at each cursor move: one /api/value per default plot.
    std::vector<double> readouts;
    for (int k = 0; k < requests; ++k) {
      const std::string t = std::to_string(any(rng));
      const auto start = Clock::now();
      for (const char* plot : {"channel=tip/error", "channel=force/actuation&reduce=sum", "channel=force/contact&reduce=max"})
        if (s.get(std::string("/api/value?") + plot + "&t=" + t) != 200) throw InputError("bench replay: a value request failed");
      readouts.push_back(ms_since(start));
    }
    // Playback: consecutive times 1/30 s apart, each requested when the last arrived.
    const auto play_start = Clock::now();
    for (int k = 0; k < requests; ++k) {
      const auto start = Clock::now();
      s.get("/api/frame.png?width=1280&height=720&layers=lumen,walls,path,start_goal,trail,rod,magnetic,contact,hud,legend&t=" +
            std::to_string(10 + k / 30.0));
      play.push_back(ms_since(start));
    }
    const double play_s = ms_since(play_start) / 1000;
    std::printf("  scrub (random times):   p50 %.1f ms   p95 %.1f ms   max %.1f ms\n", percentile(scrub, 0.5),
                percentile(scrub, 0.95), percentile(scrub, 1.0));
    std::printf("  playback (consecutive): p50 %.1f ms   p95 %.1f ms   -> %.1f frames/s\n", percentile(play, 0.5),
                percentile(play, 0.95), requests / play_s);
    std::printf("  plot readouts (3 x /api/value at a random time): p50 %.2f ms   p95 %.2f ms\n",
                percentile(readouts, 0.5), percentile(readouts, 0.95));
  }

}

// Open time, lazy-cache cost and peak memory of a server on a long synthetic log.
void bench_long_log(long long long_frames, const fs::path& dir) {
  std::printf("long log: %lld frames (synthetic, 8 nodes)\n", long_frames);
  render::SyntheticLogSpec spec;
  spec.nodes = 8;
  spec.rod_length = 0.006;
  spec.frames = static_cast<int>(long_frames);
  spec.duration = long_frames * 0.01;
  spec.speed = 0.0002;
  spec.contact_nodes = {3};
  const std::string long_log = (dir / "long.vlog").string();
  auto start = Clock::now();
  render::write_synthetic_log(long_log, spec);
  std::printf("  written in %.1f s, %.0f MB\n", ms_since(start) / 1000, fs::file_size(long_log) / 1e6);
  start = Clock::now();
  {
    LocalServer s(long_log);
    const double open_ms = ms_since(start);
    start = Clock::now();
    s.get("/api/run");
    const double run_ms = ms_since(start);
    start = Clock::now();
    s.get("/api/frame.png?t=" + std::to_string(spec.duration / 2));
    const double first_frame_ms = ms_since(start);
    start = Clock::now();
    s.get("/api/series?channel=tip/error&points=1000");
    const double first_series_ms = ms_since(start);
    std::vector<double> later;
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> any(0.0, spec.duration);
    for (int k = 0; k < 20; ++k) {
      const auto t0 = Clock::now();
      s.get("/api/frame.png?t=" + std::to_string(any(rng)));
      s.get("/api/series?channel=force/contact&reduce=max&points=1000&from=" + std::to_string(any(rng) / 2));
      s.get("/api/nodes?t=" + std::to_string(any(rng)));
      later.push_back(ms_since(t0));
    }
    std::printf("  open (server start, header and index): %.0f ms; first /api/run %.1f ms\n", open_ms, run_ms);
    std::printf("  first frame (builds the trail cache in one pass): %.0f ms; first series pass: %.0f ms\n",
                first_frame_ms, first_series_ms);
    std::printf("  then frame + series + nodes: p50 %.0f ms, p95 %.0f ms\n", percentile(later, 0.5),
                percentile(later, 0.95));
  }
  std::printf("  peak memory of the server process (max RSS, log written by the same process): %.0f MB\n", peak_rss_mb());
}

const std::vector<OptionSpec>& bench_options() {
  static const std::vector<OptionSpec> options = {
      {"run", "RUN_DIR", "measure frame latency on this run (default: a synthetic 5x5 maze log)"},
      {"requests", "N", "frame requests for the latency figures (default 200)"},
      {"frames", "N", "frames of the long synthetic log (default 1000000)"},
      {"help", "", "show this help"},
  };
  return options;
}

}  // namespace

int run_bench_replay(int argc, char** argv) {
  const Args args(argc, argv, 3, bench_options());
  if (args.flag("help")) {
    std::printf("usage: vascsim bench replay [options]\n\n%s", format_options(bench_options()).c_str());
    return 0;
  }
  const int requests = static_cast<int>(args.integer("requests", 200, 10, 100000));
  const long long long_frames = args.integer("frames", 1000000, 1000, 100000000);
  const fs::path dir = fs::temp_directory_path() / ("vascsim-bench-replay-" + std::to_string(getpid()));
  fs::create_directories(dir);
  struct Cleanup {
    fs::path d;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(d, ec);
    }
  } cleanup{dir};

  // The long log is measured in a child process started before any thread or GL context, so
  // its peak memory is the server's on that log alone.
  std::fflush(stdout);
  const pid_t child = fork();
  if (child == 0) {
    try {
      bench_long_log(long_frames, dir);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "vascsim bench replay: %s\n", e.what());
      _exit(1);
    }
    std::fflush(stdout);
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw InputError("bench replay: the long-log measurement failed");
  bench_scrub(args.value("run").value_or(""), dir, requests);
  return 0;
}

}  // namespace vascsim::cli

#endif  // VASCSIM_HAVE_RENDER

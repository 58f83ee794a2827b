// The `vascsim replay` server: serves one run (or two, to compare) and the replay page to a
// browser, over HTTP on localhost. Map pixels come from the video renderer
// (render::render_view_frame), everything else is JSON read from the frame log (docs/replay.md
// lists the endpoints). Jupyter's model of safety: it binds 127.0.0.1 unless told otherwise,
// every request needs the random token of this start, and no part of a request ever names a
// file: only the runs given at start and the page's compiled-in files are served.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace vascsim::replay {

// Whether `host` (a --host value, or a Host or Origin header's host with IPv6 in brackets) names
// this machine's loopback: 127.0.0.1, localhost, ::1.
bool is_loopback(const std::string& host);

struct ReplayOptions {
  std::vector<std::string> runs;   // one or two run directories or frame log files
  std::string host = "127.0.0.1";  // address to bind
  int port = 0;                    // 0: a free port
  bool require_token = true;       // --no-token turns it off
};

class ReplayServer {
 public:
  // Opens the runs and binds the port. Throws InputError for a bad run or a port that cannot be
  // bound.
  explicit ReplayServer(const ReplayOptions& options);
  ~ReplayServer();
  ReplayServer(const ReplayServer&) = delete;
  ReplayServer& operator=(const ReplayServer&) = delete;

  int port() const;
  const std::string& token() const;
  // "http://HOST:PORT/?token=TOKEN", the line users open.
  std::string url() const;
  // Serves until stop() is called (from any thread; a stop() before serve() has started counts:
  // serve() then returns at once).
  void serve();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vascsim::replay

// The replay server stays healthy under what a browser, a careless script or an attacker on
// localhost sends: 10^4 random query strings, malformed HTTP, oversized headers, clients that
// hang up mid-request, two clients at once; and `vascsim replay` stops cleanly on SIGINT.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <random>
#include <thread>

#include "sim/scene/input_error.h"
#include "tests/cli_test_support.h"
#include "tests/render_test_util.h"
#include "tests/replay_test_support.h"

namespace vascsim::replay {
namespace {

using render::testing::ScratchDir;
using testing::LiveServer;

std::string small_run(const ScratchDir& dir) {
  const std::string run = dir / "run";
  std::filesystem::create_directories(run);
  render::write_synthetic_log(run + "/frames.vlog", render::SyntheticLogSpec{});
  return run;
}

// Sends raw bytes on a fresh connection and returns what came back (possibly nothing).
std::string raw_exchange(int port, const std::string& bytes, bool close_early = false) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    ::close(fd);
    return "connect failed";
  }
  timeval timeout{1, 0};  // the server may keep a connection open after junk
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) break;
    sent += static_cast<std::size_t>(n);
  }
  std::string reply;
  if (!close_early) {
    char buffer[4096];
    ssize_t n;
    while ((n = ::recv(fd, buffer, sizeof buffer, 0)) > 0) reply.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return reply;
}

std::string percent_encoded(const std::string& s) {
  std::string out;
  char buf[4];
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '.' || c == '-' || c == ',') {
      out.push_back(static_cast<char>(c));
    } else {
      std::snprintf(buf, sizeof buf, "%%%02X", c);
      out += buf;
    }
  }
  return out;
}

void expect_healthy(LiveServer& s, const std::string& after) {
  const auto r = s.get("/api/run");
  ASSERT_TRUE(r) << "server did not answer after " << after;
  EXPECT_EQ(r->status, 200) << after;
}

TEST(ReplayRobustness, SurvivesTenThousandRandomQueryStrings) {
  ScratchDir dir("replay_fuzz");
  LiveServer s({{small_run(dir)}});
  std::mt19937 rng(12345);
  const std::string endpoints[] = {"/api/run", "/api/frame.png", "/api/nodes", "/api/series", "/api/value", "/api/events",
                                   "/api/compare", "/api/bookmarks", "/api/export/status", "/api/export/file", "/x"};
  const std::string names[] = {"t", "width", "height", "camera", "zoom", "center", "layers", "run", "channel",
                               "reduce", "from", "to", "points", "id", "overlay", "token", ""};
  const std::string alphabet = "0123456789.-+eE,naifNAIF%&=;/ x\x01\xff";
  auto random_value = [&] {
    std::string v;
    const int n = static_cast<int>(rng() % 12);
    for (int i = 0; i < n; ++i) v.push_back(alphabet[rng() % alphabet.size()]);
    return v;
  };
  int answered = 0, server_errors = 0;
  for (int k = 0; k < 10000; ++k) {
    std::string query;
    const int params = static_cast<int>(rng() % 4);
    for (int p = 0; p < params; ++p) {
      std::string name = names[rng() % (sizeof names / sizeof names[0])];
      // Keep frames small: a random valid size would make this a rendering benchmark.
      if (name == "width" || name == "height") name = "zoom";
      query += (p ? "&" : "") + name + "=" + percent_encoded(random_value());
    }
    const auto r = s.get(endpoints[rng() % (sizeof endpoints / sizeof endpoints[0])] + "?" + query +
                         "&width=32&height=32");
    if (r) {
      ++answered;
      server_errors += r->status >= 500;
      EXPECT_TRUE(r->status == 200 || r->status == 400 || r->status == 403 || r->status == 404) << query << " -> " << r->status << " " << r->body;
    }
  }
  EXPECT_EQ(answered, 10000);
  EXPECT_EQ(server_errors, 0);
  expect_healthy(s, "random queries");
}

TEST(ReplayRobustness, SurvivesMalformedHttpAndHangUps) {
  ScratchDir dir("replay_malformed");
  LiveServer s({{small_run(dir)}});
  const int port = s.server().port();
  const std::string junk[] = {
      "\r\n\r\n",
      "GARBAGE\r\n\r\n",
      "GET\r\n\r\n",
      "GET / HTTP/9.9\r\n\r\n",
      std::string("GET /api/run HTTP/1.1\r\nHost: x\r\n") + "X-Big: " + std::string(200000, 'a') + "\r\n\r\n",
      "GET /" + std::string(100000, 'a') + " HTTP/1.1\r\n\r\n",
      "POST /api/bookmarks?token=" + s.server().token() + " HTTP/1.1\r\nContent-Length: 99999999999\r\n\r\n{",
      "POST /api/bookmarks?token=" + s.server().token() + " HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\nzz\r\n",
      std::string("GET /api/run HTTP/1.1\r\n\0\0\0\r\n\r\n", 30),
  };
  for (const auto& bytes : junk) {
    const std::string reply = raw_exchange(port, bytes);
    // An answer, if any, refuses the request; it never serves the run.
    if (!reply.empty()) {
      EXPECT_EQ(reply.rfind("HTTP/1.1 4", 0), 0u) << reply.substr(0, 200);
    }
    expect_healthy(s, "malformed request of " + std::to_string(bytes.size()) + " bytes");
  }
  // A POST without a length: answered at once, saying what is missing (the library waited 10 s
  // for a body and said only "bad request").
  const std::string no_length = raw_exchange(port, "POST /api/bookmarks?token=" + s.server().token() + " HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_EQ(no_length.rfind("HTTP/1.1 411", 0), 0u) << no_length.substr(0, 200);
  EXPECT_NE(no_length.find("a POST needs a Content-Length header"), std::string::npos) << no_length;
  // Bodies framed wrongly are refused from the headers, before the library reads (or waits for)
  // them: a GET's body (ignored, then read as the next request), two Content-Lengths (the first
  // was taken), a length that is not a number ("abc" read as an empty body), one over the limit
  // (answered after a 10 s wait).
  const std::string bookmarks = "POST /api/bookmarks?token=" + s.server().token() + " HTTP/1.1\r\nHost: x\r\n";
  const std::pair<std::string, std::string> framing[] = {
      {"GET /api/run?token=" + s.server().token() + " HTTP/1.1\r\nHost: x\r\nContent-Length: 3\r\n\r\nx=1", "HTTP/1.1 400"},
      {bookmarks + "Content-Length: 20\r\nContent-Length: 5\r\n\r\n{\"name\": \"x\", \"t\": 1}", "HTTP/1.1 400"},
      {bookmarks + "Content-Length: abc\r\n\r\n", "HTTP/1.1 400"},
      {bookmarks + "Content-Length: -5\r\n\r\n", "HTTP/1.1 400"},
      {bookmarks + "Content-Length: 2000000\r\n\r\n", "HTTP/1.1 413"},
  };
  for (const auto& [request, status] : framing) {
    // raw_exchange waits 1 s for the answer: one the library gives after its 10 s wait is none.
    const std::string reply = raw_exchange(port, request);
    EXPECT_EQ(reply.rfind(status, 0), 0u) << request.substr(0, 80) << "\n" << reply.substr(0, 300);
    if (status == "HTTP/1.1 400") {
      EXPECT_NE(reply.find("\"parameter\":\"body\""), std::string::npos) << reply;
    }
    // The body is left unread: the client is asked to close rather than have it read as the next
    // request (a GET's "x=1" was answered as one).
    EXPECT_NE(reply.find("Connection: close\r\n"), std::string::npos) << reply.substr(0, 300);
  }
  // So is one refused for its token, which may have sent a body.
  const std::string refused = raw_exchange(port, "POST /api/bookmarks?token=wrong HTTP/1.1\r\nHost: x\r\nContent-Length: 3\r\n\r\nx=1");
  EXPECT_EQ(refused.rfind("HTTP/1.1 403", 0), 0u) << refused.substr(0, 200);
  EXPECT_NE(refused.find("Connection: close\r\n"), std::string::npos) << refused.substr(0, 300);
  // A client that asks for a frame and hangs up before the answer.
  for (int k = 0; k < 5; ++k)
    raw_exchange(port, "GET " + s.authorised("/api/frame.png?width=1024&height=1024&t=0.5") + " HTTP/1.1\r\n\r\n", true);
  expect_healthy(s, "clients hanging up mid-frame");
}

TEST(ReplayRobustness, TwoClientsAtOnce) {
  ScratchDir dir("replay_two_clients");
  LiveServer s({{small_run(dir)}});
  const std::string reference = s.get("/api/frame.png?t=0.5&width=200&height=150")->body;
  std::vector<std::thread> tabs;
  std::atomic<int> identical{0};
  for (int tab = 0; tab < 2; ++tab)
    tabs.emplace_back([&] {
      httplib::Client c("127.0.0.1", s.server().port());
      for (int k = 0; k < 10; ++k) {
        const auto r = c.Get(s.authorised("/api/frame.png?t=0.5&width=200&height=150").c_str());
        if (r && r->status == 200 && r->body == reference) ++identical;
        c.Get(s.authorised("/api/series?channel=tip/error").c_str());
      }
    });
  for (auto& t : tabs) t.join();
  EXPECT_EQ(identical, 20);
}

// A second server on a port the first holds is refused, not given half of its connections.
TEST(ReplayRobustness, ASecondServerOnTheSamePortIsRefused) {
  ScratchDir dir("replay_same_port");
  const std::string run = small_run(dir);
  LiveServer first({{run}});
  ReplayOptions second;
  second.runs = {run};
  second.port = first.server().port();
  try {
    ReplayServer s(second);
    ADD_FAILURE() << "a second server listens on port " << second.port;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot listen on 127.0.0.1:" + std::to_string(second.port)), std::string::npos)
        << e.what();
  }
}

// A stop that comes before the server listens is not lost: the library's own stop() did nothing
// then, and the server served on (a test that stopped at once hung; Ctrl-C right after the start
// would have been ignored).
TEST(ReplayRobustness, AStopBeforeOrAsServingStartsEndsTheServer) {
  ScratchDir dir("replay_early_stop");
  const std::string run = small_run(dir);
  {
    ReplayServer s(ReplayOptions{{run}});
    s.stop();
    s.serve();  // returns at once
  }
  for (int k = 0; k < 20; ++k) {
    ReplayServer s(ReplayOptions{{run}});
    std::thread serving([&] { s.serve(); });
    s.stop();
    serving.join();
  }
}

// More idle keep-alive connections than a small worker pool (two browser tabs hold 12) do not
// stall the next request.
TEST(ReplayRobustness, IdleKeepAliveConnectionsDoNotStallTheServer) {
  ScratchDir dir("replay_idle");
  LiveServer s({{small_run(dir)}});
  std::vector<std::unique_ptr<httplib::Client>> idle;
  for (int k = 0; k < 16; ++k) {
    idle.push_back(std::make_unique<httplib::Client>("127.0.0.1", s.server().port()));
    idle.back()->set_keep_alive(true);
    ASSERT_EQ(idle.back()->Get(s.authorised("/api/run").c_str())->status, 200);
  }
  httplib::Client fresh("127.0.0.1", s.server().port());
  fresh.set_read_timeout(2);  // s; the library's keep-alive timeout, which stalled it, is 5 s
  const auto r = fresh.Get(s.authorised("/api/run").c_str());
  ASSERT_TRUE(r) << "no answer within 2 s beside 16 idle connections";
  EXPECT_EQ(r->status, 200);
}

// A stop (Ctrl-C) with a browser's idle keep-alive connection open ends the server promptly: it
// waited for the connection's keep-alive timeout, the library's 5 s (6.3 s measured), now 1 s.
TEST(ReplayRobustness, AStopWithAnIdleKeepAliveConnectionOpenEndsPromptly) {
  ScratchDir dir("replay_idle_stop");
  ReplayServer s(ReplayOptions{{small_run(dir)}});
  std::thread serving([&] { s.serve(); });
  httplib::Client idle("127.0.0.1", s.port());
  idle.set_keep_alive(true);
  ASSERT_EQ(idle.Get(("/api/run?token=" + s.token()).c_str())->status, 200);
  const auto start = std::chrono::steady_clock::now();
  s.stop();
  serving.join();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 3.0) << "the stop waited for the idle connection";
}

// The command: prints one URL line, serves, and exits 0 on SIGINT.
TEST(ReplayCommand, PrintsTheUrlAndExitsCleanlyOnSigint) {
  ScratchDir dir("replay_sigint");
  const std::string run = small_run(dir);
  int out[2];
  ASSERT_EQ(::pipe(out), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(out[1], 1);
    ::close(out[0]);
    ::execl(VASCSIM_EXE, VASCSIM_EXE, "replay", run.c_str(), "--port", "0", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(out[1]);
  std::string line;
  char c;
  while (::read(out[0], &c, 1) == 1 && c != '\n') line.push_back(c);
  ASSERT_EQ(line.rfind("replay: http://127.0.0.1:", 0), 0u) << line;
  const std::size_t port_at = std::string("replay: http://127.0.0.1:").size();
  const int port = std::stoi(line.substr(port_at));
  const std::string token = line.substr(line.find("token=") + 6);
  EXPECT_EQ(token.size(), 32u);
  httplib::Client client("127.0.0.1", port);
  const auto r = client.Get(("/api/run?token=" + token).c_str());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(client.Get("/api/run")->status, 403);
  ::kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  ::close(out[0]);
}

TEST(ReplayCommand, BadRunAndBadOptionsExit2) {
  ScratchDir dir("replay_bad");
  auto r = vascsim::test::run_vascsim("replay " + (dir / "missing"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("missing"), std::string::npos) << r.output;
  r = vascsim::test::run_vascsim("replay " + small_run(dir) + " --port 99999");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = vascsim::test::run_vascsim("replay a b c");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = vascsim::test::run_vascsim("replay " + small_run(dir) + " --host ''");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("option '--host' needs a value H, got an empty one"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace vascsim::replay

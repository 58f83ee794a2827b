// The replay server, in-process on a free port: its frames are the renderer's pixels (byte for
// byte what `vascsim render --still` writes), it refuses requests without the token, answers
// each bad parameter with 400 naming it, follows a log that is still being written, aligns two
// runs by simulated time, and reads node values from the log.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "render/frame_source.h"
#include "tests/render_test_util.h"
#include "render/synthetic_log.h"
#include "render/video_encoder.h"
#include "sim/io/log_metadata.h"
#include "sim/io/output_file.h"
#include "sim/log/frame_log.h"
#include "tests/cli_test_support.h"
#include "tests/replay_test_support.h"

namespace vascsim::replay {
namespace {

using nlohmann::json;
using render::testing::ScratchDir;
using testing::LiveServer;
namespace fs = std::filesystem;

std::string synthetic_run(const ScratchDir& dir, const std::string& name, render::SyntheticLogSpec spec = {}) {
  const std::string run = dir / name;
  fs::create_directories(run);
  render::write_synthetic_log(run + "/frames.vlog", spec);
  return run;
}

render::SyntheticLogSpec long_spec() {
  render::SyntheticLogSpec spec;
  spec.frames = 101;
  spec.duration = 10.0;
  spec.speed = 0.004;
  return spec;
}

json get_json(LiveServer& s, const std::string& query, int expected_status = 200) {
  const auto r = s.get(query);
  EXPECT_TRUE(r) << query << ": no answer";
  if (!r) return json();
  EXPECT_EQ(r->status, expected_status) << query << ": " << r->body;
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json") << query;
  return json::parse(r->body, nullptr, false);
}

// Starts an export (`query`: its parameters) and returns its id, or -1 with the test failed.
int start_export(LiveServer& s, const std::string& query) {
  const auto r = s.client().Post(s.authorised("/api/export?" + query).c_str(), "", "text/plain");
  EXPECT_TRUE(r) << query << ": no answer";
  if (!r) return -1;
  EXPECT_EQ(r->status, 200) << r->body;
  return r->status == 200 ? json::parse(r->body)["id"].get<int>() : -1;
}

// Export `id`'s status once it is no longer running (at most a minute).
json finished_export(LiveServer& s, int id) {
  json status;
  for (int wait = 0; wait < 600; ++wait) {
    status = get_json(s, "/api/export/status?id=" + std::to_string(id));
    if (status["state"] != "running") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return status;
}

TEST(ReplayServer, FrameIsByteIdenticalToRenderStill) {
  ScratchDir dir("replay_still");
  const std::string run = synthetic_run(dir, "run", long_spec());
  LiveServer s({{run}});
  struct Case {
    std::string query, options;
  } cases[] = {
      {"t=3.33&width=640&height=360", "--still 3.33 --width 640 --height 360"},
      {"t=7.5&width=480&height=480&camera=follow&zoom=3", "--still 7.5 --width 480 --height 480 --camera follow --zoom 3"},
      {"t=5&width=400&height=300&center=0.02,0.03&zoom=2&layers=walls,rod,nodes,contact",
       "--still 5 --width 400 --height 300 --center 0.02,0.03 --zoom 2 --layers walls,rod,nodes,contact"},
      // A seek backwards after a later frame: the trail is rebuilt, not carried over.
      {"t=1.25&width=320&height=240", "--still 1.25 --width 320 --height 240"},
  };
  for (const auto& c : cases) {
    const auto r = s.get("/api/frame.png?" + c.query);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
    const std::string png = dir / "still.png";
    const auto cli = vascsim::test::run_vascsim("render " + run + " " + c.options + " --png " + png + " --force");
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    EXPECT_TRUE(r->body == vascsim::test::read_text(png)) << c.query << ": server frame differs from render --still";
    // The view transform puts the tip where the renderer drew it.
    const json view = json::parse(r->get_header_value("X-Vascsim-View"));
    EXPECT_GT(view["scale"].get<double>(), 0);
  }
}

TEST(ReplayServer, LayersChangeThePixels) {
  ScratchDir dir("replay_layers");
  LiveServer s({{synthetic_run(dir, "run", long_spec())}});
  const auto all = s.get("/api/frame.png?t=5&width=320&height=240");
  const auto no_trail = s.get("/api/frame.png?t=5&width=320&height=240&layers=lumen,walls,path,start_goal,rod,magnetic,contact,hud,legend");
  ASSERT_TRUE(all && no_trail);
  EXPECT_NE(all->body, no_trail->body) << "hiding the trail changed nothing";
}

TEST(ReplayServer, RequestsWithoutTheTokenAreForbidden) {
  ScratchDir dir("replay_token");
  LiveServer s({{synthetic_run(dir, "run")}});
  for (const std::string path : {"/", "/api/run", "/api/frame.png", "/replay.js", "/api/nodes?t=0"}) {
    const auto r = s.get(path, false);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 403) << path;
    const auto wrong = s.get(path + std::string(path.find('?') == std::string::npos ? "?" : "&") + "token=0123", false);
    ASSERT_TRUE(wrong);
    EXPECT_EQ(wrong->status, 403) << path << " with a wrong token";
  }
  EXPECT_EQ(s.get("/api/run")->status, 200);
  // The page opened with the token sets a cookie that authorises the requests it makes.
  const auto page = s.get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  const std::string cookie = page->get_header_value("Set-Cookie");
  ASSERT_NE(cookie.find("HttpOnly"), std::string::npos) << cookie;
  const auto with_cookie = s.client().Get("/api/run", {{"Cookie", cookie.substr(0, cookie.find(';'))}});
  ASSERT_TRUE(with_cookie);
  EXPECT_EQ(with_cookie->status, 200);
  // Nothing outside the run and the page: no path reaches the file system.
  EXPECT_EQ(s.get("/../../etc/passwd")->status, 404);
  EXPECT_EQ(s.get("/frames.vlog")->status, 404);
  // A known path asked with a method it does not take is a 405 that names the ones it does.
  const auto get_export = s.get("/api/export");
  ASSERT_TRUE(get_export);
  EXPECT_EQ(get_export->status, 405);
  EXPECT_EQ(get_export->get_header_value("Allow"), "POST");
  const auto post_run = s.post("/api/run", "{}");
  ASSERT_TRUE(post_run);
  EXPECT_EQ(post_run->status, 405);
  EXPECT_EQ(post_run->get_header_value("Allow"), "GET, HEAD");
  const auto delete_bookmarks = s.client().Delete(s.authorised("/api/bookmarks").c_str());
  ASSERT_TRUE(delete_bookmarks);
  EXPECT_EQ(delete_bookmarks->status, 405);
  EXPECT_EQ(delete_bookmarks->get_header_value("Allow"), "GET, HEAD, POST");
  EXPECT_EQ(s.post("/api/nowhere", "{}")->status, 404);
}

TEST(ReplayServer, NoTokenModeServesWithoutOne) {
  ScratchDir dir("replay_notoken");
  ReplayOptions o{{synthetic_run(dir, "run")}};
  o.require_token = false;
  LiveServer s(o);
  EXPECT_EQ(s.get("/api/run", false)->status, 200);
  EXPECT_EQ(s.server().url().find("token"), std::string::npos);
  // Nor a token to stop another site: a Host it names (DNS rebinding) or a post from its page.
  EXPECT_EQ(s.client().Get("/api/run", {{"Host", "evil.example.com"}})->status, 403);
  // Not behind a loopback one either: the first of two Hosts (or Origins) was the only one checked.
  EXPECT_EQ(s.client().Get("/api/run", {{"Host", "127.0.0.1"}, {"Host", "evil.example.com"}})->status, 403);
  EXPECT_EQ(s.client().Get("/api/run", {{"Origin", "http://127.0.0.1"}, {"Origin", "http://evil.example.com"}})->status, 403);
  EXPECT_EQ(s.client().Post("/api/bookmarks", {{"Origin", "http://evil.example.com"}}, R"({"name": "x", "t": 0})", "text/plain")->status, 403);
  EXPECT_EQ(s.client().Get("/api/run", {{"Host", "localhost:1"}, {"Origin", "http://127.0.0.1:1"}})->status, 200);
}

TEST(ReplayServer, BadParametersAre400NamingTheParameter) {
  ScratchDir dir("replay_400");
  LiveServer s({{synthetic_run(dir, "run")}});
  const std::pair<std::string, std::string> cases[] = {
      // A misspelt or foreign parameter was ignored, and its default used (T=1 drew t = 0).
      {"/api/frame.png?T=1", "T"},
      {"/api/nodes?t=1&zoom=2", "zoom"},
      {"/api/run?id=3", "id"},
      {"/api/frame.png?t=nan", "t"},
      {"/api/frame.png?t=inf", "t"},
      {"/api/frame.png?t=1e400", "t"},
      {"/api/frame.png?t=", "t"},
      {"/api/frame.png?width=5000", "width"},
      {"/api/frame.png?t=1&t=2", "t"},
      {"/api/frame.png?height=0", "height"},
      {"/api/frame.png?width=12.5", "width"},
      {"/api/frame.png?zoom=0", "zoom"},
      {"/api/frame.png?zoom=-1", "zoom"},
      {"/api/frame.png?camera=orbit", "camera"},
      {"/api/frame.png?camera=center", "center"},
      {"/api/frame.png?center=1", "center"},
      {"/api/frame.png?center=1,nan", "center"},
      {"/api/frame.png?center=1e308,1e308", "center"},
      {"/api/frame.png?camera=fit&center=0.1,0.1", "center"},  // the centre was ignored
      {"/api/frame.png?layers=walls,bogus", "layers"},
      {"/api/frame.png?layers=walls,walls", "layers"},
      {"/api/frame.png?center=0.1,0.2,", "center"},
      {"/api/frame.png?run=b", "run"},
      {"/api/frame.png?run=../../etc", "run"},
      {"/api/frame.png?overlay=b", "overlay"},
      {"/api/nodes?t=x", "t"},
      {"/api/series", "channel"},
      {"/api/series?channel=nope", "channel"},
      {"/api/series?channel=force/contact&reduce=median", "reduce"},
      {"/api/series?channel=tip/error&points=0", "points"},
      {"/api/series?channel=tip/error&from=2&to=1", "to"},
      {"/api/value", "channel"},
      {"/api/value?channel=nope&t=1", "channel"},
      {"/api/value?channel=force/contact&reduce=median&t=1", "reduce"},
      {"/api/value?channel=tip/error&t=x", "t"},
      {"/api/compare?t=1", "run"},
      {"/api/export/status?id=99", "id"},
      {"/api/export/status?id=abc", "id"},
      {"/api/export/file?id=1", "id"},
      {"/api/export/status", "id"},         // was "no such export", as if id=0 had been asked for
      {"/api/frame.png?zoom=0x2", "zoom"},  // strtod read 2
      {"/api/frame.png?width=%20400", "width"},
  };
  for (const auto& [query, parameter] : cases) {
    const json body = get_json(s, query, 400);
    EXPECT_EQ(body.value("parameter", ""), parameter) << query << ": " << body.dump();
    EXPECT_NE(body.value("error", "").find(parameter), std::string::npos) << query << ": " << body.dump();
  }
  // A value without a name is said to be one (the answer blamed a parameter named like the value).
  const json nameless = get_json(s, "/api/run?=a", 400);
  EXPECT_EQ(nameless.value("parameter", ""), "query") << nameless.dump();
  EXPECT_NE(nameless.value("error", "").find("a value without a parameter name"), std::string::npos) << nameless.dump();
  // A control character in a value is shown escaped: a NUL cut the message short ("got '1").
  EXPECT_NE(get_json(s, "/api/frame.png?t=1%00x", 400).value("error", "").find("got '1\\x00x'"), std::string::npos);
  const auto odd = s.client().Post(s.authorised("/api/export?width=321&height=240").c_str(), "", "text/plain");
  ASSERT_TRUE(odd);
  EXPECT_EQ(odd->status, 400);
  EXPECT_EQ(json::parse(odd->body)["parameter"], "width");
  const auto no_body = s.post("/api/bookmarks", "");
  ASSERT_TRUE(no_body);
  EXPECT_EQ(no_body->status, 400);
  EXPECT_EQ(json::parse(no_body->body)["error"], "body: empty; expected JSON {\"name\", \"t\", \"view\"}");
  const auto bad_bookmark = s.post("/api/bookmarks", "{\"name\": \"\", \"t\": 1}");
  ASSERT_TRUE(bad_bookmark);
  EXPECT_EQ(bad_bookmark->status, 400);
  EXPECT_EQ(json::parse(bad_bookmark->body)["parameter"], "name");
  // Two different tokens, either way round: refused (the first was taken). The same value twice
  // is no question, written differently or not (a and %61).
  EXPECT_EQ(s.get(s.authorised("/api/run") + "&token=0123", false)->status, 403);
  EXPECT_EQ(s.get("/api/run?token=0123&token=" + s.server().token(), false)->status, 403);
  EXPECT_EQ(s.get("/api/run?run=a&run=%61")->status, 200);
  EXPECT_EQ(get_json(s, "/api/run?run=a&run=b", 400).value("parameter", ""), "run");
  // Parameters in a body where an endpoint takes none would be ignored: refused.
  const auto form = s.client().Post(s.authorised("/api/export").c_str(), "width=321", "application/x-www-form-urlencoded");
  ASSERT_TRUE(form);
  EXPECT_EQ(form->status, 400) << form->body;
  EXPECT_EQ(json::parse(form->body)["parameter"], "body");
}

TEST(ReplayServer, RunInfoNodesAndSeriesComeFromTheLog) {
  ScratchDir dir("replay_nodes");
  const std::string run = synthetic_run(dir, "run", long_spec());
  auto claim = std::make_unique<RunDirectoryClaim>(run);  // as `vascsim run` holds it while it writes
  LiveServer s({{run}});
  const json info = get_json(s, "/api/run");
  EXPECT_EQ(info["frames"], 101);
  EXPECT_DOUBLE_EQ(info["last_time"].get<double>(), 10.0);
  EXPECT_EQ(info["node_count"], 40);
  // The synthetic log records no friction or drag, and nothing holds its rod: the page greys out
  // those layers.
  EXPECT_EQ(info["layers_with_content"], json({"lumen", "walls", "path", "start_goal", "trail", "rod", "nodes",
                                               "magnetic", "contact", "hud", "legend"}));
  EXPECT_EQ(info["growing"], true) << "a run directory without summary.json whose run holds its claim is being written";
  EXPECT_EQ(info["state"], "writing");
  // A run killed with kill -9 leaves its claim's file, which no process holds any more: the log
  // does not grow, however recently it was written.
  claim.reset();
  vascsim::test::write_text(run + "/" + RunDirectoryClaim::kFileName, "");
  EXPECT_EQ(get_json(s, "/api/run")["growing"], false);
  EXPECT_EQ(get_json(s, "/api/run")["state"], "killed");
  // Its pictures say "Run killed" from then on, as a still that `vascsim render` makes of it.
  const auto killed = s.get("/api/frame.png?t=10&width=320&height=240");
  ASSERT_EQ(killed->status, 200);
  const std::string still = dir / "killed.png";
  ASSERT_EQ(vascsim::test::run_vascsim("render " + run + " --still 10 --width 320 --height 240 --png " + still).exit_code, 0);
  EXPECT_TRUE(killed->body == vascsim::test::read_text(still)) << "the replay's frame of a run killed while served differs from a still of it";
  fs::remove(run + "/" + RunDirectoryClaim::kFileName);
  EXPECT_EQ(get_json(s, "/api/run")["growing"], false) << "no claim: no run writes there";
  EXPECT_EQ(get_json(s, "/api/run")["state"], "killed") << "once killed, a run stays killed";

  render::FrameSource source(run);
  render::FrameState frame, next;
  source.frame(42, frame);
  source.frame(43, next);
  const auto exact = [](double t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", t);
    return std::string(text);
  };
  // At a logged frame's time: that frame's values.
  const json at_frame = get_json(s, "/api/nodes?t=" + exact(frame.time));
  EXPECT_EQ(at_frame["frame"], 42);
  EXPECT_FALSE(at_frame.contains("between"));
  ASSERT_EQ(at_frame["nodes"].size(), 40u);
  for (const int i : {0, 10, 39}) {
    EXPECT_DOUBLE_EQ(at_frame["nodes"][i]["position"][0].get<double>(), frame.position[2 * i]);
    EXPECT_DOUBLE_EQ(at_frame["nodes"][i]["position"][1].get<double>(), frame.position[2 * i + 1]);
    EXPECT_DOUBLE_EQ(at_frame["nodes"][i]["forces"]["force/contact"][0].get<double>(), frame.contact[2 * i]);
  }
  // A third of the way from frame 42 to 43: the values the map's picture of that time is drawn
  // from, a third of the way from one frame's to the next (the nearest frame's put the hover
  // marker off the drawn rod); the nearest frame still named.
  const double t = frame.time + (next.time - frame.time) / 3;
  const json nodes = get_json(s, "/api/nodes?t=" + exact(t));
  EXPECT_EQ(nodes["frame"], 42);
  EXPECT_EQ(nodes["between"], json::array({42, 43}));
  EXPECT_DOUBLE_EQ(nodes["time"].get<double>(), t);
  ASSERT_EQ(nodes["nodes"].size(), 40u);
  double moved = 0;
  for (int i = 0; i < 40; ++i)
    for (int k = 0; k < 2; ++k) {
      const double a = frame.position[2 * i + k], b = next.position[2 * i + k];
      EXPECT_NEAR(nodes["nodes"][i]["position"][k].get<double>(), a + (b - a) / 3, 1e-12) << "node " << i;
      moved = std::max(moved, std::abs(b - a));
    }
  EXPECT_GT(moved, 1e-6) << "the rod does not move between frames 42 and 43: the blend is not checked";
  // Series: min/max over every frame equal the brute-force extremes over the log.
  const json series = get_json(s, "/api/series?channel=force/contact&reduce=max&points=7");
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < source.frame_count(); ++i) {
    source.frame(i, frame);
    lo = std::min(lo, frame.max_contact()), hi = std::max(hi, frame.max_contact());
  }
  double got_lo = 1e300, got_hi = -1e300;
  for (std::size_t k = 0; k < series["t"].size(); ++k) {
    got_lo = std::min(got_lo, series["min"][k].get<double>());
    got_hi = std::max(got_hi, series["max"][k].get<double>());
  }
  EXPECT_LE(series["t"].size(), 7u);
  EXPECT_NEAR(got_lo, lo, 1e-9 * (1 + std::abs(lo)));  // stored as float
  EXPECT_NEAR(got_hi, hi, 1e-6 * hi);
  EXPECT_EQ(series["unit"], "N");
  // The reduction is named as asked (a vector channel's default said "value", which no request can give).
  EXPECT_EQ(get_json(s, "/api/series?channel=tip/reference&points=3")["reduce"], "max");
  EXPECT_EQ(get_json(s, "/api/series?channel=tip/reference&points=3&reduce=x")["reduce"], "x");
}

// A plot's readout at the time cursor is the value the map's frame of that time shows: the
// renderer's state at t (blended between frames, clamped to the run's range), reduced as the
// HUD reduces it. The page read it from /api/series before, as the largest value of the bucket
// around t, which the HUD did not show wherever a bucket held several frames.
TEST(ReplayServer, ValueAtATimeIsWhatTheFrameOfThatTimeShows) {
  ScratchDir dir("replay_value");
  const std::string run = synthetic_run(dir, "run", long_spec());
  LiveServer s({{run}});
  render::FrameSource source(run);
  // The reference, from the two logged frames around t, blended here by hand with the weight a
  // video frame between them has: (t - t0) / (t1 - t0), t clamped to the log.
  auto blended = [&](double t) {
    t = std::clamp(t, source.first_time(), source.last_time());
    std::size_t i = 0;
    while (i + 1 < source.frame_count() && source.time_of(i + 1) <= t) ++i;
    render::FrameState a, b;
    source.frame(i, a);
    if (i + 1 == source.frame_count()) return a;
    source.frame(i + 1, b);
    const double w = (t - a.time) / (b.time - a.time);
    for (std::size_t k = 0; k < a.actuation.size(); ++k) a.actuation[k] += w * (b.actuation[k] - a.actuation[k]);
    for (std::size_t k = 0; k < a.contact.size(); ++k) a.contact[k] += w * (b.contact[k] - a.contact[k]);
    a.reference += w * (b.reference - a.reference);
    a.tip_error += w * (b.tip_error - a.tip_error);
    a.time = t;
    return a;
  };
  const double between = source.time_of(42) + 0.37 * (source.time_of(43) - source.time_of(42));
  for (const double t : {source.time_of(42), between, -1.0, 1e6}) {
    const render::FrameState want = blended(t);
    render::FrameState drawn;  // what the map's HUD is painted from
    source.at_time(t, drawn);
    char at[40];
    std::snprintf(at, sizeof at, "&t=%.17g", t);
    const json contact = get_json(s, std::string("/api/value?channel=force/contact&reduce=max") + at);
    const json magnetic = get_json(s, std::string("/api/value?channel=force/actuation&reduce=sum") + at);
    const json error = get_json(s, std::string("/api/value?channel=tip/error") + at);
    const json x = get_json(s, std::string("/api/value?channel=tip/reference&reduce=x") + at);
    const json y = get_json(s, std::string("/api/value?channel=tip/reference&reduce=y") + at);
    EXPECT_DOUBLE_EQ(contact["time"].get<double>(), want.time) << t;
    const render::FrameState* states[] = {&want, &drawn};
    for (const render::FrameState* f : states) {
      EXPECT_NEAR(contact["value"].get<double>(), f->max_contact(), 1e-12 * f->max_contact()) << t;
      EXPECT_NEAR(magnetic["value"].get<double>(), f->actuation_total().norm(), 1e-12 * f->actuation_total().norm()) << t;
      EXPECT_NEAR(error["value"].get<double>(), f->tip_error, 1e-12 * f->tip_error) << t;
      EXPECT_NEAR(x["value"].get<double>(), f->reference.x(), 1e-12) << t;
      EXPECT_NEAR(y["value"].get<double>(), f->reference.y(), 1e-12) << t;
    }
    EXPECT_EQ(contact["unit"], "N");
    EXPECT_EQ(contact["reduce"], "max");
  }
  // Between frames the value is blended, not a neighbour's: the reference moves, so the test
  // above can tell them apart (the synthetic forces and tip error keep their sizes).
  render::FrameState state;
  source.frame(42, state);
  const Vec2 at_42 = state.reference;
  source.frame(43, state);
  ASSERT_GT((at_42 - state.reference).norm(), 1e-5);
}

// The log of a run still writing, as the live tests write it: a 3-node rod in the synthetic
// maze, frame k at 0.1 k s.
FrameLogHeader live_log_header() {
  FrameLogHeader header;
  header.node_count = 3;
  header.channels = {{channel::kPosition, "m", ChannelLayout::kNodeVectors, 6}};
  header.metadata = write_log_metadata(render::synthetic_metadata(render::SyntheticLogSpec{}));
  return header;
}
void append_live_frame(FrameLogWriter& writer, int k) {
  writer.append(0.1 * k, {0.0, 0.0, 0.001 * k, 0.0, 0.002 * k, 0.001});
}

// DIR/run holding the log of twelve such frames, complete (t = 0 .. 1.1 s), and no summary.
std::string make_twelve_frame_run(const ScratchDir& dir) {
  const std::string run = dir / "run";
  fs::create_directories(run);
  FrameLogWriter writer(run + "/frames.vlog", live_log_header());
  for (int k = 0; k < 12; ++k) append_live_frame(writer, k);
  writer.close();
  return run;
}

// Where the claim cannot be asked about (its file is not one the lock can be asked through: here a
// symlink, which the probe does not follow), a run without a summary is taken to be writing while
// its log has changed in the last 30 s, and killed-or-copied ("unknown", no "Run killed") after.
TEST(ReplayServer, WhereTheClaimCannotBeAskedAboutOnlyARecentLogIsGrowing) {
  ScratchDir dir("replay_claim_unknown");
  const std::string run = synthetic_run(dir, "run");
  const std::string claim_file = run + "/" + RunDirectoryClaim::kFileName;
  fs::create_symlink("elsewhere.lock", claim_file);
  ASSERT_EQ(RunDirectoryClaim::holder(run), RunDirectoryClaim::Holder::kUnknown);
  const std::string log = run + "/frames.vlog";
  fs::last_write_time(log, fs::file_time_type::clock::now() - std::chrono::seconds(20));
  LiveServer s({{run}});
  EXPECT_EQ(get_json(s, "/api/run")["growing"], true) << "a log written 20 s ago may still grow";
  EXPECT_EQ(get_json(s, "/api/run")["state"], "writing");
  fs::last_write_time(log, fs::file_time_type::clock::now() - std::chrono::seconds(40));
  EXPECT_EQ(get_json(s, "/api/run")["growing"], false) << "a log untouched for 40 s is no longer written";
  EXPECT_EQ(get_json(s, "/api/run")["state"], "unknown") << "nothing says the run was killed";
}

// A log that a run is still writing: the server sees appended frames, then the summary.
TEST(ReplayServer, LiveFollowSeesFramesAppendedAfterStart) {
  ScratchDir dir("replay_live");
  const std::string run = dir / "run";
  fs::create_directories(run);
  RunDirectoryClaim claim(run);  // as the run writing it holds it
  FrameLogWriter writer(run + "/frames.vlog", live_log_header());
  auto append = [&](int k) { append_live_frame(writer, k); };
  for (int k = 0; k < 5; ++k) append(k);
  LiveServer s({{run}});
  json info = get_json(s, "/api/run");
  EXPECT_EQ(info["frames"], 5);
  EXPECT_EQ(info["growing"], true);
  EXPECT_TRUE(info["summary"].is_null());
  EXPECT_EQ(s.get("/api/frame.png?t=0.4&width=64&height=64")->status, 200);
  for (int k = 5; k < 12; ++k) append(k);
  info = get_json(s, "/api/run");
  EXPECT_EQ(info["frames"], 12);
  EXPECT_NEAR(info["last_time"].get<double>(), 1.1, 1e-12);
  // The trail cache grows with the log: a frame at the new end renders like a still of it.
  const auto live = s.get("/api/frame.png?t=1.1&width=64&height=64");
  ASSERT_EQ(live->status, 200);
  const json nodes = get_json(s, "/api/nodes?t=1.1");
  EXPECT_EQ(nodes["frame"], 11);
  writer.close();
  vascsim::test::write_text(run + "/summary.json", "{\"format\": \"vascsim-summary/1\", \"ok\": true}");
  info = get_json(s, "/api/run");
  EXPECT_EQ(info["growing"], false);
  EXPECT_EQ(info["summary"]["ok"], true);
  EXPECT_EQ(info["state"], "finished");
  const std::string png = dir / "live.png";
  ASSERT_EQ(vascsim::test::run_vascsim("render " + run + " --still 1.1 --width 64 --height 64 --png " + png).exit_code, 0);
  EXPECT_TRUE(live->body == vascsim::test::read_text(png)) << "a live frame differs from the still of the final log";
  // A frame appended after the summary is not the run's: the served run keeps to its 12.
  {
    std::ofstream f(run + "/frames.vlog", std::ios::binary | std::ios::app);
    const double extra[7] = {1.2, 0.0, 0.0, 0.012, 0.0, 0.024, 0.001};
    f.write(reinterpret_cast<const char*>(extra), sizeof extra);
  }
  EXPECT_EQ(get_json(s, "/api/run")["frames"], 12);
}

// A run watched live that then fails: once its summary appears, the map's HUD says it failed,
// as `vascsim render`'s pictures of it do (the same PNG bytes).
TEST(ReplayServer, ALiveRunThatFailsIsSaidToHaveFailedOnceItsSummaryAppears) {
  ScratchDir dir("replay_live_failed");
  const std::string run = make_twelve_frame_run(dir);
  LiveServer s({{run}});
  const std::string frame = "/api/frame.png?t=1&width=320&height=180";
  const auto running = s.get(frame);
  ASSERT_EQ(running->status, 200);
  vascsim::test::write_text(run + "/summary.json", R"({"format": "vascsim-summary/1", "ok": false,
      "failure": "Newton did not converge", "frames": 12, "simulated_time": 1.13})");
  EXPECT_EQ(get_json(s, "/api/run")["summary"]["ok"], false);
  EXPECT_EQ(get_json(s, "/api/run")["state"], "failed");
  const auto ended = s.get(frame);
  ASSERT_EQ(ended->status, 200);
  EXPECT_NE(ended->body, running->body) << "the HUD does not say the run failed";
  const std::string png = dir / "still.png";
  ASSERT_EQ(vascsim::test::run_vascsim("render " + run + " --still 1 --width 320 --height 180 --png " + png).exit_code, 0);
  EXPECT_TRUE(ended->body == vascsim::test::read_text(png)) << "the frame differs from the still of the failed run";
}

// A run stopped by a signal (Ctrl-C, a job's time limit) is marked on the timeline as stopped,
// not as failed: the simulation did not fail, someone ended it.
TEST(ReplayServer, ARunStoppedBySignalIsMarkedStoppedOnTheTimeline) {
  ScratchDir dir("replay_stopped");
  const std::string run = make_twelve_frame_run(dir);
  vascsim::test::write_text(run + "/summary.json", R"json({"format": "vascsim-summary/1", "ok": false,
      "failure": "stopped by SIGTERM at t = 1.13 s, before the run's end (20 s)", "stopped_by": "SIGTERM",
      "frames": 12, "simulated_time": 1.13})json");
  LiveServer s({{run}});
  EXPECT_EQ(get_json(s, "/api/run")["state"], "stopped");
  const json events = get_json(s, "/api/events");
  ASSERT_FALSE(events["events"].empty());
  EXPECT_EQ(events["events"].back()["kind"], "failure");
  EXPECT_EQ(events["events"].back()["label"], "run stopped by SIGTERM at t = 1.13 s, before the run's end (20 s)");

  // An empty /stopped_by (hand-edited) names no one: a failure, as the log check and the sweep
  // read it too (sim/io/run_summary_reader.h).
  ScratchDir other("replay_stopped_by_empty");
  const std::string failed = make_twelve_frame_run(other);
  vascsim::test::write_text(failed + "/summary.json", R"json({"format": "vascsim-summary/1", "ok": false,
      "failure": "Newton did not converge", "stopped_by": "", "frames": 12, "simulated_time": 1.13})json");
  LiveServer f({{failed}});
  EXPECT_EQ(get_json(f, "/api/events")["events"].back()["label"], "run failed: Newton did not converge");
  EXPECT_EQ(get_json(f, "/api/run")["state"], "failed");
}

// A run that failed replays up to its last frame, with the failure marked on the timeline.
TEST(ReplayServer, AFailedRunReplaysToItsLastFrame) {
  ScratchDir dir("replay_failed");
  const std::string run = dir / "run";
  fs::create_directories(run);
  const std::string scene = R"({"name": "fails", "maze": {"seed": 4}, "rod": {"nodes": 12},
      "solver": {"max_iterations": 1, "adaptive": false, "rel_tol": 1e-14}, "run": {"duration": 1}})";
  vascsim::test::write_text(dir / "scene.json", scene);
  const auto r = vascsim::test::run_vascsim("run " + (dir / "scene.json") + " --out " + run + " --force --quiet");
  ASSERT_EQ(r.exit_code, 1) << "the scene was meant to diverge: " << r.output;
  LiveServer s({{run}});
  const json info = get_json(s, "/api/run");
  EXPECT_EQ(info["summary"]["ok"], false);
  EXPECT_EQ(info["growing"], false);
  const json events = get_json(s, "/api/events");
  ASSERT_FALSE(events["events"].empty());
  EXPECT_EQ(events["events"].back()["kind"], "failure");
  EXPECT_DOUBLE_EQ(events["events"].back()["t"].get<double>(), info["last_time"].get<double>());
  EXPECT_EQ(s.get("/api/frame.png?width=64&height=64&t=" + std::to_string(info["last_time"].get<double>()))->status, 200);
}

// A run's warnings are events on the page's timeline, at the time each first happened and in the
// words `vascsim run` printed: a reviewer can go to the moment a step was retried or the rod was
// squashed. The run is a feed into a dead end that squashes the rod (tests/scenes/crammed_feed.json).
TEST(ReplayServer, EachWarningIsAnEventWhereItFirstHappenedInTheWordsOfVascsimRun) {
  ScratchDir dir("replay_warnings");
  const std::string run = dir / "run";
  const auto r = vascsim::test::run_vascsim("run " + vascsim::test::source_path("tests/scenes/crammed_feed.json") + " --out " + run + " --quiet");
  ASSERT_EQ(r.exit_code, 1) << r.output;
  std::set<std::string> printed;
  const std::string prefix = "vascsim run: warning: ", suffix = " (summary.json /warnings)";
  for (std::size_t at = r.output.find(prefix); at != std::string::npos; at = r.output.find(prefix, at + 1)) {
    const std::size_t end = r.output.find(suffix, at);
    ASSERT_NE(end, std::string::npos) << r.output;
    printed.insert("warning: " + r.output.substr(at + prefix.size(), end - at - prefix.size()));
  }
  EXPECT_GE(printed.size(), 2u) << "a retried step and a squashed rod were expected: " << r.output;
  std::ifstream in(run + "/summary.json");
  const json warnings = json::parse(in)["warnings"];
  LiveServer s({{run}});
  std::set<std::string> marked;
  const json events = get_json(s, "/api/events");
  for (const json& e : events["events"]) {
    if (e["kind"] != "warning") continue;
    const std::string label = e["label"];
    marked.insert(label);
    // At its summary entry's first time, with its count.
    bool found = false;
    for (const auto& [key, w] : warnings.items())
      if (w["count"].get<int>() > 0 && label.find(" " + std::to_string(w["count"].get<int>()) + " times") != std::string::npos &&
          std::abs(e["t"].get<double>() - w["first_time"].get<double>()) <= 1e-12)
        found = true;
    EXPECT_TRUE(found) << label << " at " << e["t"] << " is no entry of " << warnings.dump();
  }
  EXPECT_EQ(marked, printed);
}

// A hand-edited summary's warnings are listed as far as they make sense; the rest is left out.
TEST(ReplayServer, AWarningOfAnotherShapeInAHandEditedSummaryIsLeftOut) {
  ScratchDir dir("replay_warnings_edited");
  const std::string run = synthetic_run(dir, "run", long_spec());
  vascsim::test::write_text(run + "/summary.json", R"({"format": "vascsim-summary/1", "ok": true, "axial_strain_max": 0.25,
      "warnings": {"step_retried": {"count": "many", "first_time": 1}, "unresolved_step": [],
                   "large_axial_strain": {"count": 3, "first_time": 0.5}}})");
  LiveServer s({{run}});
  std::vector<json> listed;
  const json events = get_json(s, "/api/events");
  for (const json& e : events["events"])
    if (e["kind"] == "warning") listed.push_back(e);
  ASSERT_EQ(listed.size(), 1u);
  EXPECT_DOUBLE_EQ(listed[0]["t"].get<double>(), 0.5);
  const std::string label = listed[0]["label"];
  EXPECT_NE(label.find("(up to 25 %"), std::string::npos) << label;
  EXPECT_NE(label.find(" 3 times, first at t = 0.5 s"), std::string::npos) << label;
}

TEST(ReplayServer, CompareAlignsRunsBySimulatedTime) {
  ScratchDir dir("replay_compare");
  render::SyntheticLogSpec a = long_spec(), b = long_spec();
  b.frames = 31;  // a different length and output interval
  b.duration = 6.0;
  b.speed = 0.006;
  const std::string run_a = synthetic_run(dir, "a", a), run_b = synthetic_run(dir, "b", b);
  LiveServer s({{run_a, run_b}});
  EXPECT_EQ(get_json(s, "/api/run?run=b")["frames"], 31);
  EXPECT_EQ(get_json(s, "/api/run?run=b")["same_environment_as_a"], true);
  EXPECT_FALSE(get_json(s, "/api/run?run=a").contains("same_environment_as_a"));
  render::FrameSource sa(run_a), sb(run_b);
  for (const double t : {0.0, 2.55, 5.9, 8.0}) {
    render::FrameState fa, fb;
    sa.at_time(t, fa);
    sb.at_time(t, fb);
    const json c = get_json(s, "/api/compare?t=" + std::to_string(t));
    EXPECT_NEAR(c["tip_distance"].get<double>(), (fa.tip() - fb.tip()).norm(), 1e-12) << "t = " << t;
    EXPECT_EQ(c["clamped_b"], t > 6.0);
  }
  // Overlay: run b's rod drawn over run a's map changes the picture.
  EXPECT_NE(s.get("/api/frame.png?t=3&width=320&height=240&overlay=b")->body,
            s.get("/api/frame.png?t=3&width=320&height=240")->body);
  const std::string png = dir / "overlay.png";
  ASSERT_EQ(vascsim::test::run_vascsim("render " + run_a + " --still 3 --width 320 --height 240 --overlay " + run_b +
                                       " --png " + png)
                .exit_code,
            0);
  EXPECT_TRUE(s.get("/api/frame.png?t=3&width=320&height=240&overlay=b")->body == vascsim::test::read_text(png));
  // With two runs served, a refused overlay says what is wrong with it (it said "needs two runs").
  for (const auto& [query, message] : std::vector<std::pair<std::string, std::string>>{
           {"/api/frame.png?run=b&overlay=b", "overlay: goes with run=a"}, {"/api/frame.png?overlay=c", "got 'c'"}}) {
    const json body = get_json(s, query, 400);
    EXPECT_EQ(body.value("parameter", ""), "overlay") << query;
    EXPECT_NE(body.value("error", "").find(message), std::string::npos) << query << ": " << body.dump();
    EXPECT_EQ(body.value("error", "").find("needs two runs"), std::string::npos) << query << ": " << body.dump();
  }

  // The shorter run first: the overlay, the longer run, moves on past the first run's end (each
  // run clamped to its own range, not the overlay to run a's).
  LiveServer reversed({{run_b, run_a}});
  EXPECT_NE(reversed.get("/api/frame.png?t=6&width=320&height=240&overlay=b")->body,
            reversed.get("/api/frame.png?t=9&width=320&height=240&overlay=b")->body);
}

// Run b from another maze: the page is told, to warn that its rod is drawn over run a's map.
TEST(ReplayServer, RunBFromAnotherEnvironmentIsSaidToBe) {
  ScratchDir dir("replay_other_environment");
  render::SyntheticLogSpec a = long_spec(), b = long_spec();
  b.grid = a.grid + 1;
  LiveServer s({{synthetic_run(dir, "a", a), synthetic_run(dir, "b", b)}});
  EXPECT_EQ(get_json(s, "/api/run?run=b")["same_environment_as_a"], false);
}

TEST(ReplayServer, BookmarksAreSavedAndAForeignFileIsLeftAlone) {
  ScratchDir dir("replay_bookmarks");
  const std::string run = synthetic_run(dir, "run");
  LiveServer s({{run}});
  EXPECT_EQ(get_json(s, "/api/bookmarks")["bookmarks"].size(), 0u);
  const auto added = s.post("/api/bookmarks", R"({"name": "corner", "t": 0.5, "view": "t=0.5&zoom=2"})");
  ASSERT_TRUE(added);
  ASSERT_EQ(added->status, 200) << added->body;
  const json saved = json::parse(vascsim::test::read_text(run + "/bookmarks.json"));
  EXPECT_EQ(saved["format"], "vascsim-bookmarks/1");
  EXPECT_EQ(saved["bookmarks"][0]["name"], "corner");
  EXPECT_EQ(get_json(s, "/api/bookmarks")["bookmarks"][0]["view"], "t=0.5&zoom=2");
  vascsim::test::write_text(run + "/bookmarks.json", "my notes, not JSON");
  const auto refused = s.post("/api/bookmarks", R"({"name": "x", "t": 1})");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 500);
  EXPECT_EQ(vascsim::test::read_text(run + "/bookmarks.json"), "my notes, not JSON");
  // What is wrong with the file is said, not only that it is not one.
  vascsim::test::write_text(run + "/bookmarks.json", R"({"format": "notes/2", "bookmarks": []})");
  const json format = get_json(s, "/api/bookmarks", 500);
  EXPECT_NE(format.value("error", "").find("bookmarks.json: /format: expected \"vascsim-bookmarks/1\""), std::string::npos) << format.dump();
  // Keys another tool (or a later version) keeps in the file survive an added bookmark.
  vascsim::test::write_text(run + "/bookmarks.json", R"({"format": "vascsim-bookmarks/1", "reviewer": "A. N. Other",
      "bookmarks": [{"name": "entry", "t": 0.1, "view": "", "colour": "red"}]})");
  const auto beside = s.post("/api/bookmarks", R"({"name": "exit", "t": 0.9})");
  ASSERT_TRUE(beside);
  ASSERT_EQ(beside->status, 200) << beside->body;
  const json kept = json::parse(vascsim::test::read_text(run + "/bookmarks.json"));
  EXPECT_EQ(kept["reviewer"], "A. N. Other");
  EXPECT_EQ(kept["bookmarks"][0]["colour"], "red");
  EXPECT_EQ(kept["bookmarks"][1]["name"], "exit");
  // A posted bookmark keeps keys of its own (they were dropped), and JSON posted with a form's
  // content type (curl -d's default) is read as JSON (it was refused as a parameter named after
  // the whole body).
  const auto tagged = s.client().Post(s.authorised("/api/bookmarks").c_str(), R"({"name": "tagged", "t": 0.2, "label": "review"})",
                                      "application/x-www-form-urlencoded");
  ASSERT_TRUE(tagged);
  ASSERT_EQ(tagged->status, 200) << tagged->body;
  EXPECT_EQ(json::parse(vascsim::test::read_text(run + "/bookmarks.json"))["bookmarks"][2]["label"], "review");
  // A hand-edited entry the page could not show or seek to is named, and the file left alone.
  const std::string edited = R"({"format": "vascsim-bookmarks/1", "bookmarks": [{"name": "a", "t": 1}, {"name": "b"}]})";
  vascsim::test::write_text(run + "/bookmarks.json", edited);
  const json named = get_json(s, "/api/bookmarks", 500);
  EXPECT_NE(named.value("error", "").find("bookmarks.json: /bookmarks/1/t: expected a time in seconds"), std::string::npos) << named.dump();
  EXPECT_EQ(s.post("/api/bookmarks", R"({"name": "x", "t": 1})")->status, 500);
  EXPECT_EQ(vascsim::test::read_text(run + "/bookmarks.json"), edited);
  // A number the file holds that would be written back changed (another tool's 128-bit id was
  // rounded to a double) is refused, not rounded; so is one posted.
  const std::string big = R"({"format": "vascsim-bookmarks/1", "bookmarks": [{"name": "a", "t": 1, "id": 123456789012345678901234567}]})";
  vascsim::test::write_text(run + "/bookmarks.json", big);
  EXPECT_EQ(get_json(s, "/api/bookmarks")["bookmarks"].size(), 1u) << "shown as it is";
  const auto rounded = s.post("/api/bookmarks", R"({"name": "x", "t": 1})");
  ASSERT_TRUE(rounded);
  EXPECT_EQ(rounded->status, 500);
  EXPECT_NE(rounded->body.find("bookmarks.json: /bookmarks/0/id: 123456789012345678901234567: more digits"), std::string::npos)
      << rounded->body;
  EXPECT_EQ(vascsim::test::read_text(run + "/bookmarks.json"), big);
  fs::remove(run + "/bookmarks.json");
  const auto posted = s.post("/api/bookmarks", R"({"name": "x", "t": 1, "id": 123456789012345678901234567})");
  ASSERT_TRUE(posted);
  EXPECT_EQ(posted->status, 400);
  EXPECT_NE(posted->body.find("/id: 123456789012345678901234567: more digits than a bookmark keeps"), std::string::npos) << posted->body;
  EXPECT_FALSE(fs::exists(run + "/bookmarks.json"));
}

// A run repeated into the served directory (`vascsim run --force` removes the log and writes a
// new one): the server served the old file's frames beside the new run's summary. It now opens
// the run again, answers 409 while the new log has no frame, and counts the reopenings in
// `generation` (also in each frame's header, so the page asks for a reload).
TEST(ReplayServer, ALogReplacedUnderTheServerIsOpenedAgain) {
  ScratchDir dir("replay_replaced");
  const std::string run = synthetic_run(dir, "run");
  LiveServer s({{run}});
  json info = get_json(s, "/api/run");
  EXPECT_EQ(info["frames"], 10);
  EXPECT_EQ(info["generation"], 0);
  EXPECT_EQ(json::parse(s.get("/api/frame.png?width=64&height=48")->get_header_value("X-Vascsim-View"))["generations"]["a"], 0);

  fs::remove(run + "/frames.vlog");
  const auto gone = s.get("/api/run");
  ASSERT_TRUE(gone);
  EXPECT_EQ(gone->status, 409) << gone->body;
  EXPECT_NE(gone->body.find("was replaced since the server opened it"), std::string::npos) << gone->body;

  render::write_synthetic_log(run + "/frames.vlog", long_spec());
  info = get_json(s, "/api/run");
  EXPECT_EQ(info["frames"], 101);
  EXPECT_EQ(info["generation"], 1);
  const auto frame = s.get("/api/frame.png?t=9&width=64&height=48");
  ASSERT_TRUE(frame);
  ASSERT_EQ(frame->status, 200) << frame->body;
  EXPECT_EQ(json::parse(frame->get_header_value("X-Vascsim-View"))["generations"]["a"], 1);
  EXPECT_DOUBLE_EQ(json::parse(frame->get_header_value("X-Vascsim-View"))["time"].get<double>(), 9.0);

  // Cut in place to fewer frames than were served: opened again as well.
  fs::resize_file(run + "/frames.vlog", fs::file_size(run + "/frames.vlog") / 2);
  info = get_json(s, "/api/run");
  EXPECT_EQ(info["generation"], 2);
  EXPECT_LT(info["frames"].get<int>(), 101);

  // Written over in place (the same file, as cp onto it does) by another run with more frames:
  // neither the file nor the frame count says so, its header does (it was not noticed).
  render::SyntheticLogSpec other = long_spec();
  other.nodes = 30;
  other.title = "another run";
  render::write_synthetic_log(dir / "other.vlog", other);
  {
    const std::string bytes = vascsim::test::read_text(dir / "other.vlog");
    std::fstream in_place(run + "/frames.vlog", std::ios::in | std::ios::out | std::ios::binary);
    in_place.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  info = get_json(s, "/api/run");
  EXPECT_EQ(info["generation"], 3);
  EXPECT_EQ(info["frames"], 101);
  EXPECT_EQ(info["node_count"], 30) << info.dump();
}

TEST(ReplayServer, ExportWritesANewMp4EachTime) {
  ScratchDir dir("replay_export");
  const std::string run = synthetic_run(dir, "run", long_spec());
  LiveServer s({{run}});
  std::vector<std::string> files;
  for (int k = 0; k < 2; ++k) {
    const int id = start_export(s, "from=1&to=2&width=160&height=120&fps=10");
    ASSERT_GT(id, 0);
    const json status = finished_export(s, id);
    ASSERT_EQ(status["state"], "done") << status.dump();
    EXPECT_EQ(status["frames_done"], 11);
    files.push_back(status["file"]);
    const auto file = s.get("/api/export/file?id=" + std::to_string(id));
    ASSERT_TRUE(file);
    EXPECT_EQ(file->status, 200);
    EXPECT_TRUE(file->body == vascsim::test::read_text(run + "/" + files.back()));
    const render::VideoInfo video = render::probe_video(run + "/" + files.back());
    EXPECT_EQ(video.codec, "h264");
    EXPECT_EQ(video.frames, 11);
    EXPECT_EQ(video.width, 160);
  }
  EXPECT_EQ(files[0], "export-001.mp4");
  EXPECT_EQ(files[1], "export-002.mp4");
  // A finished export deleted, or a link put in its place, is not served: 404, not a 500 or the
  // link's target.
  fs::remove(run + "/export-001.mp4");
  EXPECT_EQ(s.get("/api/export/file?id=1")->status, 404);
  fs::remove(run + "/export-002.mp4");
  fs::create_symlink(run + "/frames.vlog", run + "/export-002.mp4");
  EXPECT_EQ(s.get("/api/export/file?id=2")->status, 404);
}

// An export of run a with run b drawn over it (overlay=b, as the page's compare view sends it):
// it was refused with the command line's "--overlay draws over a still or a video" message,
// checked before the job had chosen its MP4.
TEST(ReplayServer, AnExportWithTheOverlayIsAVideoOfBoth) {
  ScratchDir dir("replay_export_overlay");
  const std::string a = synthetic_run(dir, "a", long_spec());
  render::SyntheticLogSpec other = long_spec();
  other.speed = 0.002;
  const std::string b = synthetic_run(dir, "b", other);
  LiveServer s({{a, b}});
  const int id = start_export(s, "from=1&to=2&width=160&height=120&fps=10&overlay=b");
  ASSERT_GT(id, 0);
  const json status = finished_export(s, id);
  ASSERT_EQ(status["state"], "done") << status.dump();
  EXPECT_EQ(render::probe_video(a + "/" + status["file"].get<std::string>()).frames, 11);
}

// A third export while two run is refused with 429 and says why (docs/replay.md); the server
// cancels the two when it stops and leaves no partial file. Each of the two renders the whole
// 101-frame run at 30 frames a second and 1280 x 960, seconds of work, so both still run when
// the third request comes a few milliseconds later.
TEST(ReplayServer, AThirdExportWhileTwoRunIsTooManyRequests) {
  ScratchDir dir("replay_export_busy");
  const std::string run = synthetic_run(dir, "run", long_spec());
  {
    LiveServer s({{run}});
    for (int k = 0; k < 3; ++k) {
      const auto r = s.client().Post(s.authorised("/api/export?width=1280&height=960&fps=30").c_str(), "", "text/plain");
      ASSERT_TRUE(r);
      if (k < 2) {
        EXPECT_EQ(r->status, 200) << r->body;
        continue;
      }
      EXPECT_EQ(r->status, 429) << r->body;
      EXPECT_EQ(json::parse(r->body)["error"], "two exports are already running; wait for one to finish");
    }
  }
  for (const auto& entry : std::filesystem::directory_iterator(run))
    EXPECT_EQ(entry.path().filename().string().find("export-"), std::string::npos) << entry.path();
}

// Two servers on one run (two users, or a forgotten one): exports started at once get numbers
// of their own, and bookmarks added through both are all kept.
TEST(ReplayServer, TwoServersOnOneRunShareItsNumbersAndBookmarks) {
  ScratchDir dir("replay_two_servers");
  const std::string run = synthetic_run(dir, "run", long_spec());
  LiveServer s1({{run}}), s2({{run}});
  LiveServer* servers[] = {&s1, &s2};
  int ids[2];
  for (int k = 0; k < 2; ++k) {
    const auto r = servers[k]->client().Post(
        servers[k]->authorised("/api/export?from=1&to=2&width=160&height=120&fps=10").c_str(), "", "text/plain");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    ids[k] = json::parse(r->body)["id"];
  }
  std::set<std::string> files;
  for (int k = 0; k < 2; ++k) {
    json status;
    for (int wait = 0; wait < 600; ++wait) {
      status = get_json(*servers[k], "/api/export/status?id=" + std::to_string(ids[k]));
      if (status["state"] != "running") break;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ASSERT_EQ(status["state"], "done") << status.dump();
    files.insert(status["file"].get<std::string>());
  }
  EXPECT_EQ(files.size(), 2u) << "both servers wrote " << *files.begin();

  std::vector<std::thread> writers;
  for (int k = 0; k < 2; ++k)
    writers.emplace_back([&, k] {
      for (int b = 0; b < 20; ++b)
        servers[k]->post("/api/bookmarks", R"({"name": "b)" + std::to_string(k) + "-" + std::to_string(b) + R"(", "t": 1})");
    });
  for (auto& w : writers) w.join();
  EXPECT_EQ(get_json(s1, "/api/bookmarks")["bookmarks"].size(), 40u);
}

TEST(ReplayServer, BookmarkNamesAreCountedInCharactersAndTimesAreBounded) {
  ScratchDir dir("replay_bookmark_fields");
  LiveServer s({{synthetic_run(dir, "run")}});
  std::string e200, e201 = "\u00e9";
  for (int k = 0; k < 200; ++k) e200 += "\u00e9";
  e201 += e200;
  EXPECT_EQ(s.post("/api/bookmarks", R"({"name": ")" + e200 + R"(", "t": 0.5})")->status, 200) << "200 characters";
  EXPECT_EQ(s.post("/api/bookmarks", R"({"name": ")" + e201 + R"(", "t": 0.5})")->status, 400);
  EXPECT_EQ(s.post("/api/bookmarks", R"({"name": "   ", "t": 0.5})")->status, 400);
  EXPECT_EQ(s.post("/api/bookmarks", R"({"name": "\u00a0\u3000", "t": 0.5})")->status, 400) << "Unicode spaces only";
  EXPECT_EQ(s.post("/api/bookmarks", R"({"name": "\u00a0x", "t": 0.5})")->status, 200);
  EXPECT_EQ(s.post("/api/bookmarks", R"({"name": "a\u0000b", "t": 0.5})")->status, 400);
  EXPECT_EQ(s.post("/api/bookmarks", R"({"name": "late", "t": 1e13})")->status, 400);
}

}  // namespace
}  // namespace vascsim::replay

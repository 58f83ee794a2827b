#include "apps/replay/replay_server.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <random>
#include <thread>

#include <nlohmann/json.hpp>

#include "apps/replay/bookmarks.h"
#include "apps/replay/export_jobs.h"
#include "apps/replay/render_worker.h"
#include "apps/replay/replay_assets.h"
#include "apps/replay/replay_run.h"
#include "apps/replay/request_params.h"
#include "apps/replay/series.h"
#include "render/png_writer.h"
#include "sim/io/json_fields.h"
#include "sim/io/run_summary_reader.h"
#include "sim/io/run_warnings.h"
#include "render/view_frame.h"
#include "sim/scene/input_error.h"

// Last: it pulls in system headers whose macros break Eigen's templates when included first.
#include <httplib.h>

namespace vascsim::replay {

using nlohmann::json;

namespace {

constexpr long long kMaxBodyBytes = 1 << 20;  // bookmark bodies are small

// The run's log was replaced and the new one cannot be opened yet (HTTP 409).
class RunReplaced : public InputError {
 public:
  using InputError::InputError;
};

// 128 random bits as hex, from the OS's entropy source.
std::string random_token() {
  std::random_device rd;
  std::string s;
  const char* hex = "0123456789abcdef";
  for (int i = 0; i < 32; ++i) s.push_back(hex[rd() % 16]);
  return s;
}

// Compares in time independent of where the strings differ.
bool same_secret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

void send_json(httplib::Response& res, const json& body, int status = 200) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(body.dump(-1, ' ', false, json::error_handler_t::replace), "application/json");
}

void send_error(httplib::Response& res, int status, const std::string& message, const std::string& parameter = "") {
  json body = {{"error", message.substr(0, 2000)}};
  if (!parameter.empty()) body["parameter"] = parameter;
  send_json(res, body, status);
}

// Why the HTTP library refused a request before any handler saw it, for its error body.
std::string library_refusal(int status) {
  switch (status) {
    case 404: return "no such endpoint";
    case 413: return "the request body is too large: at most 1 MiB, or 8 kB form-encoded (what curl -d sends: give "
                     "-H 'Content-Type: application/json' for more)";
    case 414: return "the request's URL is too long";
    case 400: return "malformed HTTP request";
    default: return "request refused (HTTP " + std::to_string(status) + ")";
  }
}

// What is wrong with how a request frames its body, checked from its headers before the library
// reads the body (empty if nothing), with the status to answer in `status`. The library would
// wait for a POST's body without a length until the connection closes or times out (10 s) and
// then answer "bad request"; it read a GET's body as the next request; it took the first of two
// Content-Lengths; it read "abc" as an empty body; and a body over the limit it first waited for.
std::string body_framing_problem(const httplib::Request& req, int& status) {
  status = 400;
  const bool chunked = req.has_header("Transfer-Encoding");
  const std::size_t lengths = req.get_header_value_count("Content-Length");
  std::string length;
  for (std::size_t k = 0; k < lengths; ++k) {
    const std::string value = req.get_header_value("Content-Length", k);
    if (value.empty() || value.size() > 18 || value.find_first_not_of("0123456789") != std::string::npos)
      return "Content-Length: expected a number of bytes, got '" + value.substr(0, 40) + "'";
    if (k > 0 && value != length) return "two different Content-Length headers";
    length = value;
  }
  const bool has_body = chunked || (!length.empty() && std::stoll(length) > 0);
  if (req.method != "POST") {
    if (has_body) return req.method + " takes no body";
    return "";
  }
  if (length.empty() && !chunked) {
    status = 411;
    return "a POST needs a Content-Length header (Content-Length: 0 for no body)";
  }
  if (!length.empty() && std::stoll(length) > kMaxBodyBytes) {
    status = 413;
    return "the request body is larger than 1 MiB";
  }
  return "";
}

// Asks the client to end the connection after this answer: given where the request's body (if it
// sent one) is left unread, which the library would otherwise read as the next request on a kept
// connection. The library cannot close from a handler; HTTP clients close on this header.
void ask_to_close(httplib::Response& res) { res.set_header("Connection", "close"); }

// The URL's query parameters. The library also parses a form-encoded body into its parameters,
// so JSON posted with curl -d's default content type became a "parameter" named after the whole
// body; no endpoint takes form fields.
std::multimap<std::string, std::string> query_of(const httplib::Request& req) {
  std::multimap<std::string, std::string> query;
  if (const auto mark = req.target.find('?'); mark != std::string::npos)
    httplib::detail::parse_query_text(req.target.substr(mark + 1), query);
  return query;
}

// The id a started export was given (POST /api/export): required, not defaulted.
int export_id(const RequestParams& p) {
  if (!p.text("id")) throw ParamError("id", "required: the id that POST /api/export returned");
  return static_cast<int>(p.integer("id", 0, 1, 1 << 30));
}

const char* content_type(const std::string& name) {
  auto ends = [&](const char* ext) {
    const std::string e(ext);
    return name.size() >= e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
  };
  if (ends(".html")) return "text/html; charset=utf-8";
  if (ends(".js")) return "text/javascript; charset=utf-8";
  if (ends(".css")) return "text/css; charset=utf-8";
  if (ends(".svg")) return "image/svg+xml";
  if (ends(".png")) return "image/png";
  return "application/octet-stream";
}

}  // namespace

struct ReplayServer::Impl {
  ReplayOptions options;
  std::string token;
  int port = 0;
  std::vector<std::unique_ptr<ReplayRun>> runs;
  std::mutex data_mutex;  // guards the runs: frame sources and their caches are not thread-safe
  RenderWorker worker;
  ExportJobs exports;
  httplib::Server http;
  // The library's stop() does nothing until listen_after_bind() has started; these make a stop
  // that comes first (Ctrl-C right after the start, a test that stops at once) still count.
  std::atomic<bool> serve_called{false}, stop_called{false}, serve_returned{false};

  std::string cookie_name() const { return "vascsim_token_" + std::to_string(port); }

  // Without a token, a page on another site open in the user's browser could reach a server on
  // this machine's loopback by DNS rebinding (a Host it names) or post to it (its Origin): both
  // are refused. A server on another address without a token is open by the user's choice.
  bool loopback_request(const httplib::Request& req) const {
    const auto host_of = [](std::string h) {
      if (const auto scheme = h.find("://"); scheme != std::string::npos) h = h.substr(scheme + 3);
      if (!h.empty() && h[0] == '[') return h.substr(0, h.find(']') + 1);
      return h.substr(0, h.find(':'));
    };
    // Every Host and Origin given must be loopback: the library answers with the first of two
    // (RFC 9112 makes two Hosts an error), which a later one must not get past.
    for (const char* header : {"Host", "Origin"})
      for (std::size_t k = 1; k < req.get_header_value_count(header); ++k)
        if (!is_loopback(host_of(req.get_header_value(header, k)))) return false;
    if (!is_loopback(host_of(req.get_header_value("Host")))) return false;
    const std::string origin = req.get_header_value("Origin");
    return origin.empty() || is_loopback(host_of(origin));
  }

  bool authorised(const httplib::Request& req) const {
    if (!options.require_token) {
      return !is_loopback(options.host) || loopback_request(req);
    }
    // Every token the URL gives must be the right one (a wrong one beside it is not ignored).
    const auto query = query_of(req);
    const auto [first, last] = query.equal_range("token");
    if (first != last)
      return std::all_of(first, last, [&](const auto& given) { return same_secret(given.second, token); });
    const std::string cookies = req.get_header_value("Cookie");
    const std::string key = cookie_name() + "=";
    for (std::size_t at = cookies.find(key); at != std::string::npos; at = cookies.find(key, at + 1)) {
      if (at > 0 && cookies[at - 1] != ' ' && cookies[at - 1] != ';') continue;
      const std::size_t begin = at + key.size(), end = cookies.find(';', begin);
      if (same_secret(cookies.substr(begin, end == std::string::npos ? std::string::npos : end - begin), token))
        return true;
    }
    return false;
  }

  // Run k as its directory holds it now: a log replaced since it was opened (the run repeated
  // with --force into the same directory) is opened again, so no request mixes the old run's
  // frames with the new one's summary; the page sees the generation change and asks for a reload.
  ReplayRun& current(std::size_t k) {
    ReplayRun& run = *runs[k];
    if (!run.source().replaced()) return run;
    try {
      runs[k] = std::make_unique<ReplayRun>(run.id(), run.path(), run.generation() + 1);
    } catch (const InputError& e) {
      throw RunReplaced("run " + run.id() + ": " + run.source().log_path() +
                        " was replaced since the server opened it (a new run in its directory?) and cannot be read yet (" +
                        e.what() + "); it is opened again on the first request that finds it readable (a new run "
                        "has written a frame, and its summary.json if it has one)");
    }
    return *runs[k];
  }

  ReplayRun& run_of(const RequestParams& p) {
    std::vector<std::string> ids;
    for (const auto& r : runs) ids.push_back(r->id());
    const std::string id = p.choice("run", "a", ids);
    return current(id == "a" ? 0 : 1);
  }

  // The `overlay` parameter: "b", the second run drawn over run a's map; none when absent.
  ReplayRun* overlay_of(const RequestParams& p, const ReplayRun& run) {
    const auto o = p.text("overlay");
    if (!o) return nullptr;
    if (runs.size() < 2) throw ParamError("overlay", "needs two runs (vascsim replay RUN_A RUN_B)");
    if (*o != "b") throw ParamError("overlay", "expected b (the second run, drawn over run a's map), got '" + o->substr(0, 64) + "'");
    // Run b over itself would draw one rod twice.
    if (run.id() != "a") throw ParamError("overlay", "goes with run=a (run b is drawn over run a's map, not over its own)");
    return &current(1);
  }

  double time_of(const RequestParams& p, const ReplayRun& run) const {
    return p.number("t", run.source().first_time(), -1e12, 1e12);
  }

  void frame(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    const render::View view = parse_view(p);
    std::vector<std::uint8_t> rgba;
    render::ViewFrameInfo info;
    json generations = json::object();  // of the runs drawn, for the page to notice a replaced one
    {
      std::lock_guard<std::mutex> lock(data_mutex);
      ReplayRun& run = run_of(p);
      const double t = time_of(p, run);
      ReplayRun* overlay = overlay_of(p, run);
      generations[run.id()] = run.generation();
      if (overlay) generations[overlay->id()] = overlay->generation();
      run.refresh();
      if (overlay) overlay->refresh();
      render::ViewFrameInputs in;
      in.source = &run.source();
      in.peaks = run.peaks();
      const std::vector<Vec2>* tips = &run.tips();
      in.tip_of = [tips](std::size_t i) { return (*tips)[i]; };
      in.overlay = overlay ? &overlay->source() : nullptr;
      worker.run(view.width, view.height,
                 [&](render::Canvas& canvas) { info = render::render_view_frame(canvas, in, view, t, rgba); });
    }
    const std::vector<std::uint8_t> png = render::encode_png(rgba.data(), view.width, view.height);
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Vascsim-View", json{{"time", info.time},
                                          {"scale", info.transform.scale},
                                          {"ox", info.transform.ox},
                                          {"oy", info.transform.oy},
                                          {"generations", generations}}
                                         .dump());
    res.set_content(std::string(png.begin(), png.end()), "image/png");
  }

  void run_info(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    std::lock_guard<std::mutex> lock(data_mutex);
    ReplayRun& run = run_of(p);
    run.refresh();
    json info = run.info();
    // Run b's rod drawn over run a's map (overlay) means nothing where their environments differ:
    // the page says so.
    if (&run != runs.front().get())
      info["same_environment_as_a"] = same_environment(runs.front()->source().metadata(), run.source().metadata());
    info["runs"] = json::array();
    for (const auto& r : runs) info["runs"].push_back(r->id());
    send_json(res, info);
  }

  void nodes(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    std::lock_guard<std::mutex> lock(data_mutex);
    ReplayRun& run = run_of(p);
    run.refresh();
    send_json(res, run.nodes(time_of(p, run)));
  }

  // The `channel` and `reduce` parameters of /api/series and /api/value.
  struct ChannelAsked {
    int index;
    const LogChannel* channel;
    SeriesReduce reduce;
    std::string reduce_asked;  // as asked: "value" is no name a request can give
  };
  static ChannelAsked channel_asked(const RequestParams& p, const ReplayRun& run) {
    const auto name = p.text("channel");
    if (!name) throw ParamError("channel", "required: a channel name from /api/run");
    const FrameLogHeader& h = run.source().header();
    const int index = h.find_channel(*name);
    if (index < 0)
      throw ParamError("channel", "no channel '" + name->substr(0, 64) + "' in this run (see /api/run)");
    ChannelAsked asked{index, &h.channels[static_cast<std::size_t>(index)], SeriesReduce::kMax,
                       p.text("reduce").value_or("max")};
    try {
      asked.reduce = reduce_for(*asked.channel, asked.reduce_asked);
    } catch (const std::invalid_argument& e) {
      throw ParamError("reduce", e.what());
    }
    return asked;
  }

  void series(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    std::lock_guard<std::mutex> lock(data_mutex);
    ReplayRun& run = run_of(p);
    run.refresh();
    const ChannelAsked c = channel_asked(p, run);
    const double from = p.number("from", run.source().first_time(), -1e12, 1e12);
    const double to = p.number("to", run.source().last_time(), -1e12, 1e12);
    if (to < from) throw ParamError("to", "must not be before from");
    const int points = static_cast<int>(p.integer("points", 1000, 1, 10000));
    const DecimatedSeries d = decimate_min_max(run.times(), run.series(c.index, c.reduce), from, to, points);
    send_json(res, {{"run", run.id()},
                    {"channel", c.channel->name},
                    {"unit", c.channel->unit},
                    {"reduce", c.reduce_asked},
                    {"t", d.t},
                    {"min", d.min},
                    {"max", d.max}});
  }

  // A plot's readout at the time cursor: the value the map's frame of that time shows, where
  // /api/series gives a bucket's extremes.
  void value(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    std::lock_guard<std::mutex> lock(data_mutex);
    ReplayRun& run = run_of(p);
    run.refresh();
    const ChannelAsked c = channel_asked(p, run);
    const auto [time, value] = run.value_at(c.index, c.reduce, time_of(p, run));
    send_json(res, {{"run", run.id()},
                    {"channel", c.channel->name},
                    {"unit", c.channel->unit},
                    {"reduce", c.reduce_asked},
                    {"time", time},
                    {"value", std::isfinite(value) ? json(value) : json(nullptr)}});
  }

  // First and last frame of each wall-contact episode, the goal and a failure.
  void events(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    std::lock_guard<std::mutex> lock(data_mutex);
    ReplayRun& run = run_of(p);
    run.refresh();
    json list = json::array();
    constexpr std::size_t kMaxEvents = 2000;
    const int contact = run.source().header().find_channel(channel::kContactForce);
    bool truncated = false;
    if (contact >= 0) {
      const auto& times = run.times();
      const auto& force = run.series(contact, SeriesReduce::kMax);
      const std::size_t n = std::min(times.size(), force.size());
      std::size_t episode = 0;
      for (std::size_t i = 0; i < n && !truncated; ++i) {
        const bool touching = force[i] > 0, was = i > 0 && force[i - 1] > 0;
        if (touching && !was) {
          ++episode;
          list.push_back({{"t", times[i]}, {"kind", "contact_start"}, {"label", "contact " + std::to_string(episode) + " starts"}});
        }
        if (touching && (i + 1 == n || !(force[i + 1] > 0)))
          list.push_back({{"t", times[i]}, {"kind", "contact_end"}, {"label", "contact " + std::to_string(episode) + " ends"}});
        truncated = list.size() >= kMaxEvents;
      }
    }
    const json& s = run.summary();
    if (s.is_object() && s.contains("navigation") && s["navigation"].value("goal_reached", false) &&
        s["navigation"]["goal_time"].is_number())
      list.push_back({{"t", s["navigation"]["goal_time"]}, {"kind", "goal"}, {"label", "goal reached"}});
    // Where each warning first happened, in the words `vascsim run` printed.
    for (const RunWarning& w : listed_warnings(s))
      if (std::isfinite(w.first_time))
        list.push_back({{"t", w.first_time}, {"kind", "warning"}, {"label", "warning: " + w.line()}});
    if (s.is_object() && s.contains("ok") && s["ok"] == false) {
      const std::string failure = s["failure"].is_string() ? s["failure"].get<std::string>() : "";
      // A run stopped by a signal is not a failure of the simulation; its /failure says who stopped it.
      const bool stopped = summary_says_stopped(s);
      list.push_back({{"t", run.source().last_time()},
                      {"kind", "failure"},
                      {"label", stopped ? "run " + failure : "run failed: " + failure}});
    }
    std::stable_sort(list.begin(), list.end(), [](const json& a, const json& b) { return a["t"] < b["t"]; });
    send_json(res, {{"run", run.id()}, {"events", list}, {"truncated", truncated}});
  }

  void compare(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    std::lock_guard<std::mutex> lock(data_mutex);
    if (runs.size() < 2) throw ParamError("run", "compare needs two runs (vascsim replay RUN_A RUN_B)");
    const double t = time_of(p, current(0));
    json body = {{"time", t}};
    Vec2 tip[2];
    for (std::size_t k = 0; k < 2; ++k) {
      ReplayRun& run = current(k);
      run.refresh();
      render::FrameState state;
      run.source().at_time(t, state);
      tip[k] = state.tip();
      const std::string id = run.id();
      body["tip_" + id] = {tip[k].x(), tip[k].y()};
      body["clamped_" + id] = t < run.source().first_time() || t > run.source().last_time();
    }
    body["tip_distance"] = (tip[0] - tip[1]).norm();
    send_json(res, body);
  }

  void get_bookmarks(const httplib::Request& req, httplib::Response& res) { bookmarks(req, res, false); }
  void post_bookmark(const httplib::Request& req, httplib::Response& res) { bookmarks(req, res, true); }
  void bookmarks(const httplib::Request& req, httplib::Response& res, bool add) {
    const RequestParams p(query_of(req));
    std::lock_guard<std::mutex> lock(data_mutex);
    ReplayRun& run = run_of(p);
    json list;
    if (add) {
      json body;
      if (req.body.empty()) throw ParamError("body", "empty; expected JSON {\"name\", \"t\", \"view\"}");
      try {
        body = io::parse_json_strictly(req.body, "request body");
      } catch (const InputError& e) {
        throw ParamError("body", std::string(e.what()) + "; expected JSON {\"name\", \"t\", \"view\"}");
      }
      if (const std::string inexact = io::first_inexact_number(req.body); !inexact.empty())
        throw ParamError("body", inexact + ": more digits than a bookmark keeps (a 64-bit integer or a double); send it as a string");
      list = add_bookmark(run.bookmarks_path(), body);
    } else {
      list = load_bookmarks(run.bookmarks_path());
    }
    send_json(res, {{"run", run.id()}, {"bookmarks", list}});
  }

  void start_export(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    render::RenderOptions o;
    o.view = parse_view(p);
    if (o.view.width % 2 || o.view.height % 2)
      throw ParamError(o.view.width % 2 ? "width" : "height", "an MP4 (yuv420p) needs an even frame size");
    o.fps = static_cast<int>(p.integer("fps", 30, 1, 240));
    o.speed = p.number("speed", 1.0, 1e-3, 1e3);
    o.from = p.optional_number("from", -1e12, 1e12);
    o.to = p.optional_number("to", -1e12, 1e12);
    if (o.from && o.to && *o.to < *o.from) throw ParamError("to", "must not be before from");
    std::string path, out_dir;
    {
      std::lock_guard<std::mutex> lock(data_mutex);
      ReplayRun& run = run_of(p);
      path = run.source().log_path();
      out_dir = run.output_dir();
      if (const ReplayRun* overlay = overlay_of(p, run)) o.overlay_run = overlay->source().log_path();
      const double t0 = std::max(o.from.value_or(run.source().first_time()), run.source().first_time());
      const double t1 = std::min(o.to.value_or(run.source().last_time()), run.source().last_time());
      if (std::floor((t1 - t0) * o.fps / o.speed) > 200000)
        throw ParamError("to", "more than 200000 video frames; choose a shorter range or a higher speed");
    }
    try {
      // Checked as the export will run: into an MP4, whose name the job chooses.
      render::RenderOptions as_run = o;
      as_run.mp4_path = out_dir + "/export.mp4";
      render::validate_render_options(as_run);
    } catch (const InputError& e) {
      throw ParamError("from", e.what());
    }
    send_json(res, {{"id", exports.start(path, out_dir, o)}});
  }

  void export_status(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    const auto s = exports.status(export_id(p));
    if (!s) throw ParamError("id", "no such export");
    send_json(res, *s);
  }

  void export_file(const httplib::Request& req, httplib::Response& res) {
    const RequestParams p(query_of(req));
    const auto path = exports.file(export_id(p));
    if (!path) throw ParamError("id", "no finished export with this id");
    // The file the export wrote, as it wrote it: not one deleted since, nor a link put in its place.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(*path, ec))) {
      send_error(res, 404, *path + ": the exported video is no longer there (deleted or replaced since)");
      return;
    }
    auto in = std::make_shared<std::ifstream>(*path, std::ios::binary);
    if (!*in) throw InputError(*path + ": cannot read the exported video");
    in->seekg(0, std::ios::end);
    const auto size = static_cast<std::size_t>(in->tellg());
    in->seekg(0);
    const std::string name = path->substr(path->find_last_of('/') + 1);
    res.set_header("Content-Disposition", "attachment; filename=\"" + name + "\"");
    res.set_content_provider(size, "video/mp4", [in](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
      std::vector<char> buffer(std::min<std::size_t>(length, 1 << 16));
      in->seekg(static_cast<std::streamoff>(offset));
      in->read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      const auto got = in->gcount();
      if (got <= 0) return false;
      return sink.write(buffer.data(), static_cast<std::size_t>(got));
    });
  }

  void asset(const std::string& name, const httplib::Request& req, httplib::Response& res) {
    for (const auto& a : embedded_assets()) {
      if (a.name != name) continue;
      std::string body(reinterpret_cast<const char*>(a.data), a.size);
      if (name == "index.html") {
        const std::string marker = "{{TOKEN}}";
        for (std::size_t at = body.find(marker); at != std::string::npos; at = body.find(marker, at))
          body.replace(at, marker.size(), options.require_token ? token : "");
        if (options.require_token && query_of(req).count("token"))
          res.set_header("Set-Cookie", cookie_name() + "=" + token + "; Path=/; HttpOnly; SameSite=Strict");
      }
      res.set_header("Cache-Control", "no-store");
      res.set_content(body, content_type(name));
      return;
    }
    send_error(res, 404, "no such file");
  }

  using Handler = void (Impl::*)(const httplib::Request&, httplib::Response&);
  // `takes`: the endpoint's parameters (besides token). Any other is refused before the handler
  // runs: a misspelt one (T=1 for t=1) would otherwise be ignored and its default used.
  // `takes_body`: the endpoint reads a JSON body; others refuse one rather than ignore it.
  httplib::Server::Handler wrap(Handler handler, std::vector<std::string> takes, bool takes_body = false) {
    return [this, handler, takes, takes_body](const httplib::Request& req, httplib::Response& res) {
      guarded(req, res, [&] {
        refuse_unknown_parameters(req, takes);
        if (!takes_body && !req.body.empty())
          throw ParamError("body", "this endpoint takes no body: give its parameters in the URL's query");
        (this->*handler)(req, res);
      });
    };
  }
  static void refuse_unknown_parameters(const httplib::Request& req, const std::vector<std::string>& takes) {
    // cpp-httplib reads "=a" as a parameter named "a": a value without a name is refused as such.
    if (const auto mark = req.target.find('?'); mark != std::string::npos) {
      const std::string raw = "&" + req.target.substr(mark + 1);
      if (raw.find("&=") != std::string::npos)
        throw ParamError("query", "a value without a parameter name ('=...')");
    }
    const auto query = query_of(req);
    for (const auto& [name, value] : query) {
      if (name == "token" || std::find(takes.begin(), takes.end(), name) != takes.end()) continue;
      std::string list;
      for (const auto& t : takes) list += (list.empty() ? "" : ", ") + t;
      throw ParamError(name.substr(0, 64), "not a parameter of " + req.path + (list.empty() ? " (it takes none)" : " (it takes " + list + ")"));
    }
  }
  template <class Body>
  void guarded(const httplib::Request&, httplib::Response& res, Body body) {
    try {
      body();
    } catch (const ParamError& e) {
      send_error(res, 400, e.what(), e.parameter());
    } catch (const ExportsBusy& e) {
      send_error(res, 429, e.what());
    } catch (const RunReplaced& e) {
      send_error(res, 409, e.what());
    } catch (const InputError& e) {
      send_error(res, 500, e.what());
    } catch (const std::exception& e) {
      send_error(res, 500, std::string("internal error: ") + e.what());
    }
  }

  // Each path and the methods it answers, for a 405 (not a 404) when it is asked with another.
  std::map<std::string, std::string> allowed_methods;
  void get(const std::string& path, httplib::Server::Handler handler) {
    http.Get(path, std::move(handler));
    add_method(path, "GET, HEAD");
  }
  void post(const std::string& path, httplib::Server::Handler handler) {
    http.Post(path, std::move(handler));
    add_method(path, "POST");
  }
  void add_method(const std::string& path, const std::string& method) {
    std::string& list = allowed_methods[path];
    list += (list.empty() ? "" : ", ") + method;
  }

  void routes() {
    http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      // Nothing the page loads comes from elsewhere, and the token in the URL must not leak.
      res.set_header("X-Content-Type-Options", "nosniff");
      res.set_header("Referrer-Policy", "no-referrer");
      res.set_header("Content-Security-Policy",
                     "default-src 'self'; img-src 'self' blob: data:; style-src 'self' 'unsafe-inline'; "
                     "connect-src 'self'; media-src 'self' blob:; frame-ancestors 'none'");
      if (authorised(req)) {
        int status = 0;
        if (const std::string problem = body_framing_problem(req, status); !problem.empty()) {
          send_error(res, status, problem, status == 400 ? "body" : "");
          ask_to_close(res);
          return httplib::Server::HandlerResponse::Handled;
        }
        return httplib::Server::HandlerResponse::Unhandled;
      }
      ask_to_close(res);
      if (options.require_token)
        send_error(res, 403, "missing or wrong token: open the URL that vascsim replay printed", "token");
      else
        send_error(res, 403, "Host or Origin is not this machine's loopback: a request from another site is refused");
      return httplib::Server::HandlerResponse::Handled;
    });
    get("/", [this](const httplib::Request& req, httplib::Response& res) { asset("index.html", req, res); });
    for (const auto& a : embedded_assets()) {
      if (a.name == "index.html") continue;
      const std::string name = a.name;
      get("/" + name, [this, name](const httplib::Request& req, httplib::Response& res) { asset(name, req, res); });
    }
    const std::vector<std::string> view = {"run", "width", "height", "camera", "zoom", "center", "layers", "overlay"};
    const auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
      a.insert(a.end(), b.begin(), b.end());
      return a;
    };
    get("/api/run", wrap(&Impl::run_info, {"run"}));
    get("/api/frame.png", wrap(&Impl::frame, with(view, {"t"})));
    get("/api/nodes", wrap(&Impl::nodes, {"run", "t"}));
    get("/api/series", wrap(&Impl::series, {"run", "channel", "reduce", "from", "to", "points"}));
    get("/api/value", wrap(&Impl::value, {"run", "channel", "reduce", "t"}));
    get("/api/events", wrap(&Impl::events, {"run"}));
    get("/api/compare", wrap(&Impl::compare, {"t"}));
    get("/api/bookmarks", wrap(&Impl::get_bookmarks, {"run"}));
    post("/api/bookmarks", wrap(&Impl::post_bookmark, {"run"}, true));
    post("/api/export", wrap(&Impl::start_export, with(view, {"from", "to", "fps", "speed"})));
    get("/api/export/status", wrap(&Impl::export_status, {"id"}));
    get("/api/export/file", wrap(&Impl::export_file, {"id"}));
    http.set_error_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (!res.body.empty()) return;
      const auto known = allowed_methods.find(req.path);
      if (res.status == 404 && known != allowed_methods.end()) {
        // A known path asked with another method (GET /api/export): say which it takes.
        res.set_header("Allow", known->second);
        send_error(res, 405, req.method + " is not allowed here; this path takes " + known->second);
        return;
      }
      send_error(res, res.status, library_refusal(res.status));
    });
    http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
      send_error(res, 500, "internal error");
    });
    http.set_payload_max_length(kMaxBodyBytes);
    http.set_read_timeout(10);
    http.set_keep_alive_max_count(1000);
    // An idle keep-alive connection holds its worker until this timeout, and stop() waits for
    // the workers: the library's 5 s made Ctrl-C take 6 s with a browser tab open. A browser
    // reopens a closed connection at its next request, at no cost on localhost.
    http.set_keep_alive_timeout(1);
    // A browser keeps up to 6 idle keep-alive connections per tab, each holding a worker until it
    // times out: the library's default pool (one per core, at least 8) stalled a second tab.
    http.new_task_queue = [] { return new httplib::ThreadPool(64); };
    // SO_REUSEADDR, to restart on a port in TIME_WAIT; not the library's SO_REUSEPORT as well,
    // which let a second server listen on the same port and take half of the first's requests.
    http.set_socket_options([](socket_t sock) {
      int yes = 1;
      ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
  }
};

bool is_loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "localhost" || host == "::1" || host == "[::1]";
}

ReplayServer::ReplayServer(const ReplayOptions& options) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.options = options;
  if (options.runs.empty() || options.runs.size() > 2) throw InputError("expected one or two runs to replay");
  const char* ids[] = {"a", "b"};
  for (std::size_t i = 0; i < options.runs.size(); ++i) s.runs.push_back(std::make_unique<ReplayRun>(ids[i], options.runs[i]));
  s.token = options.require_token ? random_token() : "";
  s.routes();
  if (options.port == 0) {
    s.port = s.http.bind_to_any_port(options.host);
    if (s.port <= 0) throw InputError("cannot listen on " + options.host + " (no free port, or not an address of this machine)");
  } else {
    if (!s.http.bind_to_port(options.host, options.port))
      throw InputError("cannot listen on " + options.host + ":" + std::to_string(options.port) +
                       " (in use, or not an address of this machine)");
    s.port = options.port;
  }
}

ReplayServer::~ReplayServer() { stop(); }

int ReplayServer::port() const { return impl_->port; }
const std::string& ReplayServer::token() const { return impl_->token; }

std::string ReplayServer::url() const {
  const std::string& h = impl_->options.host;
  const std::string host = h == "0.0.0.0" || h.empty() ? "127.0.0.1" : h.find(':') != std::string::npos ? "[" + h + "]" : h;
  return "http://" + host + ":" + std::to_string(impl_->port) + "/" +
         (impl_->options.require_token ? "?token=" + impl_->token : "");
}

void ReplayServer::serve() {
  impl_->serve_called = true;
  if (!impl_->stop_called) impl_->http.listen_after_bind();
  impl_->serve_returned = true;
}

void ReplayServer::stop() {
  impl_->stop_called = true;
  if (!impl_->serve_called) return;  // serve() will see stop_called and not listen
  while (!impl_->http.is_running() && !impl_->serve_returned) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  impl_->http.stop();
}

}  // namespace vascsim::replay

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "apps/replay/bookmarks.h"
#include "apps/replay/request_params.h"
#include "apps/replay/series.h"
#include "render/render_run.h"
#include "sim/io/json_fields.h"
#include "sim/scene/input_error.h"
#include "tests/fuzz/fuzz_harnesses.h"

// Last, as in replay_server.cpp: its system headers' macros break Eigen's templates otherwise.
#include <httplib.h>

namespace vascsim::fuzz {

namespace {

using replay::ParamError;
using replay::RequestParams;

// A run's time range as the handlers see it (s), and a small series to decimate.
constexpr double kFirst = 0.0, kLast = 2.5;

// Every parameter the replay server's handlers read (apps/replay/replay_server.cpp), with the
// same names, ranges and order, minus the data they are applied to.
void parse_like_the_handlers(const RequestParams& p) {
  // /api/frame.png
  const render::View view = replay::parse_view(p);
  if (view.width < 16 || view.width > replay::kMaxFrameSide || view.height < 16 || view.height > replay::kMaxFrameSide)
    fail("parse_view accepted a frame of " + std::to_string(view.width) + " x " + std::to_string(view.height));
  p.choice("run", "a", {"a", "b"});
  p.number("t", kFirst, -1e12, 1e12);
  p.text("overlay");
  // /api/series and /api/value (channel, reduce; t above)
  if (const auto name = p.text("channel")) {
    LogChannel c;
    c.name = *name;
    c.layout = static_cast<ChannelLayout>(name->size() % 3);
    c.count = c.layout == ChannelLayout::kScalars ? 1 : 2 * 3;
    try {
      replay::reduce_for(c, p.text("reduce").value_or("max"));
    } catch (const std::invalid_argument& e) {
      throw ParamError("reduce", e.what());  // as the handler does
    }
  }
  const double from = p.number("from", kFirst, -1e12, 1e12);
  const double to = p.number("to", kLast, -1e12, 1e12);
  const int points = static_cast<int>(p.integer("points", 1000, 1, 10000));
  if (to >= from) {
    std::vector<double> times;
    std::vector<float> values;
    for (int i = 0; i <= 50; ++i) {
      times.push_back(kLast * i / 50);
      values.push_back(static_cast<float>(std::sin(i)));
    }
    const replay::DecimatedSeries d = replay::decimate_min_max(times, values, from, to, points);
    if (d.t.size() > static_cast<std::size_t>(points) || d.min.size() != d.t.size() || d.max.size() != d.t.size())
      fail("decimate_min_max gave " + std::to_string(d.t.size()) + " buckets for points=" + std::to_string(points));
  }
  // /api/export
  render::RenderOptions o;
  o.view = view;
  o.fps = static_cast<int>(p.integer("fps", 30, 1, 240));
  o.speed = p.number("speed", 1.0, 1e-3, 1e3);
  o.from = p.optional_number("from", -1e12, 1e12);
  o.to = p.optional_number("to", -1e12, 1e12);
  if (!(o.from && o.to && *o.to < *o.from)) {
    try {
      render::validate_render_options(o);
    } catch (const InputError& e) {
      throw ParamError("from", e.what());
    }
  }
  // /api/export/status and /api/export/file
  p.integer("id", 0, 1, 1 << 30);
}

const std::string& bookmarks_path() {
  static const std::string path = [] {
    const std::string p =
        (std::filesystem::temp_directory_path() / ("vascsim_fuzz_bookmarks_" + std::to_string(::getpid()) + ".json"))
            .string();
    std::atexit([] { std::remove(bookmarks_path().c_str()); });
    return p;
  }();
  return path;
}

}  // namespace

int replay_request(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t newline = input.find('\n');
  httplib::Params query;
  httplib::detail::parse_query_text(input.substr(0, newline), query);
  try {
    parse_like_the_handlers(RequestParams(query));
  } catch (const ParamError&) {
    // the documented refusal: status 400 naming the parameter
  }
  if (newline == std::string::npos) return 0;
  // POST /api/bookmarks: the body, onto an empty bookmarks file.
  std::remove(bookmarks_path().c_str());
  try {
    replay::add_bookmark(bookmarks_path(), io::parse_json_strictly(input.substr(newline + 1), "request body"));
  } catch (const ParamError&) {
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace vascsim::fuzz

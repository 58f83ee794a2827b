#include "apps/replay/replay_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>

#include "sim/io/json_fields.h"
#include "sim/io/output_file.h"
#include "sim/io/run_summary_reader.h"
#include "sim/scene/input_error.h"

namespace vascsim::replay {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char* layout_name(ChannelLayout l) {
  switch (l) {
    case ChannelLayout::kScalars: return "scalars";
    case ChannelLayout::kNodeVectors: return "node_vectors";
    case ChannelLayout::kVector: return "vector";
  }
  return "scalars";
}

// Finite numbers as numbers, the rest as null (JSON has no NaN).
json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }
json pair(double x, double y) { return json::array({number(x), number(y)}); }

// The cached series of one run stay few: a page asks for a handful of channels.
constexpr std::size_t kMaxCachedSeries = 12;
// Where a run's claim cannot be asked about: a log without a summary that has not grown for this
// long is taken as a killed run's.
constexpr int kStaleLogSeconds = 30;

}  // namespace

ReplayRun::ReplayRun(std::string id, const std::string& run_path, int generation)
    : id_(std::move(id)), path_(run_path), generation_(generation) {
  source_ = std::make_unique<render::FrameSource>(run_path);
  std::error_code ec;
  log_is_file_ = !fs::is_directory(run_path, ec);
  run_dir_ = log_is_file_ ? fs::path(source_->log_path()).parent_path().string() : run_path;
  if (run_dir_.empty()) run_dir_ = ".";
  refresh();
}

void ReplayRun::refresh() {
  // A finished run's frames are those its summary counts: frames appended after it are not the
  // run's (a reader refuses such a log on opening; one served already keeps to the summary's).
  if (!summary_.is_null()) return;
  source_->refresh();
  // A summary belongs to the run directory's own log only.
  const bool own_log = !log_is_file_ || fs::path(source_->log_path()).filename() == "frames.vlog";
  if (!own_log) {
    growing_ = false;
    return;
  }
  std::optional<json> summary;
  try {
    summary = read_run_summary(run_dir_);
    if (!summary) {
      // No summary yet: a run still writing if it holds its claim on the directory; a killed one
      // leaves no summary either. Where the claim cannot be asked about, a run still writing is
      // one whose log has changed lately.
      const bool was_growing = growing_;
      switch (RunDirectoryClaim::holder(run_dir_)) {
        case RunDirectoryClaim::Holder::kRun: growing_ = true; break;
        case RunDirectoryClaim::Holder::kNoClaim:
        case RunDirectoryClaim::Holder::kAbandoned: growing_ = false; break;
        case RunDirectoryClaim::Holder::kUnknown: {
          std::error_code ec;
          const auto written = fs::last_write_time(source_->log_path(), ec);
          growing_ = !ec && fs::file_time_type::clock::now() - written < std::chrono::seconds(kStaleLogSeconds);
        }
      }
      // A run killed while served: its pictures say "Run killed" from now on.
      if (was_growing && !growing_) source_->recheck_run();
      return;
    }
    summary_ = std::move(*summary);
  } catch (const InputError& e) {
    summary_ = json{{"error", e.what()}};
  }
  growing_ = false;
  source_->refresh();
  // The run has ended: the pictures of one that failed say so from now on, as `vascsim render`'s do.
  try {
    source_->recheck_run();
  } catch (const InputError&) {
    // A summary counting other frames than the log (appended to): the served run keeps to the
    // frames it had, and its pictures to what was known when it was opened.
  }
}

std::string ReplayRun::state() const {
  if (const auto& end = source_->ended_early()) return verb(end->how);
  if (growing_) return "writing";
  const auto ok = summary_.find("ok");
  return ok != summary_.end() && ok->is_boolean() && ok->get<bool>() ? "finished" : "unknown";
}

json ReplayRun::info() const {
  const render::FrameSource& s = *source_;
  const FrameLogHeader& h = s.header();
  const LogMetadata& m = s.metadata();
  json channels = json::array();
  for (const LogChannel& c : h.channels)
    channels.push_back({{"name", c.name}, {"unit", c.unit}, {"layout", layout_name(c.layout)}, {"count", c.count}});
  json layers = json::array(), defaults = json::array(), with_content = json::array(), content = json::object();
  const render::LayerSet drawn = render::layers_with_content(m, h);
  for (const auto& name : render::all_layer_names()) {
    layers.push_back(name);
    const render::Layer layer = *render::layer_from_name(name);
    if (render::LayerSet::defaults().has(layer)) defaults.push_back(name);
    if (drawn.has(layer)) with_content.push_back(name);
    if (*render::layer_content_phrase(layer)) content[name] = render::layer_content_phrase(layer);
  }
  return {{"run", id_},
          {"path", path_},
          {"title", m.title},
          {"node_count", h.node_count},
          {"channels", channels},
          {"frames", s.frame_count()},
          {"first_time", s.first_time()},
          {"last_time", s.last_time()},
          {"output_interval", m.output_interval},
          {"growing", growing_},
          {"state", state()},
          {"generation", generation_},
          {"summary", summary_},
          {"bounds", {{"min", pair(m.bounds.min.x(), m.bounds.min.y())}, {"max", pair(m.bounds.max.x(), m.bounds.max.y())}}},
          {"layers", layers},
          {"default_layers", defaults},
          {"layers_with_content", with_content},
          {"layer_content", content}};
}

json ReplayRun::nodes(double t) const {
  const render::FrameSource& s = *source_;
  const std::size_t before = s.frame_at_time(t);
  std::size_t i = before;
  if (i + 1 < s.frame_count() && std::abs(s.time_of(i + 1) - t) < std::abs(s.time_of(i) - t)) ++i;
  // The record the map's picture of t is drawn from, read once (every channel is a slice of it):
  // the nearest frame's values put the hover marker off the drawn rod of a fast-moving run.
  std::vector<double> r;
  s.record_at_time(t, r);
  const FrameLogHeader& h = s.header();
  const int position = h.find_channel(channel::kPosition), velocity = h.find_channel(channel::kVelocity);
  json nodes = json::array();
  for (std::size_t n = 0; n < h.node_count; ++n) {
    const double* p = &r[h.channel_offset(position) + 2 * n];
    json node = {{"index", n}, {"position", pair(p[0], p[1])}};
    if (velocity >= 0) {
      const double* v = &r[h.channel_offset(velocity) + 2 * n];
      node["velocity"] = pair(v[0], v[1]);
      node["speed"] = number(std::hypot(v[0], v[1]));
    }
    json forces = json::object();
    for (std::size_t c = 0; c < h.channels.size(); ++c) {
      const LogChannel& ch = h.channels[c];
      if (ch.layout != ChannelLayout::kNodeVectors || ch.name.rfind("force/", 0) != 0) continue;
      const double* f = &r[h.channel_offset(static_cast<int>(c)) + 2 * n];
      forces[ch.name] = pair(f[0], f[1]);
    }
    node["forces"] = forces;
    nodes.push_back(node);
  }
  json out = {{"run", id_}, {"time", r[0]}, {"frame", i}, {"nodes", nodes}};
  if (r[0] != s.time_of(before)) out["between"] = {before, before + 1};
  return out;
}

std::pair<double, double> ReplayRun::value_at(int channel, SeriesReduce reduce, double t) const {
  std::vector<double> r;
  source_->record_at_time(t, r);
  const FrameLogHeader& h = source_->header();
  return {r[0], reduce_values(&r[h.channel_offset(channel)], h.channels[static_cast<std::size_t>(channel)], reduce)};
}

template <class Visit>
void ReplayRun::scan(std::size_t first, Visit visit) const {
  const FrameLogHeader& h = source_->header();
  const std::size_t per_record = h.record_doubles();
  const std::size_t chunk = std::max<std::size_t>(1, (4u << 20) / (per_record * sizeof(double)));  // ~4 MB reads
  std::vector<double> buffer;
  for (std::size_t i = first; i < source_->frame_count(); i += chunk) {
    const std::size_t n = std::min(chunk, source_->frame_count() - i);
    source_->records(i, n, buffer);
    for (std::size_t k = 0; k < n; ++k) visit(i + k, &buffer[k * per_record]);
  }
}

void ReplayRun::extend_track() {
  if (times_.size() >= source_->frame_count()) return;
  const FrameLogHeader& h = source_->header();
  const std::size_t tip = h.channel_offset(h.find_channel(channel::kPosition)) + 2 * (h.node_count - 1);
  times_.reserve(source_->frame_count());
  tips_.reserve(source_->frame_count());
  scan(times_.size(), [&](std::size_t i, const double* r) {
    source_->check_frame_time(i, r[0], times_.empty() ? 0.0 : times_.back());
    times_.push_back(r[0]);
    tips_.emplace_back(r[tip], r[tip + 1]);
  });
  if (!times_.empty()) source_->times_checked_elsewhere(times_.size(), times_.back());
}

const std::vector<double>& ReplayRun::times() {
  extend_track();
  return times_;
}

const std::vector<Vec2>& ReplayRun::tips() {
  extend_track();
  return tips_;
}

const std::vector<float>& ReplayRun::series(int channel, SeriesReduce reduce) {
  const auto key = std::make_pair(channel, reduce);
  auto it = series_.find(key);
  if (it == series_.end()) {
    if (series_.size() >= kMaxCachedSeries) series_.erase(series_.begin());
    it = series_.emplace(key, std::vector<float>()).first;
  }
  std::vector<float>& values = it->second;
  if (values.size() < source_->frame_count()) {
    const FrameLogHeader& h = source_->header();
    const LogChannel& c = h.channels[static_cast<std::size_t>(channel)];
    const std::size_t offset = h.channel_offset(channel);
    values.reserve(source_->frame_count());
    scan(values.size(), [&](std::size_t, const double* r) {
      values.push_back(static_cast<float>(reduce_values(r + offset, c, reduce)));
    });
  }
  return values;
}

const render::ForcePeaks& ReplayRun::peaks() {
  if (peaks_frames_ != source_->frame_count()) {
    peaks_ = render::measure_force_peaks(*source_);
    peaks_frames_ = source_->frame_count();
  }
  return peaks_;
}

std::string ReplayRun::bookmarks_path() const {
  if (!log_is_file_) return (fs::path(run_dir_) / "bookmarks.json").string();
  return fs::path(source_->log_path()).replace_extension(".bookmarks.json").string();
}

std::string ReplayRun::output_dir() const { return run_dir_; }

}  // namespace vascsim::replay

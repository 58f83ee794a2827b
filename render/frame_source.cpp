#include "render/frame_source.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "sim/io/log_run_check.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

Vec2 FrameState::actuation_total() const {
  Vec2 f = Vec2::Zero();
  for (std::size_t i = 0; i + 1 < actuation.size(); i += 2) f += Vec2(actuation[i], actuation[i + 1]);
  return f;
}

double FrameState::max_contact() const {
  double m = 0;
  for (std::size_t i = 0; i + 1 < contact.size(); i += 2) m = std::max(m, std::hypot(contact[i], contact[i + 1]));
  return m;
}

namespace {

int require_layout(const FrameLogHeader& h, const char* name, ChannelLayout layout, const std::string& path) {
  const int index = h.find_channel(name);
  if (index >= 0 && h.channels[static_cast<std::size_t>(index)].layout != layout)
    throw InputError(path + ": channel '" + name + "' has an unexpected layout");
  return index;
}

}  // namespace

FrameSource::FrameSource(const std::string& run_path)
    : run_path_(run_path), log_path_(frame_log_path(run_path)), reader_(log_path_) {
  const FrameLogHeader& h = reader_.header();
  metadata_ = read_log_metadata(h.metadata, log_path_);
  position_ = require_layout(h, channel::kPosition, ChannelLayout::kNodeVectors, log_path_);
  if (position_ < 0) throw InputError(log_path_ + ": frame log has no 'position' channel");
  if (h.node_count < 2) throw InputError(log_path_ + ": frame log rod has fewer than 2 nodes");
  actuation_ = require_layout(h, channel::kActuationForce, ChannelLayout::kNodeVectors, log_path_);
  contact_ = require_layout(h, channel::kContactForce, ChannelLayout::kNodeVectors, log_path_);
  friction_ = require_layout(h, channel::kFrictionForce, ChannelLayout::kNodeVectors, log_path_);
  drag_ = require_layout(h, channel::kDragForce, ChannelLayout::kNodeVectors, log_path_);
  reference_ = require_layout(h, channel::kTipReference, ChannelLayout::kVector, log_path_);
  tip_error_ = require_layout(h, channel::kTipError, ChannelLayout::kScalars, log_path_);
  // Both or neither: the run writes them together (control.advance).
  feed_force_ = require_layout(h, channel::kFeedForce, ChannelLayout::kScalars, log_path_);
  fed_length_ = require_layout(h, channel::kFeedLength, ChannelLayout::kScalars, log_path_);
  if (feed_force_ < 0) fed_length_ = -1;
  if (fed_length_ < 0) feed_force_ = -1;
  frame_count_ = reader_.frame_count();
  if (frame_count_ == 0) throw InputError(log_path_ + ": frame log has no complete frame");
  first_time_ = checked_time(0);
  last_time_ = checked_time(frame_count_ - 1);
  if (last_time_ < first_time_) throw bad_time(frame_count_ - 1, last_time_, "before the first frame's time");
  recheck_run();
}

void FrameSource::recheck_run() {
  LogRunCheck check = check_log_against_run(run_path_, frame_count_, metadata_.scene_hash);
  warnings_ = std::move(check.warnings);
  // A summary without a time reached (hand-edited) still marks the run, after its log.
  ended_early_ = check.ended_early;
  if (ended_early_ && !std::isfinite(ended_early_->at)) ended_early_->at = last_time_;
}

std::vector<std::string> FrameSource::run_files() const {
  const std::filesystem::path dir = std::filesystem::path(log_path_).parent_path();
  return {log_path_, (dir / "summary.json").string(), (dir / "scene.json").string(), (dir / "bookmarks.json").string()};
}

bool FrameSource::refresh() {
  const std::size_t n = reader_.frame_count();
  if (n <= frame_count_) return false;
  const double last = checked_time(n - 1);
  if (last < last_time_) throw bad_time(n - 1, last, "before an earlier frame's time");
  frame_count_ = n;
  last_time_ = last;
  return true;
}

void FrameSource::check_times(std::size_t end) const {
  for (; times_checked_ < std::min(end, frame_count_); ++times_checked_) {
    const double t = reader_.time_of(times_checked_);
    check_frame_time(times_checked_, t, last_checked_time_);
    last_checked_time_ = t;
  }
}

void FrameSource::check_frame_time(std::size_t i, double t, double previous) const {
  vascsim::check_frame_time(log_path_, i, t, previous);
}

InputError FrameSource::bad_time(std::size_t i, double t, const char* why) const {
  return bad_frame_time(log_path_, i, t, why);
}

double FrameSource::checked_time(std::size_t i) const {
  const double t = reader_.time_of(i);
  if (!std::isfinite(t) || t < 0) throw bad_time(i, t, "not a finite time >= 0");
  return t;
}

Vec2 FrameSource::tip_of(std::size_t i) const {
  double xy[2];
  reader_.read_values(i, reader_.header().channel_offset(position_) + 2 * (reader_.header().node_count - 1), 2, xy);
  return {xy[0], xy[1]};
}

void FrameSource::unpack(const std::vector<double>& r, FrameState& out) const {
  const FrameLogHeader& h = reader_.header();
  auto copy = [&](int channel, std::vector<double>& dst) {
    if (channel < 0) {
      dst.clear();
      return;
    }
    const std::size_t off = h.channel_offset(channel);
    dst.assign(r.begin() + static_cast<long>(off), r.begin() + static_cast<long>(off + h.channels[channel].count));
  };
  out.time = r[0];
  copy(position_, out.position);
  copy(actuation_, out.actuation);
  copy(contact_, out.contact);
  copy(friction_, out.friction);
  copy(drag_, out.drag);
  out.has_reference = reference_ >= 0;
  if (out.has_reference) {
    const std::size_t off = h.channel_offset(reference_);
    out.reference = Vec2(r[off], r[off + 1]);
  }
  out.tip_error = tip_error_ >= 0 ? r[h.channel_offset(tip_error_)] : -1.0;
  out.has_feed = feed_force_ >= 0;
  out.feed_force = out.has_feed ? r[h.channel_offset(feed_force_)] : 0.0;
  out.fed_length = out.has_feed ? r[h.channel_offset(fed_length_)] : 0.0;
}

void FrameSource::frame(std::size_t i, FrameState& out) const {
  reader_.read(i, record_a_);
  if (!std::isfinite(record_a_[0]) || record_a_[0] < 0) throw bad_time(i, record_a_[0], "not a finite time >= 0");
  unpack(record_a_, out);
}

void FrameSource::at_time(double t, FrameState& out) const {
  record_at_time(t, record_a_);
  unpack(record_a_, out);
}

void FrameSource::record_at_time(double t, std::vector<double>& out) const {
  t = std::clamp(t, first_time_, last_time_);
  const std::size_t i = frame_at_time(t);
  reader_.read(i, out);
  if (!std::isfinite(out[0]) || out[0] < 0) throw bad_time(i, out[0], "not a finite time >= 0");
  if (i + 1 >= frame_count_ || t <= out[0]) return;
  reader_.read(i + 1, record_b_);
  const double next = record_b_[0];
  if (!std::isfinite(next) || next < 0) throw bad_time(i + 1, next, "not a finite time >= 0");
  if (next < out[0]) throw bad_time(i + 1, next, "before the previous frame's time");
  const double span = next - out[0];
  if (span <= 0) return;
  // Every value at once (positions, forces, the reference, the tip error), so a value reduced
  // from this record is the one the picture of time t shows.
  const double w = std::clamp((t - out[0]) / span, 0.0, 1.0);
  for (std::size_t k = 1; k < out.size() && k < record_b_.size(); ++k) out[k] += w * (record_b_[k] - out[k]);
  out[0] = t;
}

}  // namespace vascsim::render

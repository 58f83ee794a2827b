#include "render/frame_source.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

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

std::string log_path_of(const std::string& run_path) {
  std::error_code ec;
  if (!std::filesystem::exists(run_path, ec))
    throw InputError(run_path + ": no such run directory or frame log (expected RUN_DIR/frames.vlog)");
  if (std::filesystem::is_directory(run_path, ec)) return (std::filesystem::path(run_path) / "frames.vlog").string();
  return run_path;
}

namespace {

int require_layout(const FrameLogHeader& h, const char* name, ChannelLayout layout, const std::string& path) {
  const int index = h.find_channel(name);
  if (index >= 0 && h.channels[static_cast<std::size_t>(index)].layout != layout)
    throw InputError(path + ": channel '" + name + "' has an unexpected layout");
  return index;
}

}  // namespace

FrameSource::FrameSource(const std::string& run_path) : log_path_(log_path_of(run_path)), reader_(log_path_) {
  const FrameLogHeader& h = reader_.header();
  metadata_ = read_log_metadata(h.metadata, log_path_);
  position_ = require_layout(h, channel::kPosition, ChannelLayout::kNodeVectors, log_path_);
  if (position_ < 0) throw InputError(log_path_ + ": frame log has no 'position' channel");
  if (h.node_count < 2) throw InputError(log_path_ + ": frame log rod has fewer than 2 nodes");
  actuation_ = require_layout(h, channel::kActuationForce, ChannelLayout::kNodeVectors, log_path_);
  contact_ = require_layout(h, channel::kContactForce, ChannelLayout::kNodeVectors, log_path_);
  reference_ = require_layout(h, channel::kTipReference, ChannelLayout::kVector, log_path_);
  tip_error_ = require_layout(h, channel::kTipError, ChannelLayout::kScalars, log_path_);
  frame_count_ = reader_.frame_count();
  if (frame_count_ == 0) throw InputError(log_path_ + ": frame log has no complete frame");
  first_time_ = reader_.time_of(0);
  last_time_ = reader_.time_of(frame_count_ - 1);
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
  out.has_reference = reference_ >= 0;
  if (out.has_reference) {
    const std::size_t off = h.channel_offset(reference_);
    out.reference = Vec2(r[off], r[off + 1]);
  }
  out.tip_error = tip_error_ >= 0 ? r[h.channel_offset(tip_error_)] : -1.0;
}

void FrameSource::frame(std::size_t i, FrameState& out) const {
  reader_.read(i, record_a_);
  unpack(record_a_, out);
}

void FrameSource::at_time(double t, FrameState& out) const {
  const std::size_t i = reader_.frame_at_time(t);
  frame(i, out);
  if (i + 1 >= frame_count_ || t <= out.time) return;
  frame(i + 1, next_);
  const double span = next_.time - out.time;
  if (span <= 0) return;
  const double w = std::clamp((t - out.time) / span, 0.0, 1.0);
  auto blend = [w](std::vector<double>& a, const std::vector<double>& b) {
    for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) a[k] += w * (b[k] - a[k]);
  };
  blend(out.position, next_.position);
  blend(out.actuation, next_.actuation);
  blend(out.contact, next_.contact);
  out.reference += w * (next_.reference - out.reference);
  if (out.tip_error >= 0 && next_.tip_error >= 0) out.tip_error += w * (next_.tip_error - out.tip_error);
  out.time = t;
}

}  // namespace vascsim::render

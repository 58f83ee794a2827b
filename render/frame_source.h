// Reads a run's frame log for the renderer: the metadata, and the state at any time, linearly
// interpolated between the two logged frames around it so a video's frame rate need not match
// the log's output interval. Only the position channel is required; forces, the reference, the
// tip error and the feed are used when the log has them.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sim/io/log_metadata.h"
#include "sim/io/log_run_check.h"
#include "sim/log/frame_log.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

// One moment of a run, as the renderer needs it. Vectors are interleaved x0 y0 x1 y1 ...
struct FrameState {
  double time = 0;                 // s
  std::vector<double> position;    // m, 2 per node
  std::vector<double> actuation;   // N, 2 per node; empty if the log has no actuation channel
  std::vector<double> contact;     // N, 2 per node; empty if absent
  std::vector<double> friction;    // N, 2 per node; empty if absent
  std::vector<double> drag;        // N, 2 per node; empty if absent
  bool has_reference = false;
  Vec2 reference = Vec2::Zero();   // m
  double tip_error = -1;           // m; < 0 if unknown
  bool has_feed = false;           // the root is fed through the inlet (control.advance)
  double feed_force = 0;           // N, the drive's push along the inlet (negative: pulling back)
  double fed_length = 0;           // m, fed so far

  std::size_t node_count() const { return position.size() / 2; }
  Vec2 node(std::size_t i) const { return {position[2 * i], position[2 * i + 1]}; }
  Vec2 tip() const { return node(node_count() - 1); }
  // Sum of the actuation force over all nodes (N): the magnetic force on the robot.
  Vec2 actuation_total() const;
  // Largest per-node contact force magnitude (N); 0 without a contact channel.
  double max_contact() const;
};

class FrameSource {
 public:
  // Opens RUN_DIR/frames.vlog, or the log file itself if `run_path` is a file. Throws
  // InputError naming the file if it is missing, not a log, has no position channel, no
  // complete frame, or a first or last time that is not finite, negative or out of order;
  // every frame read later is checked the same way.
  explicit FrameSource(const std::string& run_path);

  const std::string& log_path() const { return log_path_; }
  // The log and the run's files beside it (summary.json, scene.json, bookmarks.json): what an
  // output never replaces, even with --force.
  std::vector<std::string> run_files() const;
  const LogMetadata& metadata() const { return metadata_; }
  // What a user should know about the log's run on opening it (or at the last recheck_run): a
  // run without summary.json (killed or still writing), a summary the log could not be checked
  // against, or a run that failed or was stopped.
  const std::vector<std::string>& warnings() const { return warnings_; }
  // The run failed or was stopped (its summary says so), and the time it had reached (s, the
  // last frame's where the summary gives none). Its pictures say so.
  const std::optional<EarlyEnd>& ended_early() const { return ended_early_; }
  std::size_t frame_count() const { return frame_count_; }
  double first_time() const { return first_time_; }
  double last_time() const { return last_time_; }
  // Logged frame i exactly.
  void frame(std::size_t i, FrameState& out) const;
  // The state at time t (s), clamped to the logged range and interpolated between frames: the
  // record_at_time(t) the picture of time t is drawn from.
  void at_time(double t, FrameState& out) const;
  // The raw record (as record()) at time t: t clamped to the logged range and every value
  // blended linearly between the two frames around it. out[0] is the time. A value reduced from
  // it (a replay plot's readout at the cursor) is what the picture of that time shows.
  void record_at_time(double t, std::vector<double>& out) const;
  // Index of the last logged frame with time <= t.
  std::size_t frame_at_time(double t) const { return reader_.frame_at_time(t); }
  double time_of(std::size_t i) const { return reader_.time_of(i); }
  // Logged frame i's raw record: time, then every channel's values (docs/frame-log.md).
  void record(std::size_t i, std::vector<double>& out) const { reader_.read(i, out); }
  // Records [first, first + count) back to back, in one read, from the file this source opened
  // (never the path again: a log replaced since would give another run's records).
  void records(std::size_t first, std::size_t count, std::vector<double>& out) const {
    reader_.read_frames(first, count, out);
  }
  // Checks that frames [0, end) have finite, non-negative, non-decreasing times (each frame is
  // read once over the source's life); throws InputError naming the first bad frame.
  void check_times(std::size_t end) const;
  // The one rule for a frame's time: finite, >= 0 and not before the previous frame's
  // (`previous`, s; ignored for frame 0). Throws InputError naming the log and frame i.
  void check_frame_time(std::size_t i, double t, double previous) const;
  // Frames [0, end) were checked elsewhere (a reader that streams every time, like the replay
  // server's index), the last of them at time `last` (s).
  void times_checked_elsewhere(std::size_t end, double last) const {
    if (end <= times_checked_) return;
    times_checked_ = end;
    last_checked_time_ = last;
  }
  // The tip (last node) of logged frame i, reading only its two values.
  Vec2 tip_of(std::size_t i) const;
  // Re-polls the log for frames appended since (a run still writing it). Returns true if the
  // frame count changed.
  bool refresh();
  // Checks the log against its run again, as on opening: once the summary of a run that was
  // still writing has appeared, warnings() and ended_early() are the ended run's. Throws as the
  // constructor does (a summary counting other frames than the log holds).
  void recheck_run();
  // The log's path now names another file, or the log holds fewer frames than it did (cut, or
  // written over in place): this source's frames are no longer the run's.
  bool replaced() const { return reader_.replaced() || reader_.frame_count() < frame_count_; }
  const FrameLogHeader& header() const { return reader_.header(); }
  // The log has the feed's push and length (control.advance): FrameState::has_feed.
  bool has_feed() const { return feed_force_ >= 0; }

 private:
  void unpack(const std::vector<double>& record, FrameState& out) const;
  // Frame i's time, refused (InputError naming the log and the frame) unless finite and >= 0.
  double checked_time(std::size_t i) const;
  InputError bad_time(std::size_t i, double t, const char* why) const;

  std::string run_path_;  // as given: the run directory, or a log file
  std::string log_path_;
  FrameLogReader reader_;
  LogMetadata metadata_;
  std::vector<std::string> warnings_;
  std::optional<EarlyEnd> ended_early_;
  std::size_t frame_count_ = 0;
  double first_time_ = 0, last_time_ = 0;
  int position_ = -1, actuation_ = -1, contact_ = -1, friction_ = -1, drag_ = -1, reference_ = -1, tip_error_ = -1,
      feed_force_ = -1, fed_length_ = -1;
  mutable std::vector<double> record_a_, record_b_;
  mutable std::size_t times_checked_ = 0;  // frames [0, times_checked_) passed check_times
  mutable double last_checked_time_ = 0;   // s
};

}  // namespace vascsim::render

// One run opened for replay: its frame log, its summary, and the caches the server builds
// lazily from streaming passes over the log (times and tips of every frame for the trail and
// the timeline, reduced series for the plots, the arrow scales). Memory grows with the frame
// count only by these per-frame numbers (about 30 bytes per frame, plus 4 per cached series),
// never by whole records. The log may still be growing: refresh() picks up appended frames.
// Not thread-safe: the server serialises access.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/replay/series.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"

namespace vascsim::replay {

class ReplayRun {
 public:
  // `id` is "a" or "b"; `run_path` a run directory or a frame log file; `generation` counts
  // the times the server opened this run again because its log was replaced (0 at start).
  // Throws InputError.
  ReplayRun(std::string id, const std::string& run_path, int generation = 0);

  const std::string& id() const { return id_; }
  int generation() const { return generation_; }
  const std::string& path() const { return path_; }
  render::FrameSource& source() { return *source_; }
  const render::FrameSource& source() const { return *source_; }

  // Picks up frames appended since and a summary.json that appeared.
  void refresh();
  // No summary.json yet, and a `vascsim run` holds its claim on the directory: it is still writing.
  bool growing() const { return growing_; }
  // How the run stands, as python/vascsim_log.py's run_state() says it: "finished", "failed",
  // "stopped", "writing", "killed" or "unknown" (no summary and no claim, a summary that cannot be
  // read, a log outside its run directory).
  std::string state() const;
  const nlohmann::json& summary() const { return summary_; }

  // GET /api/run
  nlohmann::json info() const;
  // GET /api/nodes: every node at time t as the picture of t shows it (between two logged frames,
  // blended as the renderer blends them), with the nearest logged frame's index.
  nlohmann::json nodes(double t) const;
  // GET /api/value: one channel reduced at time t as the map shows that time (clamped to the
  // run's range, blended between frames; see FrameSource::record_at_time). {time (s), value}.
  std::pair<double, double> value_at(int channel, SeriesReduce reduce, double t) const;

  // Time and tip of every logged frame so far.
  const std::vector<double>& times();
  const std::vector<Vec2>& tips();
  // One reduced value per logged frame so far (NaN-free unless the log holds NaN).
  const std::vector<float>& series(int channel, SeriesReduce reduce);
  // The whole log's typical forces, re-measured when the log has grown.
  const render::ForcePeaks& peaks();

  // Where bookmarks and exports go: the run directory (or the log file's directory).
  std::string bookmarks_path() const;
  std::string output_dir() const;

 private:
  void extend_track();
  // Calls `visit(i, record)` for logged frames [first, frame_count), reading big chunks.
  template <class Visit>
  void scan(std::size_t first, Visit visit) const;

  std::string id_, path_, run_dir_;
  int generation_ = 0;
  bool log_is_file_ = false;
  std::unique_ptr<render::FrameSource> source_;
  bool growing_ = false;
  nlohmann::json summary_;
  std::vector<double> times_;
  std::vector<Vec2> tips_;
  std::map<std::pair<int, SeriesReduce>, std::vector<float>> series_;
  render::ForcePeaks peaks_;
  std::size_t peaks_frames_ = 0;
};

}  // namespace vascsim::replay

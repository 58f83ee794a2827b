// The renderer's entry point: turn a run directory (DIR/frames.vlog, as written by
// `vascsim run SCENE --out DIR`) into a review video, a PNG sequence and/or plots. Used by
// `vascsim render` and by `vascsim run --render`. Reads only the frame log, so a run can be
// re-rendered with other settings without re-simulating.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/canvas.h"
#include "render/frame_painter.h"

namespace vascsim::render {

struct RenderOptions {
  // Outputs. If all three are empty the video goes to RUN_DIR/video.mp4.
  std::string mp4_path;   // H.264 MP4 (VP9 WebM if H.264 is unavailable)
  std::string png_dir;    // frame_000000.png, frame_000001.png, ...
  std::string plots_dir;  // tip_trajectory.png, actuation_force.png, snapshots.png, ...
  std::optional<double> still;  // s: render only the view at this time, to png_path
  std::string png_path;         // the still's PNG file
  std::string overlay_run;      // compare: this run's rod drawn over the map (a still or a video)
  View view;              // size, camera, layers, arrow scales
  // The layers the user named (--layers): each that draws nothing for this run (a magnetic force
  // its log does not record, say) gets a warning, rather than a picture silently without it.
  LayerSet layers_named = LayerSet::none();
  int fps = 30;           // video frames per second
  double speed = 1.0;     // simulated seconds per video second
  std::optional<double> from, to;  // s, simulated time range (default: the whole log)
  bool force = false;     // overwrite existing outputs
  AntiAliasing aa = AntiAliasing::kAnalytic;
  // Called after each video or PNG frame with (frames done, frames in all); returning false
  // cancels the render (an InputError, and no output appears).
  std::function<bool(std::size_t, std::size_t)> progress;
  // Called with each warning about the runs read (FrameSource::warnings), before any output.
  std::function<void(const std::string&)> warn;
};

struct RenderReport {
  std::size_t frames = 0;  // video / PNG frames written
  std::string video_path;  // final name (may end in .webm after a fallback)
  std::string video_codec;
  std::string note;        // e.g. the H.264 fallback message; empty if none
  std::vector<std::string> plots;
};

// The most video or PNG frames one render writes (about 3.9 days of 30 fps video).
inline constexpr double kMaxVideoFrames = 1e7;

// Throws InputError (exit code 2 in the CLI) for a missing or bad log, bad options, an
// existing output without `force`, or an unwritable destination; no output file ever appears
// under its final name unless complete.
RenderReport render_run(const std::string& run_dir, const RenderOptions& options);

// Checks options that need no log (sizes, rates, range order); render_run calls it too.
void validate_render_options(const RenderOptions& options);

}  // namespace vascsim::render

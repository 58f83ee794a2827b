#include "render/render_run.h"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <tuple>

#include "render/frame_pipeline.h"
#include "render/frame_source.h"
#include "render/plots.h"
#include "render/png_writer.h"
#include "render/tip_trail.h"
#include "render/video_encoder.h"
#include "render/view_frame.h"
#include "sim/io/json_fields.h"
#include "sim/io/output_file.h"
#include "sim/io/run_files.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

namespace fs = std::filesystem;

namespace {

// frame_NNNNNN.png (six or more digits): the names png_frame_path gives --png-dir's frames.
bool is_rendered_frame_name(const std::string& name) {
  if (name.size() < 16 || name.rfind("frame_", 0) != 0 || name.substr(name.size() - 4) != ".png") return false;
  return name.substr(6, name.size() - 10).find_first_not_of("0123456789") == std::string::npos;
}

// Two outputs of one command never share a file: a video named as one of the frames or plots
// was written over by them halfway (or they by it), with the encoder's noise as the only error.
void check_outputs_apart(const RenderOptions& o) {
  if (o.mp4_path.empty()) return;
  std::error_code ec;
  const auto resolved = [&ec](const std::string& p) {
    const fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return r.has_filename() ? r : r.parent_path();  // "out/" is "out"
  };
  const fs::path video = resolved(o.mp4_path);
  const std::string name = video.filename().string();
  const bool a_frame = is_rendered_frame_name(name);
  const bool a_plot =
      std::find(std::begin(kRunPlotFiles), std::end(kRunPlotFiles), name) != std::end(kRunPlotFiles) || name == kFeedPlotFile;
  for (const auto& [dir, option, one_of_its_files] : {std::tuple{o.png_dir, "--png-dir", a_frame}, std::tuple{o.plots_dir, "--plots", a_plot}}) {
    if (dir.empty()) continue;
    const fs::path written_to = resolved(dir);
    if (written_to == video)
      throw InputError("--mp4 " + o.mp4_path + " is the directory " + option + " writes to: name the video otherwise");
    if (written_to == video.parent_path() && one_of_its_files)
      throw InputError("--mp4 " + o.mp4_path + " is one of the files " + option + " " + dir + " writes: name the video otherwise");
  }
}

}  // namespace

void validate_render_options(const RenderOptions& o) {
  const auto& v = o.view;
  if (v.width < 16 || v.width > 7680 || v.height < 16 || v.height > 4320)
    throw InputError("frame size " + std::to_string(v.width) + "x" + std::to_string(v.height) +
                     ": expected 16..7680 x 16..4320 px");
  if (!o.mp4_path.empty() && (v.width % 2 || v.height % 2))
    throw InputError("--width " + std::to_string(v.width) + " --height " + std::to_string(v.height) +
                     ": an MP4 (yuv420p) needs an even frame width and height");
  if (o.fps < 1 || o.fps > 240) throw InputError("fps: expected 1..240, got " + std::to_string(o.fps));
  if (!(o.speed > 0) || !std::isfinite(o.speed)) throw InputError("speed: expected a positive number");
  if (!(v.zoom > 0) || !std::isfinite(v.zoom)) throw InputError("zoom: expected a positive number");
  if (o.from && o.to && *o.from > *o.to) throw InputError("time range: --from must not be after --to");
  if (o.still && !std::isfinite(*o.still)) throw InputError("still: expected a finite time");
  if (o.still && o.png_path.empty()) throw InputError("--still needs --png FILE");
  if (o.still && (!o.mp4_path.empty() || !o.png_dir.empty() || !o.plots_dir.empty()))
    throw InputError("--still T --png FILE writes one picture; --mp4, --png-dir and --plots render a time range (without --still)");
  if (!o.still && !o.png_path.empty()) throw InputError("--png FILE needs --still T (for a sequence use --png-dir)");
  if (!o.overlay_run.empty() && !o.still && o.mp4_path.empty() && o.png_dir.empty())
    throw InputError("--overlay draws over a still (--still T --png FILE) or a video (--mp4, --png-dir), not --plots");
  check_outputs_apart(o);
}

namespace {

// A frame over the canvas's limits (Canvas::kMaxShapes: a log whose path, walls or lumen has
// millions of points) is drawn incomplete; the report says so rather than nothing.
std::string dropped_note(const Canvas& canvas) {
  if (canvas.dropped() == 0) return "";
  return "warning: " + std::to_string(canvas.dropped()) + " shapes and vertices over a frame's limits (" +
         std::to_string(Canvas::kMaxShapes) + " shapes, " + std::to_string(Canvas::kMaxVertices) +
         " vertices) were not drawn (a path, walls or lumen of millions of points in the log?)";
}

// Run B from another environment is drawn over this run's map, where its rod means nothing:
// most likely the wrong run was named. Said, not refused: two variants of one vessel compare.
std::string overlay_environment_note(const FrameSource& source, const FrameSource& overlay, const std::string& overlay_run) {
  if (same_environment(source.metadata(), overlay.metadata())) return "";
  return "warning: " + overlay_run + " ran in another environment (its walls or lumen differ from this run's): its rod is drawn over this run's map";
}

std::string joined_notes(const std::string& a, const std::string& b) { return a.empty() || b.empty() ? a + b : a + "; " + b; }

// `vascsim render RUN --still T --png FILE`: one view, the same pixels the replay server sends.
RenderReport render_still(const FrameSource& source, const FrameSource* overlay, const std::vector<std::string>& inputs,
                          const RenderOptions& o) {
  check_replaceable_output(o.png_path, o.force, inputs);
  remove_stale_temporaries(fs::path(o.png_path).parent_path().string());
  ViewFrameInputs in;
  in.source = &source;
  in.peaks = measure_force_peaks(source);
  in.overlay = overlay;
  Canvas canvas(o.view.width, o.view.height, o.aa);
  std::vector<std::uint8_t> rgba;
  render_view_frame(canvas, in, o.view, *o.still, rgba);
  write_png(o.png_path, rgba.data(), o.view.width, o.view.height);
  RenderReport report;
  report.frames = 1;
  report.note = joined_notes(overlay ? overlay_environment_note(source, *overlay, o.overlay_run) : "", dropped_note(canvas));
  return report;
}

}  // namespace

namespace {

// A render's own frames: regular files named as png_frame_path names them (frame_ and at least
// six digits). A user's frame_final.png, a link or a directory of such a name is not one, and
// --force never removes it.
std::vector<fs::path> rendered_frames(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> frames;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!is_rendered_frame_name(it->path().filename().string())) continue;
    if (fs::symlink_status(it->path(), ec).type() == fs::file_type::regular) frames.push_back(it->path());
  }
  return frames;
}

// Creates `dir` if needed and proves it writable with a probe file, so a bad destination fails
// before any rendering.
void prepare_directory(const std::string& dir, const char* what) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw InputError(dir + ": cannot create " + what + " directory" + (ec ? " (" + ec.message() + ")" : ""));
  const fs::path probe = fs::path(dir) / ".vascsim-write-probe";
  {
    std::ofstream out(probe);
    if (!out) throw InputError(dir + ": " + what + " directory is not writable");
  }
  fs::remove(probe, ec);
}

}  // namespace

RenderReport render_run(const std::string& run_dir, const RenderOptions& options_in) {
  RenderOptions o = options_in;
  validate_render_options(o);
  FrameSource source(run_dir);
  // Every frame's time, once: a log with a frame out of order must fail, not render a range
  // that its first and last frames alone make look right.
  source.check_times(source.frame_count());
  const auto outside = [&](double t) { return t < source.first_time() || t > source.last_time(); };
  const std::string span =
      " (the log spans " + io::format_number(source.first_time()) + " .. " + io::format_number(source.last_time()) + " s)";
  if (o.still && outside(*o.still))
    throw InputError("--still " + io::format_number(*o.still) + ": no frame at that time" + span);
  if ((o.from && *o.from > source.last_time()) || (o.to && *o.to < source.first_time()))
    throw InputError("--from/--to: no frame in the time range" + span);
  // Compare: run B's rod at each frame's time (clamped to its own range), over this run's map.
  // Its log is checked as this run's is, and its files are inputs too: no output replaces them.
  std::unique_ptr<FrameSource> overlay;
  std::vector<std::string> inputs = source.run_files();
  if (!o.overlay_run.empty()) {
    overlay = std::make_unique<FrameSource>(o.overlay_run);
    overlay->check_times(overlay->frame_count());
    const std::vector<std::string> overlay_files = overlay->run_files();
    inputs.insert(inputs.end(), overlay_files.begin(), overlay_files.end());
  }
  if (o.warn)
    for (const FrameSource* run : {&source, overlay.get()})
      if (run)
        for (const std::string& warning : run->warnings()) o.warn(warning);
  const bool plots_only = !o.still && o.mp4_path.empty() && o.png_dir.empty() && !o.plots_dir.empty();
  if (o.warn && !plots_only) {
    const LayerSet content = layers_with_content(source.metadata(), source.header());
    for (int i = 0; i < static_cast<int>(Layer::kCount); ++i) {
      const Layer layer = static_cast<Layer>(i);
      if (o.layers_named.has(layer) && o.view.layers.has(layer) && !content.has(layer))
        o.warn(std::string("warning: layer '") + layer_name(layer) + "' draws nothing: " + source.log_path() +
               " does not record " + layer_content_phrase(layer));
    }
  }
  if (o.still) return render_still(source, overlay.get(), inputs, o);
  if (o.mp4_path.empty() && o.png_dir.empty() && o.plots_dir.empty()) {
    // A run directory's log named directly renders to the run's video, as its directory does.
    const std::string dir = run_dir_of(run_dir);
    o.mp4_path = !dir.empty() ? (fs::path(dir) / "video.mp4").string() : fs::path(run_dir).replace_extension(".mp4").string();
    validate_render_options(o);
  }
  const double t0 = std::clamp(o.from.value_or(source.first_time()), source.first_time(), source.last_time());
  const double t1 = std::clamp(o.to.value_or(source.last_time()), source.first_time(), source.last_time());
  if (t1 < t0) throw InputError("time range [" + io::format_number(t0) + ", " + io::format_number(t1) + "] s is empty");

  // Refuse before doing any work or removing anything: too many frames, an output in the way.
  const double frames = std::floor((t1 - t0) * o.fps / o.speed + 1e-9) + 1;
  if ((!o.mp4_path.empty() || !o.png_dir.empty()) && frames > kMaxVideoFrames)
    throw InputError("the time range " + io::format_number(t0) + " .. " + io::format_number(t1) + " s at " + std::to_string(o.fps) +
                     " fps and speed " + io::format_number(o.speed) + " makes " + io::format_number(frames) +
                     " frames, more than " + io::format_number(kMaxVideoFrames) + ": choose a shorter --from/--to or a higher --speed");
  // The plots show the logged frames of the range (a clip's plots are the clip's).
  FrameRange plotted;
  if (!o.plots_dir.empty()) {
    plotted.first = source.frame_at_time(t0);
    if (source.time_of(plotted.first) < t0) ++plotted.first;
    plotted.last = source.frame_at_time(t1);
    if (plotted.first > plotted.last)
      throw InputError("--plots: no logged frame from " + io::format_number(t0) + " to " + io::format_number(t1) +
                       " s to plot (frames are " + io::format_number(source.metadata().output_interval) +
                       " s apart): widen --from/--to");
  }
  if (!o.mp4_path.empty()) check_replaceable_output(o.mp4_path, o.force, inputs);
  // What a killed render left here under temporary names goes first (sim/io/output_file.h).
  if (!o.mp4_path.empty()) remove_stale_temporaries(fs::path(o.mp4_path).parent_path().string());
  if (!o.png_dir.empty()) {
    if (!rendered_frames(o.png_dir).empty() && !o.force)
      throw InputError(o.png_dir + ": already holds frame_*.png files (use --force to overwrite)");
    prepare_directory(o.png_dir, "PNG");
  }
  RenderReport report;
  if (!o.plots_dir.empty()) {
    prepare_directory(o.plots_dir, "plots");
    remove_stale_temporaries(o.plots_dir);
    report.plots = write_plots(source, o.plots_dir, o.force, plotted);
  }
  // An earlier render's frames go only once everything else has been checked (a refused
  // --plots removed them and wrote nothing).
  if (!o.png_dir.empty()) {
    std::error_code ec;
    for (const auto& frame : rendered_frames(o.png_dir)) fs::remove(frame, ec);
    remove_stale_temporaries(o.png_dir);
  }
  if (o.mp4_path.empty() && o.png_dir.empty()) return report;
  const auto count = static_cast<std::size_t>(frames);
  const View& view = o.view;
  std::unique_ptr<VideoEncoder> video;
  if (!o.mp4_path.empty()) {
    video = std::make_unique<VideoEncoder>(o.mp4_path, VideoSettings{view.width, view.height, o.fps, 20});
    check_replaceable_output(video->path(), o.force, inputs);
  }

  FrameState state, overlay_state;
  source.frame(0, state);
  const ForceScales scales = choose_force_scales(source, view);
  FramePainter painter(source.metadata(), view, scales, state,
                       {source.ended_early(), overlay ? overlay->ended_early() : std::nullopt});
  Canvas canvas(view.width, view.height, o.aa);

  // Video frames must reach the encoder in order even when two workers also compress PNGs.
  std::mutex order_mutex;
  std::condition_variable order_changed;
  std::size_t next_video = 0;
  bool failed = false;  // a worker failed: the others must not wait for its frame
  const bool png = !o.png_dir.empty();
  auto consume = [&](std::size_t index, const std::vector<std::uint8_t>& rgba) {
    try {
      if (png) write_png(png_frame_path(o.png_dir, index), rgba.data(), view.width, view.height);
      if (video) {
        std::unique_lock<std::mutex> lock(order_mutex);
        order_changed.wait(lock, [&] { return next_video == index || failed; });
        if (failed) return;
        video->add_frame(rgba.data());
        ++next_video;
        order_changed.notify_all();
      }
    } catch (...) {
      {
        std::lock_guard<std::mutex> lock(order_mutex);
        failed = true;
      }
      order_changed.notify_all();
      throw;
    }
  };
  const int workers = png ? 2 : 1;
  FramePipeline pipeline(static_cast<std::size_t>(view.width) * view.height * 4, workers, workers + 2, consume);

  // The trail starts at the log's first frame, also for a clip: the same trail as a still at
  // that time (render_view_frame), and the path that led there.
  TipTrail trail(1.0 / painter.pixels_per_metre());
  const auto tip_of = [&](std::size_t i) { return source.tip_of(i); };
  for (std::size_t k = 0; k < count; ++k) {
    const double t = t0 + static_cast<double>(k) * o.speed / o.fps;
    source.at_time(t, state);
    trail.advance(frames_through(source, t), tip_of);
    if (overlay) overlay->at_time(t, overlay_state);
    painter.paint(canvas, state, trail.points(state.tip()), overlay ? &overlay_state : nullptr);
    canvas.finish(pipeline.acquire().data());
    pipeline.submit(k);
    if (o.progress && !o.progress(k + 1, count)) throw InputError("render cancelled");
  }
  pipeline.finish();
  if (video) {
    video->finish();
    report.video_path = video->path();
    report.video_codec = video->codec();
    report.note = video->note();
  }
  if (overlay) report.note = joined_notes(report.note, overlay_environment_note(source, *overlay, o.overlay_run));
  report.note = joined_notes(report.note, dropped_note(canvas));
  report.frames = count;
  return report;
}

}  // namespace vascsim::render

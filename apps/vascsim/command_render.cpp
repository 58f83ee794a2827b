// vascsim render RUN_DIR: frame log to MP4 / PNG sequence / plots (render/render_run.h).
// Built only with the renderer (VASCSIM_RENDER=ON); the file is globbed into the app either way.
#ifdef VASCSIM_HAVE_RENDER
#include <unistd.h>

#include <chrono>
#include <functional>
#include <memory>
#include <cstdio>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "render/render_run.h"
#include "render/view.h"
#include "sim/scene/input_error.h"

namespace vascsim::cli {

namespace {

const std::vector<OptionSpec>& render_options() {
  static const std::vector<OptionSpec> options = {
      {"mp4", "FILE", "write an H.264 MP4 review video (default RUN_DIR/video.mp4 if no output is given)"},
      {"png-dir", "DIR", "write the frames as DIR/frame_000000.png, ..."},
      {"plots", "DIR", "write plots (trajectory, forces, snapshots, error) of --from..--to as PNG into DIR"},
      {"width", "W", "frame width in px (default 1280)"},
      {"height", "H", "frame height in px (default 720)"},
      {"fps", "F", "video frames per second (default 30)"},
      {"speed", "S", "simulated seconds per video second (default 1)"},
      {"from", "T0", "first simulated time to show, s (default: start of the log)"},
      {"to", "T1", "last simulated time to show, s (default: end of the log)"},
      {"still", "T", "render only the view at simulated time T (s) into --png FILE"},
      {"png", "FILE", "the PNG file of --still"},
      {"camera", "fit|follow|center", "fit the whole maze (default), follow the tip, or centre on --center"},
      {"zoom", "Z", "magnification over the fitted view (default 1)"},
      {"center", "X,Y", "centre of the view in metres (implies --camera center)"},
      {"layers", kListValue, "draw exactly these layers (default: all but nodes,friction,drag); see docs/rendering.md"},
      {"hide", kListValue, "do not draw these layers (applied after --layers)"},
      {"overlay", "RUN_B", "draw run B's rod at the same time over this run's map (a still or a video)"},
      {"actuation-scale", "PX_PER_N", "magnetic force arrow length per newton (default: automatic)"},
      {"contact-scale", "PX_PER_N", "contact force arrow length per newton (default: automatic)"},
      {"aa", "analytic|msaa", "anti-aliasing: analytic edges (default) or 4x multisampling"},
      {"force", "", "overwrite existing outputs"},
      {"quiet", "", "no progress line (there is none unless stderr is a terminal)"},
      {"help", "", "show this help"},
  };
  return options;
}

// "frames done / all, frames per second, ETA" on a terminal, at most 10 times a second, after the
// first second, as vascsim run shows its progress; nothing on a pipe or a log file.
std::function<bool(std::size_t, std::size_t)> terminal_progress(bool enabled, bool& shown) {
  if (!enabled || !::isatty(STDERR_FILENO)) return nullptr;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto last = std::make_shared<double>(0.0);
  return [start, last, &shown](std::size_t done, std::size_t all) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if ((elapsed < 1.0 || elapsed - *last < 0.1) && done < all) return true;
    *last = elapsed;
    const double rate = elapsed > 0 ? done / elapsed : 0.0;
    const double eta = rate > 0 ? (all - done) / rate : 0.0;
    std::fprintf(stderr, "\r  frame %zu / %zu  %.1f frames/s  ETA %.1f s   ", done, all, rate, eta);
    shown = true;
    return true;
  };
}

}  // namespace

int run_render_command(int argc, char** argv) {
  const Args args(argc, argv, 2, render_options());
  if (args.flag("help")) {
    std::printf("usage: vascsim render RUN_DIR [options]\n\nRenders a run's frame log (RUN_DIR/frames.vlog).\n\n%s",
                format_options(render_options()).c_str());
    return 0;
  }
  if (args.positional().size() != 1) throw UsageError("expected one RUN_DIR (or frame log file)");
  render::RenderOptions o;
  o.mp4_path = args.value("mp4").value_or("");
  o.png_dir = args.value("png-dir").value_or("");
  o.plots_dir = args.value("plots").value_or("");
  o.view.width = static_cast<int>(args.integer("width", 1280, 16, 7680));
  o.view.height = static_cast<int>(args.integer("height", 720, 16, 4320));
  o.fps = static_cast<int>(args.integer("fps", 30, 1, 240));
  o.speed = args.number("speed", 1.0, 1e-9, 1e9);
  if (args.value("from")) o.from = args.number("from", 0, -1e12, 1e12);
  if (args.value("to")) o.to = args.number("to", 0, -1e12, 1e12);
  if (args.value("still")) o.still = args.number("still", 0, -1e12, 1e12);
  if (o.still)
    for (const char* range_option : {"from", "to", "fps", "speed"})
      if (args.value(range_option))
        throw UsageError(std::string("--") + range_option + " chooses a video's frames; --still T draws the one picture at T");
  o.png_path = args.value("png").value_or("");
  o.overlay_run = args.value("overlay").value_or("");
  // The view parsers' messages say what was expected; the option is named here.
  const auto view_option = [&args](const char* name, const auto& parse) {
    const auto text = args.value(name);
    if (!text) return;
    try {
      parse(*text);
    } catch (const InputError& e) {
      throw UsageError(std::string("--") + name + ": " + e.what());
    }
  };
  view_option("center", [&o](const std::string& t) {
    o.view.centre = render::parse_centre(t);
    o.view.camera = render::CameraMode::kCentre;
  });
  view_option("camera", [&o](const std::string& t) { o.view.camera = render::parse_camera(t); });
  if (o.view.camera == render::CameraMode::kCentre && !args.value("center"))
    throw UsageError("--camera center needs --center X,Y");
  if (o.view.camera != render::CameraMode::kCentre && args.value("center"))
    throw UsageError("--center goes with --camera center (or no --camera), not --camera " + *args.value("camera"));
  view_option("layers", [&o](const std::string& t) { o.view.layers = o.layers_named = render::parse_layer_list(t); });
  view_option("hide", [&o](const std::string& t) { o.view.layers = render::hide_layers(o.view.layers, t); });
  o.view.zoom = args.number("zoom", 1.0, 1e-3, 1e3);
  o.view.actuation_px_per_newton = args.number("actuation-scale", 0.0, 0.0, 1e15);
  o.view.contact_px_per_newton = args.number("contact-scale", 0.0, 0.0, 1e15);
  const std::string aa = args.value("aa").value_or("analytic");
  if (aa == "analytic") o.aa = render::AntiAliasing::kAnalytic;
  else if (aa == "msaa") o.aa = render::AntiAliasing::kMsaa4;
  else throw UsageError("--aa: expected analytic or msaa, got '" + aa + "'");
  o.force = args.flag("force");

  o.warn = [](const std::string& warning) { std::fprintf(stderr, "vascsim render: %s\n", warning.c_str()); };
  bool progress_shown = false;
  o.progress = terminal_progress(!args.flag("quiet"), progress_shown);
  const render::RenderReport r = render::render_run(args.positional()[0], o);
  if (progress_shown) std::fprintf(stderr, "\n");
  if (!r.note.empty()) std::fprintf(stderr, "vascsim render: %s\n", r.note.c_str());
  if (!r.video_path.empty())
    std::printf("wrote %s (%zu frames, %s, %d fps)\n", r.video_path.c_str(), r.frames, r.video_codec.c_str(), o.fps);
  if (!o.png_dir.empty()) std::printf("wrote %zu PNG frames to %s\n", r.frames, o.png_dir.c_str());
  if (o.still) std::printf("wrote %s\n", o.png_path.c_str());
  for (const auto& p : r.plots) std::printf("wrote %s\n", p.c_str());
  return 0;
}

}  // namespace vascsim::cli

#endif  // VASCSIM_HAVE_RENDER

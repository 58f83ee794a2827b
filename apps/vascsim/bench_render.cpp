// vascsim bench render: frames per second of the renderer on a synthetic run comparable to the
// issue's reference frame (about 60 walls, a 200-node rod, 20 force arrows, HUD), at 1280x720
// and 1920x1080: drawing alone (analytic anti-aliasing and 4x MSAA) and end to end to MP4 and
// to PNG. Prints numbers; asserts nothing.
// Built only with the renderer (VASCSIM_RENDER=ON); the file is globbed into the app either way.
#ifdef VASCSIM_HAVE_RENDER
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render/render_run.h"
#include "render/synthetic_log.h"

namespace vascsim::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Drawing and read-back only, no encoding: the renderer's own cost.
double draw_fps(const std::string& log, int width, int height, render::AntiAliasing aa, int frames, std::string* gl) {
  render::FrameSource source(log);
  render::View view;
  view.width = width;
  view.height = height;
  render::FrameState state;
  source.at_time(source.first_time(), state);
  const auto scales = render::choose_force_scales(source, view);
  render::FramePainter painter(source.metadata(), view, scales, state);
  render::Canvas canvas(width, height, aa);
  if (gl) *gl = canvas.gl_description();
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  std::vector<Vec2> trail;
  const auto start = Clock::now();
  for (int k = 0; k < frames; ++k) {
    source.at_time(source.first_time() + (source.last_time() - source.first_time()) * k / frames, state);
    trail.push_back(state.tip());
    painter.paint(canvas, state, trail);
    canvas.finish(rgba.data());
  }
  return frames / seconds_since(start);
}

double output_fps(const std::string& log, const fs::path& dir, int width, int height, int frames, bool mp4) {
  render::RenderOptions o;
  o.view.width = width;
  o.view.height = height;
  o.fps = 30;
  o.to = (frames - 1) / 30.0;
  o.force = true;
  if (mp4) o.mp4_path = (dir / "bench.mp4").string();
  else o.png_dir = (dir / "png").string();
  const auto start = Clock::now();
  const auto report = render::render_run(log, o);
  return static_cast<double>(report.frames) / seconds_since(start);
}

}  // namespace

int run_bench_render(int argc, char** argv) {
  const std::vector<OptionSpec> options = {
      {"frames", "N", "frames per measurement (default 120)"},
      {"help", "", "show this help"},
  };
  const Args args(argc, argv, 3, options);
  if (args.flag("help")) {
    std::printf("usage: vascsim bench render [options]\n\n%s", format_options(options).c_str());
    return 0;
  }
  const int frames = static_cast<int>(args.integer("frames", 120, 2, 100000));
  const fs::path dir = fs::temp_directory_path() / ("vascsim_bench_render_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string log = (dir / "frames.vlog").string();
  render::SyntheticLogSpec spec;
  spec.grid = 7;  // 4*7 boundary + 6*6 inner = 64 wall segments
  spec.cell = 0.01;
  spec.nodes = 200;
  spec.rod_length = 0.1;
  spec.frames = frames + 1;
  spec.duration = frames / 30.0;
  spec.speed = 0.05;
  spec.contact_nodes.clear();
  for (int i = 0; i < 19; ++i) spec.contact_nodes.push_back(5 + 10 * i);  // 19 contact + 1 magnetic arrow
  render::write_synthetic_log(log, spec);

  std::string gl;
  std::printf("vascsim bench render: %d frames per row; synthetic run with 64 walls, 200-node rod, 20 arrows, HUD\n",
              frames);
  std::printf("%-10s %-28s %10s\n", "size", "what", "frames/s");
  for (auto [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}}) {
    char size[32];
    std::snprintf(size, sizeof size, "%dx%d", w, h);
    const double analytic = draw_fps(log, w, h, render::AntiAliasing::kAnalytic, frames, &gl);
    const double msaa = draw_fps(log, w, h, render::AntiAliasing::kMsaa4, frames, nullptr);
    const double none = draw_fps(log, w, h, render::AntiAliasing::kNone, frames, nullptr);
    std::printf("%-10s %-28s %10.1f\n", size, "draw, no AA", none);
    std::printf("%-10s %-28s %10.1f\n", size, "draw, analytic AA", analytic);
    std::printf("%-10s %-28s %10.1f\n", size, "draw, 4x MSAA", msaa);
    std::printf("%-10s %-28s %10.1f\n", size, "MP4 (H.264), analytic AA", output_fps(log, dir, w, h, frames, true));
    std::printf("%-10s %-28s %10.1f\n", size, "PNG, analytic AA", output_fps(log, dir, w, h, frames, false));
    std::fflush(stdout);
  }
  std::printf("OpenGL: %s\n", gl.c_str());
  std::error_code ec;
  fs::remove_all(dir, ec);
  return 0;
}

}  // namespace vascsim::cli

#endif  // VASCSIM_HAVE_RENDER

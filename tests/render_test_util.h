// Helpers shared by the render tests: scratch directories, synthetic logs, running the vascsim
// executable (or a test tool), and comparing against golden images under tests/golden/.
#pragma once

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render/image_diff.h"
#include "render/synthetic_log.h"

namespace vascsim::render::testing {

namespace fs = std::filesystem;

// A fresh directory, removed when the object goes out of scope.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(fs::temp_directory_path() / ("vascsim_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string operator/(const std::string& child) const { return (path_ / child).string(); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// A ring-shaped vessel: lumen between radii 10 and 20 mm around (25, 25) mm, zero-thickness
// walls on both outlines (as a vessel network logs them), the path most of the way round.
inline Polyline circle(Vec2 centre, double radius, int n, double phase = 0.0) {
  Polyline p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * 3.14159265358979323846 * i / n;
    p.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}
constexpr double kInner = 0.010, kOuter = 0.020;  // m
inline const Vec2 kCentre(0.025, 0.025);          // m

inline LogMetadata annulus_metadata() {
  LogMetadata m;
  m.title = "annulus";
  m.bounds = {Vec2(0, 0), Vec2(0.05, 0.05)};
  m.lumen = {circle(kCentre, kOuter, 120, 0.013), circle(kCentre, kInner, 72, 0.029)};
  for (const auto& ring : m.lumen)
    for (std::size_t i = 0; i < ring.size(); ++i) m.walls.push_back({ring[i], ring[(i + 1) % ring.size()], 0.0});
  for (int i = 0; i <= 60; ++i) {
    const double a = -0.5 * 3.14159265358979323846 + 1.6 * 3.14159265358979323846 * i / 60;
    m.path.push_back(kCentre + 0.5 * (kInner + kOuter) * Vec2(std::cos(a), std::sin(a)));
  }
  m.lumen_width = kOuter - kInner;
  m.start = m.path.front();
  m.goal = m.path.back();
  m.rod_outer_radius = 0.0005;
  m.rod_length = 0.02;
  m.output_interval = 0.1;
  return m;
}

// A frame log `name`.vlog in `dir` with metadata `m` (its rod moves as SyntheticLogSpec's does).
inline std::string write_log(const ScratchDir& dir, const std::string& name, const LogMetadata& m) {
  SyntheticLogSpec spec;
  spec.cell = m.lumen_width > 0 ? m.lumen_width : spec.cell;
  const std::string path = dir / (name + ".vlog");
  write_synthetic_log(path, spec, m);
  return path;
}

// A run directory holding frames.vlog from `spec`.
inline std::string make_run(const ScratchDir& dir, const SyntheticLogSpec& spec, const std::string& name = "run") {
  const std::string run = dir / name;
  fs::create_directories(run);
  write_synthetic_log((fs::path(run) / "frames.vlog").string(), spec);
  return run;
}

// The last frame of a run painted at width x height (the default view, the run's failure if any),
// with what the panel drew.
struct PaintedFrame {
  std::vector<std::uint8_t> rgba;
  std::vector<FramePainter::PanelItem> items;
  std::vector<FramePainter::HudField> hud;
};
inline PaintedFrame paint_last_frame(const std::string& run, int width, int height) {
  FrameSource source(run);
  View view;
  view.width = width;
  view.height = height;
  FrameState state;
  source.frame(source.frame_count() - 1, state);
  FramePainter painter(source.metadata(), view, choose_force_scales(source, view), state, {source.ended_early(), std::nullopt});
  Canvas canvas(width, height);
  painter.paint(canvas, state, {});
  PaintedFrame p;
  p.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  canvas.finish(p.rgba.data());
  p.items = painter.panel_items();
  p.hud = painter.hud_fields();
  return p;
}

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

// Runs `PROGRAM ARGS` (arguments already shell-quoted where needed).
inline CommandResult run_program(const std::string& program, const std::string& args, const ScratchDir& dir) {
  const std::string out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = "'" + program + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// Runs `vascsim ARGS`.
inline CommandResult run_vascsim(const std::string& args, const ScratchDir& dir) { return run_program(VASCSIM_EXE, args, dir); }

// Runs `vascsim ARGS` and kills it with SIGKILL, as a user's kill -9 would, the first time
// `ready()` holds (polled every 2 ms: a file appeared, n frames were written). exit_code is
// 128 + 9 if it was killed, its own if it ended first.
inline CommandResult run_vascsim_killed_when(const std::string& args, const ScratchDir& dir,
                                             const std::function<bool()>& ready) {
  const std::string out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = "exec '" + std::string(VASCSIM_EXE) + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) != pid) {
    if (ready()) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    ::usleep(2000);
  }
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_bytes(out);
  r.err = read_bytes(err);
  return r;
}

// Compares `png` with tests/golden/NAME. With VASCSIM_UPDATE_GOLDENS=1 in the environment it
// replaces the golden instead (scripts/update-goldens), so goldens change only on purpose.
// Tolerance: llvmpipe is deterministic here, but a small slack keeps the goldens valid across
// Mesa point releases that may round an edge pixel differently.
inline void expect_matches_golden(const std::string& png, const std::string& name) {
  const fs::path golden = fs::path(VASCSIM_SOURCE_DIR) / "tests" / "golden" / name;
  const char* update = std::getenv("VASCSIM_UPDATE_GOLDENS");
  if (update && std::string(update) == "1") {
    fs::copy_file(png, golden, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "updated golden " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " missing: run scripts/update-goldens";
  const Image a = load_png(png), b = load_png(golden.string());
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  const DiffStats s = diff_images(a, b, 24, nullptr);
  EXPECT_LE(s.pixels_over, a.width * a.height / 1000)
      << name << ": " << s.pixels_over << " pixels differ by more than 24 (max " << s.max_difference
      << ", PSNR " << s.psnr_db << " dB); compare with: vascsim diff " << png << " " << golden << " --out diff.png";
  EXPECT_GT(s.psnr_db, 40.0) << name;
}

}  // namespace vascsim::render::testing

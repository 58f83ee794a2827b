#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render/view_frame.h"
#include "sim/scene/input_error.h"
#include "tests/fuzz/fuzz_harnesses.h"

namespace vascsim::fuzz {

namespace {

// The readers take a path (they seek and re-poll a growing file), so the bytes go to a file of
// this process's own, removed at exit.
const std::string& input_path() {
  static const std::string path = [] {
    const std::string p =
        (std::filesystem::temp_directory_path() / ("vascsim_fuzz_" + std::to_string(::getpid()) + ".vlog")).string();
    std::atexit([] { std::remove(input_path().c_str()); });
    return p;
  }();
  return path;
}

// Every layer on, on a canvas small enough that a frame costs well under a millisecond of
// painting: what is fuzzed is the reading and the geometry, not the fill rate.
render::View fuzz_view() {
  render::View v;
  v.width = 64;
  v.height = 40;
  v.layers = render::LayerSet::none();
  for (int l = 0; l < static_cast<int>(render::Layer::kCount); ++l) v.layers.set(static_cast<render::Layer>(l), true);
  return v;
}

render::Canvas& canvas() {
  // Never destroyed: OSMesa's teardown at exit is not what is tested.
  static render::Canvas* c = new render::Canvas(fuzz_view().width, fuzz_view().height);
  return *c;
}

}  // namespace

int frame_log(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(input_path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) fail("cannot write " + input_path() + " (" + std::strerror(errno) + ")");
  }
  try {
    const render::FrameSource source(input_path());
    source.check_times(source.frame_count());
    render::ViewFrameInputs in;
    in.source = &source;
    in.peaks = render::measure_force_peaks(source);
    std::vector<std::uint8_t> rgba;
    const double t = 0.5 * (source.first_time() + source.last_time());
    render::render_view_frame(canvas(), in, fuzz_view(), t, rgba);
  } catch (const InputError&) {
    // the documented refusal
  }
  return 0;
}

}  // namespace vascsim::fuzz

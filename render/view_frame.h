// One view of a run at one time, as pixels: the entry point shared by `vascsim render --still`
// and the replay server, so the two give byte-identical PNGs for the same options. The frame is
// interpolated at t exactly as a video frame is, the trail rebuilt from the log's first frame
// (so it is right after a seek backwards), the arrow scales chosen from the whole log.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render/view.h"

namespace vascsim::render {

struct ViewFrameInputs {
  const FrameSource* source = nullptr;
  ForcePeaks peaks;                             // measure_force_peaks(*source), cacheable
  std::function<Vec2(std::size_t)> tip_of;      // logged frame i's tip; default source->tip_of
  const FrameSource* overlay = nullptr;         // compare mode: this run's rod drawn over the map
};

// Paints the view at time t (s, clamped to the log) on `canvas` (view.width x view.height) and
// reads it back into `rgba`. Returns where the world landed and the time shown.
struct ViewFrameInfo {
  ViewTransform transform;
  double time = 0;  // s
};
ViewFrameInfo render_view_frame(Canvas& canvas, const ViewFrameInputs& inputs, const View& view, double t,
                                std::vector<std::uint8_t>& rgba);

}  // namespace vascsim::render

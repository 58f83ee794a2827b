#include "render/view_frame.h"

#include <algorithm>

#include "render/tip_trail.h"

namespace vascsim::render {

ViewFrameInfo render_view_frame(Canvas& canvas, const ViewFrameInputs& in, const View& view, double t,
                                std::vector<std::uint8_t>& rgba) {
  const FrameSource& source = *in.source;
  // Each run is drawn at the time asked for, clamped to its own range: a shorter run A must not
  // hold a longer overlay B at A's end.
  const double asked = t;
  t = std::clamp(t, source.first_time(), source.last_time());
  FrameState first, state, other;
  source.frame(0, first);
  source.at_time(t, state);
  FramePainter painter(source.metadata(), view, scales_for(in.peaks, view), first,
                       {source.ended_early(), in.overlay ? in.overlay->ended_early() : std::nullopt});
  TipTrail trail(1.0 / painter.pixels_per_metre());
  trail.advance(frames_through(source, t), in.tip_of ? in.tip_of : [&](std::size_t i) { return source.tip_of(i); });
  const FrameState* overlay = nullptr;
  if (in.overlay) {
    in.overlay->at_time(asked, other);  // clamps to its own range
    if (other.node_count() > 0) overlay = &other;
  }
  painter.paint(canvas, state, trail.points(state.tip()), overlay);
  rgba.resize(static_cast<std::size_t>(view.width) * view.height * 4);
  canvas.finish(rgba.data());
  return {painter.transform(state), t};
}

}  // namespace vascsim::render

#include "render/tip_trail.h"

#include <algorithm>

#include "render/frame_source.h"

namespace vascsim::render {

void TipTrail::advance(std::size_t end, const std::function<Vec2(std::size_t)>& tip_of) {
  for (; added_ < end; ++added_) {
    const Vec2 p = tip_of(added_);
    if (kept_.empty() || (p - kept_.back()).norm() >= spacing_) kept_.push_back(p);
  }
}

const std::vector<Vec2>& TipTrail::points(Vec2 current) {
  points_ = kept_;
  points_.push_back(current);
  return points_;
}

std::size_t frames_through(const FrameSource& source, double t) {
  const std::size_t i = source.frame_at_time(t);
  const std::size_t end = source.time_of(i) <= t ? i + 1 : 0;
  // The frames a trail is built from are read in order anyway: their times must be too, or the
  // binary search above could have stopped anywhere.
  source.check_times(std::min(end + 1, source.frame_count()));
  return end;
}

}  // namespace vascsim::render

// The tip trail: where the tip has been, from the first logged frame up to the frame shown.
// Logged tip positions are thinned to one per `spacing` (about a pixel), so a trail stays a few
// thousand points on any log, and the interpolated tip of the frame shown ends it. Built the
// same way for every frame of a video (advancing) and for one still at any time (from frame 0),
// so a still at T and video frame at T draw the same trail, forwards or backwards in time.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "sim/env/geometry.h"

namespace vascsim::render {

class FrameSource;

class TipTrail {
 public:
  explicit TipTrail(double spacing_m) : spacing_(spacing_m) {}
  // Adds logged frames [frames_added(), end) in order; `tip_of(i)` gives frame i's tip (m).
  void advance(std::size_t end, const std::function<Vec2(std::size_t)>& tip_of);
  std::size_t frames_added() const { return added_; }
  // The kept points followed by `current` (the tip of the frame shown), oldest first.
  const std::vector<Vec2>& points(Vec2 current);

 private:
  double spacing_;
  std::size_t added_ = 0;
  std::vector<Vec2> kept_, points_;
};

// Logged frames with time <= t: the end to advance a trail to for a frame shown at time t.
std::size_t frames_through(const FrameSource& source, double t);

}  // namespace vascsim::render

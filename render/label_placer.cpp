#include "render/label_placer.h"

#include <algorithm>
#include <cmath>

namespace vascsim::render {

namespace {

bool clear_of(const LabelBox& box, const std::vector<LabelBox>& others) {
  return std::none_of(others.begin(), others.end(), [&](const LabelBox& other) { return box.overlaps(other); });
}

}  // namespace

LabelBox LabelPlacer::place(const LabelBox& asked) {
  LabelBox wanted = asked;
  const float past_right = wanted.max.x - bounds_.max.x, before_left = bounds_.min.x - wanted.min.x;
  const float dx = past_right > 0 ? -past_right : before_left > 0 ? before_left : 0.0f;
  wanted.min.x += dx;
  wanted.max.x += dx;
  const float height = wanted.max.y - wanted.min.y, width = wanted.max.x - wanted.min.x;
  // The spots tried, nearest first: 0, +1, -1, +2, -2, ... label heights (y down: + is below);
  // with something to avoid, also half and whole widths to either side of each.
  struct Spot {
    glm::vec2 shift;
    float distance;
  };
  std::vector<Spot> spots;
  const std::vector<float> sideways = obstacles_.empty() ? std::vector<float>{0.0f}
                                                         : std::vector<float>{0.0f, 0.5f, -0.5f, 1.0f, -1.0f};
  for (const float across : sideways)
    for (int step = 0; step <= 2 * kMaxSteps; ++step) {
      const int k = step % 2 == 1 ? (step + 1) / 2 : -(step / 2);
      const glm::vec2 shift(across * width, static_cast<float>(k) * height);
      spots.push_back({shift, std::hypot(shift.x, shift.y)});
    }
  std::stable_sort(spots.begin(), spots.end(), [](const Spot& a, const Spot& b) { return a.distance < b.distance; });
  const auto within_bounds = [&](const LabelBox& b) {
    return b.min.x >= bounds_.min.x && b.max.x <= bounds_.max.x && b.min.y >= bounds_.min.y && b.max.y <= bounds_.max.y;
  };
  const auto first_clear = [&](bool avoid_obstacles, const LabelBox& fallback) {
    for (const Spot& spot : spots) {
      if (!avoid_obstacles && spot.shift.x != 0.0f) continue;
      const LabelBox candidate{wanted.min + spot.shift, wanted.max + spot.shift};
      // Only up or down past a horizontal edge of the bounds (a label wider than them stays so).
      const bool inside = spot.shift.x == 0.0f ? candidate.min.y >= bounds_.min.y && candidate.max.y <= bounds_.max.y
                                               : within_bounds(candidate);
      if (inside && clear_of(candidate, placed_) && (!avoid_obstacles || clear_of(candidate, obstacles_))) return candidate;
    }
    return fallback;
  };
  // (Without anything to avoid, both searches are the same.)
  const LabelBox chosen = first_clear(true, first_clear(false, wanted));
  placed_.push_back(chosen);
  return chosen;
}

}  // namespace vascsim::render

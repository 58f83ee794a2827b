#include "render/label_placer.h"

namespace vascsim::render {

LabelBox LabelPlacer::place(const LabelBox& asked) {
  LabelBox wanted = asked;
  const float past_right = wanted.max.x - bounds_.max.x, before_left = bounds_.min.x - wanted.min.x;
  const float dx = past_right > 0 ? -past_right : before_left > 0 ? before_left : 0.0f;
  wanted.min.x += dx;
  wanted.max.x += dx;
  const float height = wanted.max.y - wanted.min.y;
  LabelBox chosen = wanted;
  for (int step = 0; step <= 2 * kMaxSteps; ++step) {
    // 0, +1, -1, +2, -2, ... label heights (y down: + is below).
    const int k = step % 2 == 1 ? (step + 1) / 2 : -(step / 2);
    const glm::vec2 shift(0.0f, static_cast<float>(k) * height);
    const LabelBox candidate{wanted.min + shift, wanted.max + shift};
    if (candidate.min.y < bounds_.min.y || candidate.max.y > bounds_.max.y) continue;
    bool clear = true;
    for (const LabelBox& other : placed_) clear = clear && !candidate.overlaps(other);
    if (clear) {
      chosen = candidate;
      break;
    }
  }
  placed_.push_back(chosen);
  return chosen;
}

}  // namespace vascsim::render

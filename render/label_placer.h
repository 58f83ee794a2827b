// Places the text labels of a figure so none is drawn over another: each label is tried where
// its caller wants it, then moved up or down by whole label heights until it clears the labels
// placed before it. The snapshot plot labels each rod snapshot ahead of its tip; a rod that
// hardly moved (a stuck or failed run) put six labels on one spot, unreadable.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace vascsim::render {

struct LabelBox {
  glm::vec2 min, max;  // px, y down
  bool overlaps(const LabelBox& other) const {
    return min.x < other.max.x && other.min.x < max.x && min.y < other.max.y && other.min.y < max.y;
  }
};

class LabelPlacer {
 public:
  // Labels stay within `bounds` (px; a figure's axes, outside which they would be clipped)
  // where they can.
  explicit LabelPlacer(const LabelBox& bounds) : bounds_(bounds) {}
  // `wanted`, moved sideways into the bounds, then by the fewest label heights (below first,
  // then above) that clear every label placed so far and stay within the bounds; without such a
  // spot within kMaxSteps heights, where it was wanted (over another label, rather than lost).
  // The result counts as placed.
  LabelBox place(const LabelBox& wanted);
  static constexpr int kMaxSteps = 8;

 private:
  LabelBox bounds_;
  std::vector<LabelBox> placed_;
};

}  // namespace vascsim::render

// Places the text labels of a figure so none is drawn over another, nor over what the figure
// asks it to avoid: each label is tried where its caller wants it, then moved by whole label
// heights (and sideways) until it clears them. The snapshot plot labels each rod snapshot ahead
// of its tip; a rod that hardly moved (a stuck or failed run) put six labels on one spot,
// unreadable, and a label ahead of one snapshot's tip could hide another snapshot's rod.
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
  // Something drawn that a label should not hide where it can be placed elsewhere (a segment of
  // a rod, as its bounding box).
  void avoid(const LabelBox& drawn) { obstacles_.push_back(drawn); }
  // `wanted`, moved sideways into the bounds, then to the nearest spot within the bounds that
  // clears every label placed so far and everything to avoid: by whole label heights up or down
  // (below first), and where something to avoid is in the way, also by half or whole label widths
  // sideways. Without such a spot, the nearest that clears the labels alone (up or down, as
  // without anything to avoid); without that within kMaxSteps heights, where it was wanted (over
  // another label, rather than lost). The result counts as placed.
  LabelBox place(const LabelBox& wanted);
  static constexpr int kMaxSteps = 8;

 private:
  LabelBox bounds_;
  std::vector<LabelBox> placed_, obstacles_;
};

}  // namespace vascsim::render

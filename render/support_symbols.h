// The engineering symbols of how a rod is held (the `supports` layer, docs/rendering.md): a wall
// hatched on its far side across a clamped root; a triangle on hatched ground under a pinned
// node; the same triangle on rollers under a node held in one axis only; a ring round a node
// that the scene moves. The frame painter draws them on the map at the held nodes and, smaller,
// in the legend, so both are one drawing.
#pragma once

#include <glm/vec2.hpp>

#include "render/canvas.h"

namespace vascsim::render {

// A kind of support, as the legend lists them.
enum class SupportKind { kClamp, kPin, kHeldInY, kHeldInX, kMoved };
// Its legend text: "clamped root", "pinned node", "held in y, slides in x", ...
const char* support_label(SupportKind kind);

// Size and colours of a symbol, in pixels: `size` is the unit its parts are measured in (a pin's
// triangle is 1.4 units high), `line` the stroke.
struct SupportPen {
  float size = 0;  // px
  float line = 0;  // px
  Rgba ink;
  Rgba node_fill;  // inside the node's disc at a pin's or roller's apex
};

// The wall stands across the rod at `root`, the rod leaving it along `along` (unit, screen);
// hatched on the side away from the rod.
void draw_clamp(Canvas& c, glm::vec2 root, glm::vec2 along, const SupportPen& pen);
// A triangle with its apex at the node and its base towards `down` (unit, screen): the ground it
// stands on, on rollers for a node that may slide along that ground.
void draw_stand(Canvas& c, glm::vec2 node, glm::vec2 down, bool rollers, const SupportPen& pen);
// A ring round a node whose motion the scene prescribes.
void draw_moved_ring(Canvas& c, glm::vec2 node, const SupportPen& pen);

// How far a standing symbol reaches along `down`, px: from the top of the node's disc to the end
// of the hatching (a legend row fits it).
float stand_depth(bool rollers, const SupportPen& pen);

}  // namespace vascsim::render

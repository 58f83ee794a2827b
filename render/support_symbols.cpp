#include "render/support_symbols.h"

#include <glm/geometric.hpp>

namespace vascsim::render {

namespace {

constexpr float kStandHeight = 1.4f;  // apex to base, in sizes
constexpr float kRollerRadius = 0.25f;
constexpr float kHatchLength = 0.7f;
constexpr float kNodeRadius = 0.3f;

// A ground line across `along` through `centre`, with short strokes slanting away towards `away`.
void hatched_line(Canvas& c, glm::vec2 centre, glm::vec2 along, float half, glm::vec2 away, const SupportPen& pen) {
  c.capsule(centre - half * along, centre + half * along, 0.5f * pen.line, pen.ink);
  for (int k = 0; k <= 4; ++k) {
    const glm::vec2 a = centre + (-half + 0.5f * half * static_cast<float>(k)) * along;
    c.capsule(a, a + kHatchLength * pen.size * (away - along), 0.3f * pen.line, pen.ink);
  }
}

float roller_depth(const SupportPen& pen) { return 2 * kRollerRadius * pen.size + pen.line; }

}  // namespace

const char* support_label(SupportKind kind) {
  switch (kind) {
    case SupportKind::kClamp: return "clamped root";
    case SupportKind::kPin: return "pinned node";
    case SupportKind::kHeldInY: return "held in y, slides in x";
    case SupportKind::kHeldInX: return "held in x, slides in y";
    case SupportKind::kMoved: return "prescribed motion";
  }
  return "";
}

void draw_clamp(Canvas& c, glm::vec2 root, glm::vec2 along, const SupportPen& pen) {
  const glm::vec2 across(-along.y, along.x);
  const float half = 1.6f * pen.size;
  hatched_line(c, root, across, half, -along, pen);
  c.capsule(root - half * across, root + half * across, 1.3f * pen.line, pen.ink);
}

void draw_stand(Canvas& c, glm::vec2 node, glm::vec2 down, bool rollers, const SupportPen& pen) {
  const float u = pen.size;
  const glm::vec2 side(-down.y, down.x);
  const glm::vec2 base = node + kStandHeight * u * down;
  c.triangle(node, base + 0.8f * u * side, base - 0.8f * u * side, pen.ink);
  glm::vec2 ground = base + 0.5f * pen.line * down;
  if (rollers) {
    const float r = kRollerRadius * u;
    for (float s : {-0.45f, 0.45f}) c.disc(base + s * u * side + r * down, r, pen.ink);
    ground = base + roller_depth(pen) * down;
  }
  hatched_line(c, ground, side, 1.1f * u, down, pen);
  c.disc(node, kNodeRadius * u, pen.ink);
  c.disc(node, kNodeRadius * u - pen.line, pen.node_fill);
}

void draw_moved_ring(Canvas& c, glm::vec2 node, const SupportPen& pen) { c.ring(node, 0.8f * pen.size, pen.line, pen.ink); }

float stand_depth(bool rollers, const SupportPen& pen) {
  const float ground = kStandHeight * pen.size + (rollers ? roller_depth(pen) : 0.5f * pen.line);
  return kNodeRadius * pen.size + ground + kHatchLength * pen.size;
}

}  // namespace vascsim::render

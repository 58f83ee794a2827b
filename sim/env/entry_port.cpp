#include "sim/env/entry_port.h"

#include <cmath>

namespace vascsim {

namespace {

// 2D cross product z-component.
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

Inlet open_entry(const Environment& env, const Polyline& centreline, double reach, Environment& opened) {
  Inlet port;
  port.tip = centreline.front();
  if (centreline.size() >= 2 && (centreline[1] - centreline[0]).norm() > 0)
    port.inward = (centreline[1] - centreline[0]).normalized();
  port.opening = env.lumen_width;
  opened = env;
  opened.walls.clear();
  const Vec2 back = -port.inward;
  for (const WallSegment& w : env.walls) {
    // Where does the ray tip + s back (0 <= s <= reach) cross the wall's centre segment?
    const Vec2 e = w.b - w.a;
    const double denom = cross(back, e);
    const double length = e.norm();
    bool crossed = false;
    double u = 0.0;  // along the wall, 0..1
    if (std::abs(denom) > 1e-12 * length) {
      const Vec2 d = w.a - port.tip;
      const double s = cross(d, e) / denom;
      u = cross(d, back) / denom;
      crossed = s >= 0.0 && s <= reach && u >= 0.0 && u <= 1.0;
    }
    if (!crossed || length == 0.0) {
      opened.walls.push_back(w);
      continue;
    }
    // Cut half the lumen plus the wall's cap radius on each side, so the round caps of the two
    // remaining pieces end flush with the channel's sides. The cut is measured along the wall,
    // so a wall crossed obliquely gets a wider hole: the channel width across stays the lumen.
    const double sine = std::abs(denom) / length;
    const double half_cut = (0.5 * env.lumen_width + 0.5 * w.thickness) / sine / length;
    if (u - half_cut > 0.0) opened.walls.push_back({w.a, w.a + (u - half_cut) * e, w.thickness});
    if (u + half_cut < 1.0) opened.walls.push_back({w.a + (u + half_cut) * e, w.b, w.thickness});
  }
  return port;
}

}  // namespace vascsim

// The entry port: where the catheter comes into the network. A maze is closed by its outer wall,
// so a run opens that wall where the rod enters, straight behind the start point along the first
// leg of the path, as an introducer sheath would. The rod then starts outside the maze, straight,
// with its tip at the start point, and is drawn in by the tip force (docs/navigation.md).
#pragma once

#include "sim/env/environment.h"

namespace vascsim {

struct EntryPort {
  Vec2 tip = Vec2::Zero();          // m, where the rod's tip starts (the path's start)
  Vec2 inward = Vec2::UnitX();      // unit, direction of the first path leg (into the maze)
  double opening = 0.0;             // m, width of the hole cut in the wall(s)
};

// Cuts an opening of the lumen width through every wall crossed by the ray from the start point
// backwards along the first leg of `centreline`, up to `reach` metres (the rod's length).
// Returns where the rod enters. Pure: `env` is copied, the result holds the opened walls.
EntryPort open_entry(const Environment& env, const Polyline& centreline, double reach, Environment& opened);

}  // namespace vascsim

// The entry port: where the catheter comes into the network. A maze is closed by its outer wall,
// so a run opens that wall where the rod enters, straight behind the start point along the first
// leg of the path, as an introducer sheath would. The rod then starts outside the maze, straight,
// with its tip at the start point, and is drawn in by the tip force (docs/navigation.md).
#pragma once

#include "sim/env/environment.h"

namespace vascsim {

// Cuts an opening of the lumen width through every wall crossed by the ray from the start point
// backwards along the first leg of `centreline`, up to `reach` metres (the rod's length).
// Returns where the rod enters. Pure: `env` is copied, the result holds the opened walls.
Inlet open_entry(const Environment& env, const Polyline& centreline, double reach, Environment& opened);

}  // namespace vascsim

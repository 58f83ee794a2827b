// Plain 2D geometry shared by the environment, the rod and the frame log metadata: points and
// wall segments in metres, in the maze plane (x to the right, y up, origin at the bottom-left).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace vascsim {

using Vec2 = Eigen::Vector2d;

// A straight wall: the set of points within thickness/2 of the segment a-b (a capsule).
// thickness 0 gives an ideal line wall, as the paper's figures draw the maze.
struct WallSegment {
  Vec2 a = Vec2::Zero();  // m
  Vec2 b = Vec2::Zero();  // m
  double thickness = 0.0; // m
};

// An axis-aligned rectangle, e.g. the bounds of an environment.
struct Box2 {
  Vec2 min = Vec2::Zero();  // m
  Vec2 max = Vec2::Zero();  // m
};

using Polyline = std::vector<Vec2>;

}  // namespace vascsim

// The world the robot moves in, as plain geometry every consumer shares whatever made it (a
// generated maze, explicit walls, a vessel graph, an image mask): wall segments with a thickness
// (capsules, geometry.h) for contact, friction and gap statistics; the lumen outline for drawing
// and inside tests; the start, the goal and the lumen radius there for the goal test; the inlet
// where the rod enters; the reference centreline with the local lumen radius along it. Contact
// queries on the walls are in wall_distance.h. Conventions: docs/environment.md.
#pragma once

#include <optional>
#include <vector>

#include "sim/env/geometry.h"
#include "sim/env/grid_maze.h"
#include "sim/scene/scene.h"

namespace vascsim {

// Where the rod enters the network: it starts straight behind `tip`, heading along `inward`.
struct Inlet {
  Vec2 tip = Vec2::Zero();      // m, where the rod's tip starts (the path's start)
  Vec2 inward = Vec2::UnitX();  // unit, direction of the first path leg (into the network)
  double opening = 0.0;         // m, width of the way in (a maze's port, a vessel's diameter)
};

struct Environment {
  Box2 bounds;                     // m, the maze rectangle 0..width x 0..height (the centre lines of the
                                   // outer walls; thick outer walls reach thickness/2 beyond it)
  std::vector<WallSegment> walls;  // m, includes the outer boundary
  Vec2 start = Vec2::Zero();       // m
  Vec2 goal = Vec2::Zero();        // m
  double lumen_width = 0.0;        // m, nominal channel width (a maze's; a vessel network's narrowest
                                   // diameter along the route)
  // Closed rings (the last point joins the first) whose even-odd interior is the lumen. A maze
  // gives its bounds rectangle: its walls, drawn over it, cut out the channels.
  std::vector<Polyline> lumen;
  Inlet inlet;
  Polyline centreline;                 // m, the sharp reference centreline, start to goal
  std::vector<double> centreline_radius;  // m, lumen radius at each centreline point
  // m, per centreline point: the largest corner rounding the lumen allows there; empty: the
  // scene's path.corner_radius everywhere (mazes). Where the centreline does not turn (a straight
  // point) any radius fits: kStraightCornerRadius; at the two ends there is no corner: 0.
  std::vector<double> corner_radius;
  static constexpr double kStraightCornerRadius = 1e6;
  double goal_radius = 0.0;            // m, lumen radius at the goal (the goal test's scale)
  std::optional<GridMaze> grid;    // generated mazes only
};

// Generated maze (spec.explicit_walls false): the walls of generate_maze(spec). A wall lies on every
// closed cell side and on the outer boundary, centred on the grid line, with thickness = cell pitch -
// lumen_width (pitch 0.2 m, lumen 0.1 m: 0.1 m thick walls; lumen == pitch: zero-thickness line walls,
// as the paper's figures draw them), so every channel is exactly lumen_width wide. Collinear adjacent
// pieces are merged into one segment: fewer walls and no seams at the joints. Start and goal are the
// centres of the start (top-right) and goal (bottom-left) cells.
// Explicit walls: spec.walls, spec.start and spec.goal as given; lumen_width is the nominal
// grid_pitch - (thickest wall), assuming the walls lie on the grid lines as in the paper's Fig. 10.
// Throws InputError if lumen_width does not fit in a cell.
Environment build_environment(const MazeSpec& spec);

}  // namespace vascsim

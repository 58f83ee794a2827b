#include "sim/env/maze_solvers.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/env/wall_distance.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

constexpr int kSides[4] = {kNorth, kEast, kSouth, kWest};  // clockwise: index + 1 turns right
constexpr long long kMaxCells = 1000000;

std::size_t at(const GridMaze& m, Cell c) { return static_cast<std::size_t>(m.index(c)); }

// Distance between segments p0-p1 and q0-q1: zero if they cross, else the least of the four
// endpoint-to-segment distances.
double segment_distance(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const auto cross = [](const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
  const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.0;
  const auto point_segment = [](const Vec2& p, const Vec2& a, const Vec2& b) {
    return wall_hit(WallSegment{a, b, 0.0}, 0, p).distance;
  };
  return std::min({point_segment(p0, q0, q1), point_segment(p1, q0, q1), point_segment(q0, p0, p1),
                   point_segment(q1, p0, p1)});
}

}  // namespace

// Right-hand rule: at each cell try right, straight, left, back relative to the heading. The state
// (cell, heading) determines the next move, so after 4 * cells moves without the goal the walk is in a
// cycle. The route is kept loop-erased: stepping onto a cell already on it cuts the route back to that
// cell, which removes dead ends as the walk backs out of them.
std::vector<Cell> solve_wall_follower(const GridMaze& maze) {
  std::vector<Cell> route{maze.start};
  std::vector<int> position(maze.open.size(), -1);  // index in route, -1 if not on it
  position[at(maze, maze.start)] = 0;
  // Start facing north: the right hand then rests on the outer east wall of the top-right start cell.
  int heading = 0;
  Cell c = maze.start;
  const long long max_moves = 4LL * static_cast<long long>(maze.open.size()) + 4;
  for (long long move = 0; c != maze.goal; ++move) {
    if (move >= max_moves) return {};
    int turn = -1;  // quarter turns: right +1, straight 0, left +3, back +2
    for (const int t : {1, 0, 3, 2})
      if (maze.is_open(c, kSides[(heading + t) % 4]) && maze.contains(neighbour(c, kSides[(heading + t) % 4]))) {
        turn = t;
        break;
      }
    if (turn < 0) return {};  // a closed cell: nowhere to go
    heading = (heading + turn) % 4;
    c = neighbour(c, kSides[heading]);
    const int seen = position[at(maze, c)];
    if (seen >= 0) {
      for (std::size_t k = static_cast<std::size_t>(seen) + 1; k < route.size(); ++k) position[at(maze, route[k])] = -1;
      route.resize(static_cast<std::size_t>(seen) + 1);
    } else {
      position[at(maze, c)] = static_cast<int>(route.size());
      route.push_back(c);
    }
  }
  return route;
}

std::vector<Cell> solve_breadth_first(const GridMaze& maze) {
  std::vector<int> parent(maze.open.size(), -1);  // cell index the search came from; start: itself
  std::vector<Cell> queue{maze.start};
  parent[at(maze, maze.start)] = maze.index(maze.start);
  for (std::size_t head = 0; head < queue.size() && queue[head] != maze.goal; ++head) {
    const Cell c = queue[head];
    for (const int side : kSides) {
      const Cell d = neighbour(c, side);
      if (!maze.is_open(c, side)) continue;
      if (!maze.contains(d) || parent[at(maze, d)] >= 0) continue;
      parent[at(maze, d)] = maze.index(c);
      queue.push_back(d);
    }
  }
  if (parent[at(maze, maze.goal)] < 0) return {};
  std::vector<Cell> route{maze.goal};
  while (route.back() != maze.start) {
    const int p = parent[at(maze, route.back())];
    route.push_back({p / maze.cols, p % maze.cols});
  }
  std::reverse(route.begin(), route.end());
  return route;
}

GridMaze grid_from_walls(const MazeSpec& spec) {
  const auto count = [](double extent, double pitch) {
    return std::max(1.0, std::round(extent / pitch));
  };
  const double rows = count(spec.height, spec.grid_pitch), cols = count(spec.width, spec.grid_pitch);
  if (!(spec.grid_pitch > 0.0) || !(rows * cols <= static_cast<double>(kMaxCells))) {
    std::ostringstream msg;
    msg << "/maze/grid_pitch: expected a pitch giving at most " << kMaxCells << " path cells over "
        << spec.width << " m x " << spec.height << " m, got " << spec.grid_pitch;
    throw InputError(msg.str());
  }
  GridMaze m;
  m.rows = static_cast<int>(rows);
  m.cols = static_cast<int>(cols);
  m.width = spec.width;
  m.height = spec.height;
  // All inner sides open, then each wall closes the sides whose centre-to-centre segment it meets.
  m.open.assign(static_cast<std::size_t>(m.rows) * m.cols, 0);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c)
      for (const int side : kSides)
        if (m.contains(neighbour({r, c}, side))) m.open[at(m, {r, c})] |= static_cast<std::uint8_t>(side);

  const double px = m.pitch_x(), py = m.pitch_y();
  const double touch = 1e-9 * std::min(px, py);  // rounding margin: a line wall through a centre segment
  for (const auto& w : spec.walls) {
    const double reach = 0.5 * w.thickness + touch;
    // Only cells whose centre segments can come within reach: the wall's box grown by reach and a cell.
    const Cell c0 = m.cell_at(Vec2(std::min(w.a.x(), w.b.x()) - reach, std::max(w.a.y(), w.b.y()) + reach));
    const Cell c1 = m.cell_at(Vec2(std::max(w.a.x(), w.b.x()) + reach, std::min(w.a.y(), w.b.y()) - reach));
    for (int r = std::max(0, c0.row - 1); r <= std::min(m.rows - 1, c1.row + 1); ++r)
      for (int c = std::max(0, c0.col - 1); c <= std::min(m.cols - 1, c1.col + 1); ++c)
        for (const int side : {kEast, kSouth}) {
          const Cell d = neighbour({r, c}, side);
          if (!m.contains(d) || !m.is_open({r, c}, side)) continue;
          if (segment_distance(m.centre({r, c}), m.centre(d), w.a, w.b) > reach) continue;
          m.open[at(m, {r, c})] &= static_cast<std::uint8_t>(~side);
          m.open[at(m, d)] &= static_cast<std::uint8_t>(~opposite(side));
        }
  }
  m.start = m.cell_at(spec.start);
  m.goal = m.cell_at(spec.goal);
  // The path also runs from the start to its cell's centre and from the goal cell's centre to the
  // goal. A cell wider than the channels puts a wall across those legs: with one cell, start and
  // goal share it and the path went straight through every wall between them.
  const std::pair<Vec2, Cell> ends[] = {{spec.start, m.start}, {spec.goal, m.goal}};
  for (const auto& [point, cell] : ends)
    for (const auto& w : spec.walls)
      if (segment_distance(point, m.centre(cell), w.a, w.b) <= 0.5 * w.thickness + touch) {
        std::ostringstream msg;
        msg << "/maze/grid_pitch: expected path cells no wider than the channels, got " << spec.grid_pitch
            << " m: the wall from (" << w.a.x() << ", " << w.a.y() << ") to (" << w.b.x() << ", " << w.b.y()
            << ") lies between (" << point.x() << ", " << point.y() << ") and the centre of its " << px << " m x "
            << py << " m cell";
        throw InputError(msg.str());
      }
  if (solve_breadth_first(m).empty()) {
    std::ostringstream msg;
    msg << "/maze: expected start (" << spec.start.x() << ", " << spec.start.y() << ") and goal (" << spec.goal.x()
        << ", " << spec.goal.y() << ") to be connected, but the walls cut every route between them on the path "
        << "grid of " << px << " m x " << py << " m cells";
    throw InputError(msg.str());
  }
  return m;
}

}  // namespace vascsim

#include "sim/env/environment.h"

#include <algorithm>
#include <sstream>

#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

// Appends the walls on one family of parallel grid lines. closed(line, k) says whether the k-th unit
// piece of grid line `line` is a wall; runs of closed pieces become one segment from point(line, k0)
// to point(line, k1).
template <typename Closed, typename Point>
void add_merged_lines(int lines, int pieces, double thickness, Closed closed, Point point,
                      std::vector<WallSegment>& out) {
  for (int line = 0; line < lines; ++line) {
    int k = 0;
    while (k < pieces) {
      if (!closed(line, k)) {
        ++k;
        continue;
      }
      const int k0 = k;
      while (k < pieces && closed(line, k)) ++k;
      WallSegment w;
      w.a = point(line, k0);
      w.b = point(line, k);
      w.thickness = thickness;
      out.push_back(w);
    }
  }
}

Environment generated_environment(const MazeSpec& spec) {
  GridMaze g = generate_maze(spec);
  const double px = g.pitch_x(), py = g.pitch_y();
  const double pitch = std::min(px, py);
  // A lumen equal to the pitch up to rounding (e.g. width 2.4 m / 12 cols vs 0.2 m) means line walls:
  // snap the thickness to exactly zero rather than leave +-1e-17 m, or fail on a rounding difference.
  const double snap = 1e-9 * pitch;
  const auto thickness = [&](double p) { return p - spec.lumen_width <= snap ? 0.0 : p - spec.lumen_width; };
  if (!(spec.lumen_width > 0.0) || spec.lumen_width > pitch + snap) {
    std::ostringstream msg;
    msg << "/maze/lumen_width: expected a number in (0, " << pitch << "] (the cell pitch), got " << spec.lumen_width;
    throw InputError(msg.str());
  }
  Environment env;
  env.bounds.min = Vec2(0.0, 0.0);
  env.bounds.max = Vec2(g.width, g.height);
  env.lumen_width = spec.lumen_width;
  env.start = g.centre(g.start);
  env.goal = g.centre(g.goal);

  // Horizontal grid line i (0..rows) is the north side of row i, y = height - i * py; piece k spans
  // column k. Lines 0 and rows are the outer boundary. Thickness differs per direction only when cells
  // are not square, so that every channel is lumen_width wide.
  add_merged_lines(
      g.rows + 1, g.cols, thickness(py),
      [&](int i, int k) { return i == 0 || i == g.rows || !g.is_open({i, k}, kNorth); },
      [&](int i, int k) { return Vec2(k * px, g.height - i * py); }, env.walls);
  // Vertical grid line j (0..cols) is the west side of column j, x = j * px; piece k spans row k.
  add_merged_lines(
      g.cols + 1, g.rows, thickness(px),
      [&](int j, int k) { return j == 0 || j == g.cols || !g.is_open({k, j}, kWest); },
      [&](int j, int k) { return Vec2(j * px, g.height - k * py); }, env.walls);
  env.grid = std::move(g);
  return env;
}

Environment explicit_environment(const MazeSpec& spec) {
  Environment env;
  env.bounds.min = Vec2(0.0, 0.0);
  env.bounds.max = Vec2(spec.width, spec.height);
  env.walls = spec.walls;
  env.start = spec.start;
  env.goal = spec.goal;
  double thickest = 0.0;
  for (const auto& w : spec.walls) thickest = std::max(thickest, w.thickness);
  env.lumen_width = std::max(0.0, spec.grid_pitch - thickest);
  return env;
}

}  // namespace

Environment build_environment(const MazeSpec& spec) {
  return spec.explicit_walls ? explicit_environment(spec) : generated_environment(spec);
}

}  // namespace vascsim

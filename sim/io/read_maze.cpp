#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

namespace {

WallSegment read_wall(const json& item, const std::string& file, const std::string& pointer, double default_thickness) {
  FieldReader in(item, file, pointer);
  WallSegment w;
  if (!in.has("from")) in.fail("from", "a point [x, y]", json());
  if (!in.has("to")) in.fail("to", "a point [x, y]", json());
  w.a = in.vec2("from", w.a, kMaxCoordinate);
  w.b = in.vec2("to", w.b, kMaxCoordinate);
  w.thickness = in.number("thickness", default_thickness, 0.0, 1e3);
  if ((w.a - w.b).norm() == 0.0 && w.thickness == 0.0)
    in.fail("to", "a point different from \"from\" (a wall of zero length and thickness is invisible)", item["to"]);
  in.finish();
  return w;
}

}  // namespace

void read_maze(FieldReader& in, MazeSpec& out) {
  const bool has_walls = in.has("walls");
  // From 1 mm: a smaller maze has no room for a lumen the reader can accept (a width of 1e-308
  // left /maze/lumen_width an empty range).
  out.width = in.number("width", out.width, 1e-3, 1e3);
  out.height = in.number("height", out.height, 1e-3, 1e3);
  if (has_walls) {
    for (const char* key : {"rows", "cols", "seed", "lumen_width"})
      if (in.has(key))
        in.fail(key, "no generator settings beside an explicit \"walls\" list", *in.raw(key));
    out.explicit_walls = true;
    const double thickness = in.number("wall_thickness", 0.0, 0.0, 1e3);
    const json& walls = *in.raw("walls");
    if (!walls.is_array() || walls.empty()) in.fail("walls", "a non-empty array of {\"from\", \"to\"} segments", walls);
    out.walls.clear();
    for (std::size_t i = 0; i < walls.size(); ++i)
      out.walls.push_back(read_wall(walls[i], in.file(), in.pointer_of("walls") + "/" + std::to_string(i), thickness));
    out.start = in.vec2("start", out.start, kMaxCoordinate);
    out.goal = in.vec2("goal", out.goal, kMaxCoordinate);
    out.grid_pitch = in.positive("grid_pitch", out.grid_pitch, 1e3);
    const auto inside = [&](const Vec2& p) {
      return p.x() > 0 && p.y() > 0 && p.x() < out.width && p.y() < out.height;
    };
    if (!inside(out.start)) in.fail("start", "a point inside the maze bounds", to_json(out.start));
    if (!inside(out.goal)) in.fail("goal", "a point inside the maze bounds", to_json(out.goal));
  } else {
    out.rows = static_cast<int>(in.integer("rows", out.rows, 1, 200));
    out.cols = static_cast<int>(in.integer("cols", out.cols, 1, 200));
    // The start and the goal are opposite corner cells: one cell holds both, and a run "reached
    // its goal" at its first step (vessel scenes refuse a start that is the goal).
    if (out.rows * out.cols < 2)
      in.fail(in.has("cols") ? "cols" : "rows", "a maze of at least 2 cells (its start and goal are different cells)",
              *in.raw(in.has("cols") ? "cols" : "rows"));
    out.seed = static_cast<std::uint64_t>(in.integer("seed", static_cast<long long>(out.seed), 0, 9007199254740991LL));
    const double pitch = std::min(out.width / out.cols, out.height / out.rows);
    out.lumen_width = in.number("lumen_width", std::min(out.lumen_width, pitch), 1e-6, pitch);
  }
  in.finish();
}

json write_maze(const MazeSpec& spec) {
  json j;
  j["width"] = spec.width;
  j["height"] = spec.height;
  if (spec.explicit_walls) {
    json walls = json::array();
    for (const auto& w : spec.walls)
      walls.push_back({{"from", to_json(w.a)}, {"to", to_json(w.b)}, {"thickness", w.thickness}});
    j["walls"] = walls;
    j["start"] = to_json(spec.start);
    j["goal"] = to_json(spec.goal);
    j["grid_pitch"] = spec.grid_pitch;
  } else {
    j["rows"] = spec.rows;
    j["cols"] = spec.cols;
    j["seed"] = spec.seed;
    j["lumen_width"] = spec.lumen_width;
  }
  return j;
}

}  // namespace vascsim::io

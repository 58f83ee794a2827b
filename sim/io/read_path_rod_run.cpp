#include <cmath>

#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

void read_path(FieldReader& in, PathSpec& out) {
  const std::string solver = in.choice("solver", out.solver == PathSolver::kWallFollower ? "wall_follower" : "bfs",
                                       {"wall_follower", "bfs"});
  out.solver = solver == "bfs" ? PathSolver::kBreadthFirst : PathSolver::kWallFollower;
  out.corner_radius = in.number("corner_radius", out.corner_radius, 0.0, 1e3);
  // From 1 nm/s: slower, a route's duration overflows (1e-308 m/s made it infinite).
  out.speed = in.number("speed", out.speed, 1e-9, 1e3);
  out.ramp_time = in.number("ramp_time", out.ramp_time, 0.0, 1e6);
  in.finish();
}

json write_path(const PathSpec& spec) {
  json j = {{"solver", spec.solver == PathSolver::kBreadthFirst ? "bfs" : "wall_follower"},
            {"speed", spec.speed},
            {"ramp_time", spec.ramp_time}};
  if (std::isfinite(spec.corner_radius)) j["corner_radius"] = spec.corner_radius;  // infinite: a vessel scene's "no cap"
  return j;
}

void read_rod(FieldReader& in, RodSpec& out) {
  out.nodes = static_cast<int>(in.integer("nodes", out.nodes, 3, 1000000));
  // From 1 um and 0.1 um: below, an edge's length or cross-section underflows the solver's scale
  // (a length of 1e-308 failed at the first step as "the rod blew up").
  out.length = in.number("length", out.length, 1e-6, 1e3);
  out.outer_radius = in.number("outer_radius", out.outer_radius, 1e-7, 1.0);
  out.inner_radius = in.number("inner_radius", std::min(out.inner_radius, 0.5 * out.outer_radius), 0.0, 1.0);
  if (out.inner_radius >= out.outer_radius)
    in.fail("inner_radius", "a number in [0, outer_radius = " + format_number(out.outer_radius) + ")",
            json(out.inner_radius));
  out.youngs_modulus = in.positive("youngs_modulus", out.youngs_modulus, 1e13);
  out.poisson_ratio = in.number("poisson_ratio", out.poisson_ratio, -1.0, 0.5);
  out.density = in.positive("density", out.density, 1e5);
  in.finish();
}

json write_rod(const RodSpec& spec) {
  return {{"nodes", spec.nodes},
          {"length", spec.length},
          {"outer_radius", spec.outer_radius},
          {"inner_radius", spec.inner_radius},
          {"youngs_modulus", spec.youngs_modulus},
          {"poisson_ratio", spec.poisson_ratio},
          {"density", spec.density}};
}

void read_run(FieldReader& in, RunSpec& out) {
  out.duration = in.positive("duration", out.duration, 1e7);
  // At least 1e-6 s: a finer interval logs faster than any step a scene can take usefully and
  // fills a disk within seconds (docs/scenes.md).
  out.output_interval = in.number("output_interval", out.output_interval, RunSpec::kMinOutputInterval, 1e7);
  in.finish();
}

json write_run(const RunSpec& spec) {
  return {{"duration", spec.duration}, {"output_interval", spec.output_interval}};
}

}  // namespace vascsim::io

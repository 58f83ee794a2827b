#include "sim/io/vessels_json.h"

#include <nlohmann/json.hpp>

#include "sim/env/vessel_graph.h"
#include "sim/io/scene_reader.h"
#include "sim/io/scene_sections.h"
#include "sim/run/compile.h"
#include "sim/run/navigation.h"

namespace vascsim {

using nlohmann::json;

namespace {

// Nodes, segments sampled with their radius, and the sacs; the route as node names.
json graph_json(const VesselsSpec& spec) {
  const VesselGraph g = resolve_vessel_graph(spec);
  json nodes = json::object();
  for (std::size_t i = 0; i < g.names.size(); ++i) nodes[g.names[i]] = io::to_json(g.positions[i]);
  json segments = json::array();
  for (const auto& s : g.segments) {
    json samples = json::array();
    for (const auto& v : s.samples) samples.push_back({v.point.x(), v.point.y(), v.radius});
    segments.push_back({{"from", g.names[static_cast<std::size_t>(s.from)]},
                        {"to", g.names[static_cast<std::size_t>(s.to)]},
                        {"length", s.length},
                        {"samples", samples}});
  }
  json sacs = json::array();
  for (const auto& s : g.sacs) sacs.push_back({{"centre", io::to_json(s.centre)}, {"radius", s.radius}, {"segment", s.segment}});
  json route = json::array({spec.start});
  for (const RouteStep& step : vessel_route(g, spec)) {
    const auto& s = g.segments[static_cast<std::size_t>(step.segment)];
    route.push_back(g.names[static_cast<std::size_t>(step.forward ? s.to : s.from)]);
  }
  return {{"nodes", nodes}, {"segments", segments}, {"sacs", sacs}, {"route", route},
          {"sample_format", "[x, y, radius] in m"}};
}

}  // namespace

std::string vessels_document(const Scene& scene) {
  const auto model = compile(scene);
  const Navigation& nav = *model->navigation;
  const Environment& env = nav.environment;
  const Trajectory& trajectory = *nav.trajectory;

  json walls = json::array();
  for (const auto& w : env.walls) walls.push_back({{"from", io::to_json(w.a)}, {"to", io::to_json(w.b)}, {"thickness", w.thickness}});
  json lumen = json::array();
  for (const auto& ring : env.lumen) lumen.push_back(io::to_json(ring));
  json doc;
  doc["format"] = "vascsim-vessels/1";
  Scene as_run = scene;  // with the duration a run of it would use
  as_run.run.duration = model->scene.run.duration;
  doc["scene"] = json::parse(scene_to_json(as_run));
  doc["bounds"] = {io::to_json(env.bounds.min), io::to_json(env.bounds.max)};
  doc["start"] = io::to_json(env.start);
  doc["goal"] = io::to_json(env.goal);
  doc["inlet"] = {{"tip", io::to_json(env.inlet.tip)}, {"inward", io::to_json(env.inlet.inward)}, {"opening", env.inlet.opening}};
  doc["lumen"] = lumen;
  doc["walls"] = walls;
  if (scene.vessels.from_mask)
    doc["mask"] = {{"file", scene.vessels.mask.file}, {"width", scene.vessels.mask.width},
                   {"height", scene.vessels.mask.height}, {"pixel_size", scene.vessels.mask.pixel_size}};
  else
    doc["graph"] = graph_json(scene.vessels);
  // null where the centreline has no corner to round: its ends and points where it runs straight
  // (their internal radius, kStraightCornerRadius, is a placeholder, not a length to read).
  json corners = json::array();
  for (std::size_t i = 0; i < env.corner_radius.size(); ++i) {
    const bool corner = i > 0 && i + 1 < env.corner_radius.size() && env.corner_radius[i] < Environment::kStraightCornerRadius;
    corners.push_back(corner ? json(env.corner_radius[i]) : json(nullptr));
  }
  doc["path"] = io::route_timing_json(scene.path, trajectory);
  doc["path"].update({{"centreline", io::to_json(env.centreline)},
                      {"radius", env.centreline_radius},
                      {"corner_radius", corners},
                      {"narrowest_diameter", env.lumen_width}});
  return doc.dump(1) + "\n";
}

}  // namespace vascsim

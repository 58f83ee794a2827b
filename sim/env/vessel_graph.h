// A vessel network's centreline graph, resolved from the scene's `vessels` section: named nodes,
// segments sampled along their centrelines with the lumen radius at every sample (linear taper
// between the given radii, times each stenosis's raised-cosine narrowing), the aneurysm sacs placed
// beside their segments, and the route from the start node to the goal node (the shortest by arc
// length, or the scene's explicit list of nodes). Pure geometry: the lumen polygon is
// vessel_lumen.h's job, the environment vessel_environment.h's.
#pragma once

#include <string>
#include <vector>

#include "sim/env/geometry.h"
#include "sim/scene/scene.h"

namespace vascsim {

struct VesselSample {
  Vec2 point = Vec2::Zero();  // m
  double s = 0.0;             // m, arc length from the segment's first node
  double radius = 0.0;        // m, lumen radius there
};

struct ResolvedSegment {
  int from = -1, to = -1;             // node indices
  std::vector<VesselSample> samples;  // first at `from`, last at `to`; dense inside stenoses
  double length = 0.0;                // m, centreline arc length
};

struct Sac {
  Vec2 centre = Vec2::Zero();  // m
  double radius = 0.0;         // m
  int segment = -1;
};

struct VesselGraph {
  std::vector<std::string> names;
  std::vector<Vec2> positions;  // m, per node
  std::vector<ResolvedSegment> segments;
  std::vector<Sac> sacs;
  int start = -1, goal = -1;    // node indices
};

// One step of a route: a segment and the direction it is walked in.
struct RouteStep {
  int segment = -1;
  bool forward = true;  // from -> to
};

// Validates and resolves `spec` (graph form). Throws InputError whose message starts with the JSON
// path of the offending value: unknown or repeated node names, a radius list of the wrong length or
// not positive, a stenosis or sac beyond its segment, a sac whose neck is wider than it, a start
// node that ends more than one segment.
VesselGraph resolve_vessel_graph(const VesselsSpec& spec);

// The route start -> goal: spec.route if given (consecutive names joined by a segment, else an
// InputError naming /vessels/route/i), else the shortest path by arc length (Dijkstra; ties go to
// the lower segment index, so the route is deterministic). InputError if none exists.
std::vector<RouteStep> vessel_route(const VesselGraph& graph, const VesselsSpec& spec);

// The route's centreline samples joined end to end, start to goal (the shared node once).
std::vector<VesselSample> route_samples(const VesselGraph& graph, const std::vector<RouteStep>& route);

// The factor (0..1] by which the stenoses narrow a tube at arc length s (m): for each stenosis
// within length/2 of s, 1 - (1 - fraction) (1 + cos(2 pi (s - at) / length)) / 2 (a raised
// cosine: smooth, `fraction` at `at`, 1 at both ends); overlapping ones multiply.
double stenosis_factor(const std::vector<StenosisSpec>& stenoses, double s);

}  // namespace vascsim

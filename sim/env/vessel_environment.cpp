#include "sim/env/vessel_environment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "sim/env/vessel_graph.h"
#include "sim/env/vessel_lumen.h"
#include "sim/env/vessel_mask.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

// Facets of the lumen's round parts deviate from the true circle by at most this fraction of the
// smallest radius (0.05 mm for a 0.05 m vessel): a wall error well under the rod's own radius.
constexpr double kRelativeChordError = 1e-3;
// ... but never below 1 um (ten steps of the lumen's 0.1 um grid): a vessel of 1e-8 m anywhere in
// the network made every tube a polygon of millions of vertices (minutes, gigabytes) before the
// route's own width check could refuse it.
constexpr double kMinChordError = 1e-6;  // m
// Concave corners (a carina, a bend's inner side) are rounded to this fraction of the smallest
// radius: the ridge between two daughters is blunt in real vessels, and a sharp one would make the
// contact normal jump as the rod slides over it.
constexpr double kRelativeRounding = 0.25;
// The reference keeps at least this fraction of the local radius between its rounded corners and
// the inner wall of a bend.
constexpr double kCornerClearance = 0.5;

// The largest corner radius at each centreline point: rounding a corner that turns by theta with
// radius R moves the path R (sec(theta/2) - 1) towards the bend's inner corner, which lies
// r sec(theta/2) from the centreline's corner for a tube of radius r. Keeping kCornerClearance r
// between them gives R <= r (sec - kCornerClearance) / (sec - 1). r is the narrowest radius on
// the two legs (their ends, as radii taper linearly between samples): the rounded path runs along
// both, and sizing it by the corner's own radius took it through the wall of a narrower branch
// leaving a wide parent (37 of 421 path points outside a 10 mm branch off a 50 mm vessel). Then
// the arc keeps within r (1 - kCornerClearance cos(theta/2)) of either leg.
std::vector<double> corner_allowance(const Polyline& line, const std::vector<double>& radius) {
  std::vector<double> out(line.size(), 0.0);
  for (std::size_t i = 1; i + 1 < line.size(); ++i) {
    const Vec2 u = (line[i] - line[i - 1]).normalized(), w = (line[i + 1] - line[i]).normalized();
    const double cos_half = std::sqrt(std::max(0.0, 0.5 * (1.0 + u.dot(w))));
    if (cos_half <= 1e-6) continue;  // a reversal stays sharp
    const double sec = 1.0 / cos_half;
    const double narrowest = std::min({radius[i - 1], radius[i], radius[i + 1]});
    constexpr double straight = Environment::kStraightCornerRadius;
    out[i] = sec - 1.0 <= 1e-12 ? straight : std::min(straight, narrowest * (sec - kCornerClearance) / (sec - 1.0));
  }
  return out;
}

// The introducer behind the start: a straight tube of the inlet's radius as long as the rod plus a
// margin, so the rod starts inside the lumen and enters the network at the start node.
Polyline introducer(const Inlet& inlet, double radius, double rod_length, double chord_error) {
  const Vec2 back = inlet.tip - (rod_length + 2.0 * radius) * inlet.inward;
  return tapered_tube_ring(back, radius, inlet.tip, radius, chord_error);
}

// Where segments p0-p1 and q0-q1 cross (proper or touching), if they do.
bool segments_cross(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1, Vec2& at) {
  const Vec2 d = p1 - p0, e = q1 - q0, w = q0 - p0;
  const double denom = d.x() * e.y() - d.y() * e.x();
  if (denom == 0.0) return false;  // parallel: a wall along the axis is not a vessel across it
  const double t = (w.x() * e.y() - w.y() * e.x()) / denom, u = (w.x() * d.y() - w.y() * d.x()) / denom;
  if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) return false;
  at = p0 + t * d;
  return true;
}

// The introducer must leave the network through nothing but the inlet: across another vessel,
// the union would join that vessel to the inlet (a way round the route) and the rod would start
// drawn through its walls. Its axis is checked from its far end to three inlet radii behind the
// start, clear of the inlet vessel's own round end.
void refuse_an_introducer_across_the_lumen(const Inlet& inlet, double radius, double rod_length,
                                           const std::vector<Polyline>& pieces) {
  const Vec2 far = inlet.tip - (rod_length + 2.0 * radius) * inlet.inward;
  const Vec2 near = inlet.tip - 3.0 * radius * inlet.inward;
  if ((near - inlet.tip).dot(far - near) <= 0.0) return;  // a rod shorter than that: nothing to check
  for (const Polyline& ring : pieces)
    for (std::size_t k = 0; k < ring.size(); ++k) {
      Vec2 at;
      if (!segments_cross(far, near, ring[k], ring[(k + 1) % ring.size()], at)) continue;
      char text[400];
      std::snprintf(text, sizeof text,
                    "the rod's way in (straight back from the start along the inlet for the rod's length, %g m) "
                    "crosses the lumen at (%g, %g) m: choose a start whose vessel runs straight out of the "
                    "network for that length, or a shorter rod",
                    rod_length, at.x(), at.y());
      throw InputError(std::string("/vessels/start: ") + text);
    }
}

// What graph and mask share once their lumen pieces and centreline are known.
void finish(Environment& env, std::vector<Polyline> pieces, double rounding, double chord_error, double rod_length) {
  const Polyline& c = env.centreline;
  const std::vector<double>& r = env.centreline_radius;
  refuse_an_introducer_across_the_lumen(env.inlet, r.front(), rod_length, pieces);
  pieces.push_back(introducer(env.inlet, r.front(), rod_length, chord_error));
  env.lumen = lumen_union(pieces, rounding, chord_error);
  env.walls = walls_along(env.lumen);
  env.bounds.min = env.bounds.max = c.front();
  for (const auto& ring : env.lumen)
    for (const Vec2& p : ring) env.bounds.min = env.bounds.min.cwiseMin(p), env.bounds.max = env.bounds.max.cwiseMax(p);
  env.start = c.front();
  env.goal = c.back();
  env.goal_radius = r.back();
  env.lumen_width = 2.0 * *std::min_element(r.begin(), r.end());
  env.inlet.opening = 2.0 * r.front();
  env.corner_radius = corner_allowance(c, r);
}

Environment graph_environment(const VesselsSpec& spec, double rod_length) {
  const VesselGraph graph = resolve_vessel_graph(spec);
  const std::vector<VesselSample> route = route_samples(graph, vessel_route(graph, spec));
  double smallest = INFINITY;
  for (const auto& s : graph.segments)
    for (const auto& v : s.samples) smallest = std::min(smallest, v.radius);
  const double chord_error = std::max(kRelativeChordError * smallest, kMinChordError);

  std::vector<Polyline> pieces;
  for (const auto& s : graph.segments)
    for (std::size_t k = 1; k < s.samples.size(); ++k)
      pieces.push_back(tapered_tube_ring(s.samples[k - 1].point, s.samples[k - 1].radius, s.samples[k].point,
                                         s.samples[k].radius, chord_error));
  for (const auto& sac : graph.sacs) pieces.push_back(disc_ring(sac.centre, sac.radius, chord_error));

  Environment env;
  for (const auto& v : route) {
    env.centreline.push_back(v.point);
    env.centreline_radius.push_back(v.radius);
  }
  env.inlet.tip = env.centreline.front();
  env.inlet.inward = (env.centreline[1] - env.centreline[0]).normalized();
  finish(env, std::move(pieces), kRelativeRounding * smallest, chord_error, rod_length);
  return env;
}

// The traced outline is the lumen as drawn: no rounding beyond the pixel's own (the tracer's
// wall is within a fifth of a pixel of the drawn edge), faceted at the pixel scale.
Environment mask_environment(const VesselMaskSpec& mask, double rod_length) {
  const MaskTrace trace = trace_vessel_mask(mask);
  Environment env;
  env.centreline = trace.centreline;
  env.centreline_radius = trace.radius;
  env.inlet.tip = env.centreline.front();
  // The inlet heads along the centreline's first stretch of one local diameter, which the
  // smoothing has made straight: the first pixel step alone may point anywhere within 45 degrees.
  const double reach = 2.0 * trace.radius.front();
  std::size_t k = 1;
  while (k + 1 < env.centreline.size() && (env.centreline[k] - env.centreline[0]).norm() < reach) ++k;
  env.inlet.inward = (env.centreline[k] - env.centreline[0]).normalized();
  finish(env, trace.outline, 0.0, 0.1 * mask.pixel_size, rod_length);
  return env;
}

}  // namespace

Environment build_vessel_environment(const VesselsSpec& spec, double rod_length) {
  return spec.from_mask ? mask_environment(spec.mask, rod_length) : graph_environment(spec, rod_length);
}

}  // namespace vascsim

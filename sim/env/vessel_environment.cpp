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

// The rod's way in: the introducer's axis, from the start straight back along the inlet for the
// rod's length and two inlet radii. The introducer must leave the network through nothing but its
// own vessel: joined to another one, the union would give the rod a way round the route and start
// it drawn through that vessel's walls.
struct WayIn {
  Vec2 tip, far;
  double length = 0.0;  // m
  Vec2 at(double s) const { return tip + (s / length) * (far - tip); }
};

WayIn way_in(const Inlet& inlet, double radius, double rod_length) {
  const double length = rod_length + 2.0 * radius;
  return {inlet.tip, inlet.tip - length * inlet.inward, length};
}

[[noreturn]] void refuse_way_in(const WayIn& w, double s, const char* what, const std::string& image = "") {
  const Vec2 p = w.at(s);
  char text[400];
  std::snprintf(text, sizeof text,
                "the rod's way in (straight back from the start along the inlet for the rod's length and two "
                "inlet radii, %g m) %s at (%g, %g) m, %g m behind the start: choose a start whose vessel runs "
                "straight out of the network for that length, or a shorter rod",
                w.length, what, p.x(), p.y(), s);
  throw InputError(std::string("/vessels/start: ") + text + (image.empty() ? "" : " (" + image + ")"));
}

// Parameter t in [0, 1] along p0-p1 where it crosses q0-q1, or -1.
double crossing(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const Vec2 d = p1 - p0, e = q1 - q0, w = q0 - p0;
  const double denom = d.x() * e.y() - d.y() * e.x();
  if (denom == 0.0) return -1.0;
  const double t = (w.x() * e.y() - w.y() * e.x()) / denom, u = (w.x() * d.y() - w.y() * d.x()) / denom;
  return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0 ? t : -1.0;
}

// A graph: the pieces of every other segment, and sacs off the inlet segment, must keep clear of
// the introducer (its radius, plus the gap the lumen's rounding closes). Returns the distance
// along the way in of the nearest piece that does not, or -1.
double way_in_meets(const WayIn& w, double radius, double rounding, const std::vector<Polyline>& others) {
  const double reach = radius + 2.0 * rounding;
  double nearest = -1.0;
  const auto note = [&](double s) { nearest = nearest < 0.0 ? s : std::min(nearest, s); };
  const Vec2 low = w.tip.cwiseMin(w.far) - Vec2::Constant(reach), high = w.tip.cwiseMax(w.far) + Vec2::Constant(reach);
  for (const Polyline& ring : others) {
    Vec2 ring_low = ring.front(), ring_high = ring.front();
    for (const Vec2& q : ring) ring_low = ring_low.cwiseMin(q), ring_high = ring_high.cwiseMax(q);
    if ((ring_low.array() > high.array()).any() || (ring_high.array() < low.array()).any()) continue;  // far away
    if (inside_lumen({ring}, w.tip)) note(0.0);
    else if (inside_lumen({ring}, w.far)) note(w.length);
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2 &q0 = ring[k], &q1 = ring[(k + 1) % ring.size()];
      if (const double t = crossing(w.tip, w.far, q0, q1); t >= 0.0) {
        note(t * w.length);
        continue;
      }
      // Not crossing: the nearest approach is at an end of one of the two segments.
      const auto to_segment = [](const Vec2& p, const Vec2& a, const Vec2& b, double& t) {
        const Vec2 ab = b - a;
        t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
        return (p - (a + t * ab)).norm();
      };
      double t = 0.0;
      if (to_segment(q0, w.tip, w.far, t) < reach) note(t * w.length);
      if (to_segment(q1, w.tip, w.far, t) < reach) note(t * w.length);
      double u = 0.0;
      if (to_segment(w.tip, q0, q1, u) < reach) note(0.0);
      if (to_segment(w.far, q0, q1, u) < reach) note(w.length);
    }
  }
  return nearest;
}

// What graph and mask share once their lumen pieces and centreline are known.
void finish(Environment& env, std::vector<Polyline> pieces, double rounding, double chord_error, double rod_length) {
  const Polyline& c = env.centreline;
  const std::vector<double>& r = env.centreline_radius;
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
  double smallest = INFINITY;
  for (const auto& s : graph.segments)
    for (const auto& v : s.samples) smallest = std::min(smallest, v.radius);
  const double chord_error = std::max(kRelativeChordError * smallest, kMinChordError);

  const std::vector<RouteStep> steps = vessel_route(graph, spec);
  const std::vector<VesselSample> route = route_samples(graph, steps);
  const int inlet_segment = steps.front().segment;
  const bool inlet_forward = steps.front().forward;
  const double start_radius = route.front().radius, rounding = kRelativeRounding * smallest;
  // What the way in must keep clear of: every other segment, and the inlet's own segment from
  // beyond the stretch at the start that touches the introducer by design (a vessel that loops
  // back across its own way in joins it as another segment would).
  const double own_clear = 2.0 * (start_radius + 2.0 * rounding) + start_radius;
  std::vector<Polyline> pieces, others;
  for (std::size_t i = 0; i < graph.segments.size(); ++i) {
    const auto& s = graph.segments[i];
    for (std::size_t k = 1; k < s.samples.size(); ++k) {
      pieces.push_back(tapered_tube_ring(s.samples[k - 1].point, s.samples[k - 1].radius, s.samples[k].point,
                                         s.samples[k].radius, chord_error));
      const double from_start = inlet_forward ? s.samples[k - 1].s : s.length - s.samples[k].s;
      if (static_cast<int>(i) != inlet_segment || from_start > own_clear) others.push_back(pieces.back());
    }
  }
  std::vector<Polyline> inlet_sacs;
  for (const auto& sac : graph.sacs) {
    pieces.push_back(disc_ring(sac.centre, sac.radius, chord_error));
    (sac.segment != inlet_segment ? others : inlet_sacs).push_back(pieces.back());
  }

  Environment env;
  for (const auto& v : route) {
    env.centreline.push_back(v.point);
    env.centreline_radius.push_back(v.radius);
  }
  env.inlet.tip = env.centreline.front();
  env.inlet.inward = (env.centreline[1] - env.centreline[0]).normalized();
  const WayIn w = way_in(env.inlet, env.centreline_radius.front(), rod_length);
  if (const double s = way_in_meets(w, env.centreline_radius.front(), rounding, others); s >= 0.0)
    refuse_way_in(w, s, "comes within the introducer's radius of another vessel, which its lumen would join to the inlet,");
  // A sac on the inlet's own segment opens off it, but one near the start may reach back past it,
  // beside the introducer, where the rod lies in a straight sheath: checked from one reach behind
  // the start (a sac wholly in front of the start's cross-section is farther than that from it).
  const double reach = env.centreline_radius.front() + 2.0 * rounding;
  const WayIn behind{w.at(reach), w.far, w.length - reach};
  if (const double s = way_in_meets(behind, env.centreline_radius.front(), rounding, inlet_sacs); s >= 0.0)
    refuse_way_in(w, reach + s, "comes within the introducer's radius of an aneurysm on the inlet that reaches back past the start,");
  finish(env, std::move(pieces), rounding, chord_error, rod_length);
  return env;
}

// A mask: the introducer may overlap its own vessel (which may run on behind the start, to the
// image's edge), but its union with the traced lumen must have the lumen's shape: fewer outer
// rings (it joined another part of the lumen, across the way in or beside it) or more holes (it
// closed a loop through its own vessel) give the rod a way the image does not. Counting the
// union's rings is exact for what the union does, whatever the error of the traced inlet
// direction: a way in that drifts out through its own jagged wall and grazes it again changes
// neither count (an earlier test, along the way in's axis, had to allow such grazes and missed a
// vessel beside the way in). Slivers are not counted as holes: where the introducer's edge
// crosses its own vessel's staircase wall at a shallow angle (a thin vessel whose traced
// direction is a degree off) it encloses lenses of up to 2.4 px^2 but at most 0.33 px thick on
// average (measured on straight vessels of radius 2.5 to 6 px at 1 to 15 degrees), which no rod
// enters; a loop's hole is the tissue the loop goes round.
bool is_sliver(const Polyline& ring, double pixel_size) {
  double perimeter = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) perimeter += (ring[(k + 1) % ring.size()] - ring[k]).norm();
  return 2.0 * std::abs(ring_area(ring)) < pixel_size * perimeter;  // mean thickness under a pixel
}

void check_mask_way_in(const Environment& env, const std::vector<Polyline>& outline, const WayIn& w, double pixel_size,
                       const std::string& image) {
  const double radius = env.centreline_radius.front();
  const auto is_hole = [&](const Polyline& ring) { return ring_area(ring) < 0.0 && !is_sliver(ring, pixel_size); };
  const auto count = [&](const std::vector<Polyline>& rings, bool holes) {
    return std::count_if(rings.begin(), rings.end(),
                         [&](const Polyline& ring) { return holes ? is_hole(ring) : ring_area(ring) > 0.0; });
  };
  // Where along the way in the nearest of `rings` comes within the introducer (or -1).
  const auto nearest = [&](const std::vector<Polyline>& rings) {
    double at = -1.0;
    for (const Polyline& ring : rings)
      if (const double s = way_in_meets(w, radius + pixel_size, 0.0, {ring}); s >= 0.0) at = at < 0.0 ? s : std::min(at, s);
    return std::max(at, 0.0);
  };
  if (count(env.lumen, false) < count(outline, false)) {
    std::vector<Polyline> others;
    for (const Polyline& ring : outline)
      if (ring_area(ring) > 0.0 && !inside_lumen({ring}, w.tip)) others.push_back(ring);
    refuse_way_in(w, nearest(others), "comes within the introducer's radius of another vessel, which its lumen would join to the inlet,", image);
  }
  if (count(env.lumen, true) > count(outline, true)) {
    // Where the loop closes: walking back along the way in, the first place where, after a
    // stretch clear of the lumen, the introducer meets it again (the new hole also touches the
    // way in where it leaves its own vessel: reported there, it named the start).
    const auto distance_to_wall = [&](const Vec2& p) {
      double d = INFINITY;
      for (const Polyline& ring : outline)
        for (std::size_t k = 0; k < ring.size(); ++k) {
          const Vec2 &a = ring[k], &b = ring[(k + 1) % ring.size()], ab = b - a;
          const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
          d = std::min(d, (p - (a + t * ab)).norm());
        }
      return d;
    };
    double at = -1.0;
    bool cleared = false;
    for (double s = 0.0; s <= w.length && at < 0.0; s += pixel_size) {
      const bool touching = inside_lumen(outline, w.at(s)) || distance_to_wall(w.at(s)) < radius;
      if (!touching) cleared = true;
      else if (cleared) at = s;
    }
    if (at < 0.0) {
      // Never clear (the loop runs beside the way in from its own vessel's end): the first place
      // outside its own vessel beside which the new hole's wall runs.
      std::vector<double> beside;
      for (const Polyline& ring : env.lumen)
        if (is_hole(ring))
          for (const Vec2& q : ring) {
            const double s = std::clamp((q - w.tip).dot(w.far - w.tip) / w.length, 0.0, w.length);
            if ((q - w.at(s)).norm() < radius + pixel_size) beside.push_back(s);
          }
      std::sort(beside.begin(), beside.end());
      const auto outside = std::find_if(beside.begin(), beside.end(), [&](double s) { return !inside_lumen(outline, w.at(s)); });
      at = outside == beside.end() ? 0.0 : *outside;
    }
    refuse_way_in(w, at, "comes within the introducer's radius of its own vessel elsewhere, which its lumen would join into a loop,",
                  image);
  }
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
  // smoothing has made straight (the first pixel step alone may point anywhere within 45
  // degrees). For a start on the image's border, along two diameters from where the border no
  // longer pulls the path off the vessel's axis: a vessel leaving the image at 75 degrees from the
  // border's normal gave 17 degrees off from the start, 6.6 over one diameter, 0.1 over two.
  // (From the start if the route ends within that of where the border lets go.)
  const Polyline& c = env.centreline;
  const double reach = (trace.clear_of_border > 0 ? 4.0 : 2.0) * trace.radius.front();
  const std::size_t from =
      trace.clear_of_border > 0 && trace.clear_of_border + 1 < c.size() && (c.back() - c[trace.clear_of_border]).norm() >= reach
          ? trace.clear_of_border
          : 0;
  std::size_t k = from + 1;
  while (k + 1 < c.size() && (c[k] - c[from]).norm() < reach) ++k;
  env.inlet.inward = (c[k] - c[from]).normalized();
  finish(env, trace.outline, 0.0, 0.1 * mask.pixel_size, rod_length);
  check_mask_way_in(env, trace.outline, way_in(env.inlet, env.centreline_radius.front(), rod_length),
                    mask.pixel_size, mask.file);
  return env;
}

}  // namespace

Environment build_vessel_environment(const VesselsSpec& spec, double rod_length) {
  return spec.from_mask ? mask_environment(spec.mask, rod_length) : graph_environment(spec, rod_length);
}

}  // namespace vascsim

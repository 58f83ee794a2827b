#include "sim/env/vessel_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <sstream>

#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Samples across each stenosis: its raised cosine is then drawn with a chord error below 0.1 % of
// the narrowing's depth, far finer than the wall's facets.
constexpr int kStenosisSamples = 48;

[[noreturn]] void fail(const std::string& pointer, const std::string& what) { throw InputError(pointer + ": " + what); }
[[noreturn]] void fail(const std::string& pointer, const std::string& expected, const std::string& got) {
  fail(pointer, "expected " + expected + ", got " + got);
}
std::string number(double x) {
  std::ostringstream m;
  m << x;
  return m.str();
}
std::string quoted(const std::string& name) { return "\"" + name + "\""; }

std::string segment_pointer(std::size_t i) { return "/vessels/segments/" + std::to_string(i); }

// A tube of `radius` that comes in along leg `in` and leaves along leg `out` (vectors as long as
// the legs) turning by more than 90 degrees: its two legs' tubes part 2 radius / sin(angle between
// the legs) from the corner. If that is beyond the shorter leg, and that leg is at least two
// diameters long, one stretch of vessel lies inside the other all along it: the vessel folds
// onto itself, and the reference path has no corner it can round (a rounded 179.9-degree turn
// cut the whole hairpin off). A shorter leg is a jog, not a fold (a 100-degree Z-jog with a leg
// of two radii was refused). An exact reversal is always a fold: no side to round it to.
bool folds_back(const Vec2& in, const Vec2& out, double radius) {
  if (in.dot(out) >= 0.0) return false;
  const double li = in.norm(), lo = out.norm(), shorter = std::min(li, lo);
  const double sin_between = std::abs(in.x() * out.y() - in.y() * out.x()) / (li * lo);
  if (sin_between <= 1e-9) return true;
  return shorter >= 4.0 * radius && 2.0 * radius >= sin_between * shorter;
}

// A leg of a turn: `away` runs from the turn point away from it, along the vessel before or after
// the turn. The leg goes on as long as the vessel stays within half a radius of its first piece's
// line (a sub-degree kink does not end it: the vessel still lies in the other leg's tube), as a
// vector along that piece as long as the leg. Beyond, the vessel bends away, so a fold is a fold of
// these legs (a test with the whole segments as legs passed a daughter running back inside its
// parent before bending away, and one with the first pieces alone a 1-degree kink near the node).
Vec2 leg(const Polyline& away, double radius) {
  const Vec2 turn = away[0], direction = (away[1] - away[0]).normalized();
  const double tolerance = 0.5 * radius;
  const auto off_line = [&](const Vec2& q) { const Vec2 d = q - turn; return std::abs(direction.x() * d.y() - direction.y() * d.x()); };
  double length = 0.0;
  for (std::size_t k = 1; k < away.size(); ++k) {
    const double piece = (away[k] - away[k - 1]).norm();
    const double before = off_line(away[k - 1]), after = off_line(away[k]);
    if (after > tolerance || (away[k] - turn).dot(direction) <= 0.0) {
      // Up to where it leaves the band (linear along the piece), then no further.
      if (after > before) length += piece * std::clamp((tolerance - before) / (after - before), 0.0, 1.0);
      break;
    }
    length += piece;
  }
  return length * direction;
}

// The points of a polyline from index k back to its start, and from k on to its end.
Polyline behind_from(const Polyline& p, std::size_t k) { return Polyline(p.rend() - 1 - k, p.rend()); }
Polyline ahead_from(const Polyline& p, std::size_t k) { return Polyline(p.begin() + k, p.end()); }

double turn_degrees(const Vec2& in, const Vec2& out) {
  return std::atan2(std::abs(in.x() * out.y() - in.y() * out.x()), in.dot(out)) * 180.0 / kPi;
}

// Point and base radius (the linear taper) at arc length s along a polyline with radii.
struct Profile {
  Polyline points;
  std::vector<double> s, radius;  // m, cumulative arc length and radius at each point
  void at(double where, Vec2& point, double& r) const {
    const auto it = std::upper_bound(s.begin(), s.end(), where);
    std::size_t k = it == s.begin() ? 0 : static_cast<std::size_t>(it - s.begin()) - 1;
    k = std::min(k, s.size() - 2);
    const double span = s[k + 1] - s[k];
    const double u = span > 0.0 ? std::clamp((where - s[k]) / span, 0.0, 1.0) : 0.0;
    point = points[k] + u * (points[k + 1] - points[k]);
    r = radius[k] + u * (radius[k + 1] - radius[k]);
  }
};

Profile profile_of(const VesselSegmentSpec& seg, const Vec2& from, const Vec2& to, std::size_t index) {
  Profile p;
  p.points.push_back(from);
  for (const Vec2& v : seg.via) p.points.push_back(v);
  p.points.push_back(to);
  p.s.push_back(0.0);
  for (std::size_t k = 1; k < p.points.size(); ++k) {
    const double step = (p.points[k] - p.points[k - 1]).norm();
    if (!(step > 0.0)) {
      // Points are from, via/0 .. via/n-1, to: the via point at k - 1 repeats the point before
      // it, or the last one lies on `to`.
      if (seg.via.empty())
        fail(segment_pointer(index), quoted(seg.from) + " and " + quoted(seg.to) +
                                         " are at the same point (a segment joins two different places)");
      const bool at_end = k > seg.via.size();
      const std::size_t j = at_end ? seg.via.size() - 1 : k - 1;
      const std::string other = at_end ? "node " + quoted(seg.to) + ", where the segment ends"
                                : j == 0 ? "node " + quoted(seg.from) + ", where the segment starts"
                                         : "via/" + std::to_string(j - 1);
      fail(segment_pointer(index) + "/via/" + std::to_string(j), "a point other than " + other,
           "[" + number(seg.via[j].x()) + ", " + number(seg.via[j].y()) + "]");
    }
    p.s.push_back(p.s.back() + step);
  }
  const std::string rp = segment_pointer(index) + "/radius";
  if (seg.radius.size() == 2) {
    for (double s : p.s) p.radius.push_back(seg.radius[0] + (seg.radius[1] - seg.radius[0]) * s / p.s.back());
  } else if (seg.radius.size() == p.points.size()) {
    p.radius = seg.radius;
  } else {
    std::ostringstream m;
    m << "expected 2 radii (at the ends)";
    if (p.points.size() > 2) m << " or " << p.points.size() << " (one per point: from, via, to)";
    m << ", got " << seg.radius.size();
    fail(rp, m.str());
  }
  for (std::size_t k = 0; k < seg.radius.size(); ++k)
    if (!(seg.radius[k] > 0.0) || !std::isfinite(seg.radius[k])) fail(rp + "/" + std::to_string(k), "a radius > 0 (m)", number(seg.radius[k]));
  for (std::size_t k = 1; k + 1 < p.points.size(); ++k) {
    const Vec2 in = -leg(behind_from(p.points, k), p.radius[k]), out = leg(ahead_from(p.points, k), p.radius[k]);
    if (folds_back(in, out, p.radius[k]))
      fail(segment_pointer(index) + "/via/" + std::to_string(k - 1),
           "the segment turns by " + number(turn_degrees(in, out)) + " degrees at [" + number(seg.via[k - 1].x()) + ", " +
               number(seg.via[k - 1].y()) + "], so sharply that its two legs (radius " + number(p.radius[k]) +
               " m) overlap all along the shorter one: the vessel folds onto itself");
  }
  return p;
}

Polyline points_of(const std::vector<VesselSample>& samples) {
  Polyline p;
  for (const auto& v : samples) p.push_back(v.point);
  return p;
}

// Whether the route folds back at the node between steps `came` and `goes` (folds_back of the
// two segments' legs there).
bool route_folds_back(const VesselGraph& g, const RouteStep& came, const RouteStep& goes, Vec2& in, Vec2& out) {
  const auto& s = g.segments[static_cast<std::size_t>(came.segment)].samples;
  const auto& t = g.segments[static_cast<std::size_t>(goes.segment)].samples;
  const double radius = std::max(came.forward ? s.back().radius : s.front().radius, goes.forward ? t.front().radius : t.back().radius);
  const Polyline incoming = points_of(s), outgoing = points_of(t);
  in = -leg(came.forward ? behind_from(incoming, incoming.size() - 1) : ahead_from(incoming, 0), radius);
  out = leg(goes.forward ? ahead_from(outgoing, 0) : behind_from(outgoing, outgoing.size() - 1), radius);
  return folds_back(in, out, radius);
}

}  // namespace

double stenosis_factor(const std::vector<StenosisSpec>& stenoses, double s) {
  double factor = 1.0;
  for (const auto& st : stenoses) {
    const double u = (s - st.at) / st.length;
    if (std::abs(u) < 0.5) factor *= 1.0 - (1.0 - st.fraction) * 0.5 * (1.0 + std::cos(2.0 * kPi * u));
  }
  return factor;
}

VesselGraph resolve_vessel_graph(const VesselsSpec& spec) {
  VesselGraph g;
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < spec.nodes.size(); ++i) {
    const auto& n = spec.nodes[i];
    if (!index.emplace(n.name, static_cast<int>(i)).second)
      fail("/vessels/nodes/" + std::to_string(i) + "/name", "node names must be unique, \"" + n.name + "\" repeats");
    g.names.push_back(n.name);
    g.positions.push_back(n.position);
  }
  const auto node = [&](const std::string& name, const std::string& pointer) {
    const auto it = index.find(name);
    if (it == index.end()) fail(pointer, "\"" + name + "\" is not a node in /vessels/nodes");
    return it->second;
  };
  if (spec.segments.empty()) fail("/vessels/segments", "at least one segment");
  for (std::size_t i = 0; i < spec.segments.size(); ++i) {
    const auto& seg = spec.segments[i];
    ResolvedSegment r;
    r.from = node(seg.from, segment_pointer(i) + "/from");
    r.to = node(seg.to, segment_pointer(i) + "/to");
    const Profile p = profile_of(seg, g.positions[static_cast<std::size_t>(r.from)],
                                 g.positions[static_cast<std::size_t>(r.to)], i);
    r.length = p.s.back();
    // Sample at every given point, and densely across each stenosis.
    std::vector<double> at = p.s;
    for (std::size_t k = 0; k < seg.stenoses.size(); ++k) {
      const auto& st = seg.stenoses[k];
      const std::string sp = segment_pointer(i) + "/stenoses/" + std::to_string(k);
      if (!(st.at - 0.5 * st.length >= 0.0 && st.at + 0.5 * st.length <= r.length)) {
        std::ostringstream m;
        m << "the narrowing (at " << st.at << " m, length " << st.length << " m) must lie within the segment (0 to "
          << r.length << " m)";
        fail(sp, m.str());
      }
      for (int j = 0; j <= kStenosisSamples; ++j) at.push_back(st.at + st.length * (double(j) / kStenosisSamples - 0.5));
    }
    std::sort(at.begin(), at.end());
    for (double s : at) {
      if (!r.samples.empty() && s - r.samples.back().s <= 1e-9 * r.length) continue;
      VesselSample v;
      v.s = s;
      double base = 0.0;
      p.at(s, v.point, base);
      v.radius = base * stenosis_factor(seg.stenoses, s);
      r.samples.push_back(v);
    }
    for (std::size_t k = 0; k < seg.aneurysms.size(); ++k) {
      const auto& a = seg.aneurysms[k];
      const std::string ap = segment_pointer(i) + "/aneurysms/" + std::to_string(k);
      if (!(a.at >= 0.0 && a.at <= r.length)) fail(ap + "/at", "an arc length within the segment, [0, " + number(r.length) + "] m", number(a.at));
      if (!(a.neck > 0.0 && a.neck < 2.0 * a.radius)) fail(ap + "/neck", "a width > 0 and below the sac's diameter, " + number(2.0 * a.radius) + " m", number(a.neck));
      Vec2 point, ahead;
      double base = 0.0, unused = 0.0;
      p.at(a.at, point, base);
      const double radius = base * stenosis_factor(seg.stenoses, a.at);
      // The local tangent from a small step along the centreline (either way at the ends).
      const double ds = 1e-6 * r.length;
      p.at(std::min(a.at + ds, r.length), ahead, unused);
      Vec2 behind;
      p.at(std::max(a.at - ds, 0.0), behind, unused);
      const Vec2 tangent = (ahead - behind).normalized();
      const Vec2 left(-tangent.y(), tangent.x());
      // The sac's circle crosses the tube's wall line in a chord `neck` long: its centre lies
      // sqrt(R^2 - (neck/2)^2) beyond the wall.
      const double beyond = std::sqrt(a.radius * a.radius - 0.25 * a.neck * a.neck);
      g.sacs.push_back({point + (a.left ? 1.0 : -1.0) * (radius + beyond) * left, a.radius, static_cast<int>(i)});
    }
    g.segments.push_back(std::move(r));
  }
  g.start = node(spec.start, "/vessels/start");
  g.goal = node(spec.goal, "/vessels/goal");
  int ends = 0;
  for (const auto& s : g.segments) ends += (s.from == g.start) + (s.to == g.start);
  if (ends != 1)
    fail("/vessels/start", "the inlet node \"" + spec.start + "\" must end exactly one segment (the rod enters there), it ends " +
                               std::to_string(ends));
  if (g.start == g.goal) fail("/vessels/goal", "a node other than the start", quoted(spec.goal));
  return g;
}

std::vector<RouteStep> vessel_route(const VesselGraph& g, const VesselsSpec& spec) {
  const int n = static_cast<int>(g.names.size());
  std::vector<RouteStep> route;
  if (!spec.route.empty()) {
    std::vector<int> nodes;
    for (std::size_t i = 0; i < spec.route.size(); ++i) {
      const auto it = std::find(g.names.begin(), g.names.end(), spec.route[i]);
      if (it == g.names.end()) fail("/vessels/route/" + std::to_string(i), "\"" + spec.route[i] + "\" is not a node");
      nodes.push_back(static_cast<int>(it - g.names.begin()));
    }
    if (nodes.front() != g.start) fail("/vessels/route/0", "the start node " + quoted(spec.start), quoted(spec.route.front()));
    if (nodes.back() != g.goal)
      fail("/vessels/route/" + std::to_string(nodes.size() - 1), "the goal node " + quoted(spec.goal), quoted(spec.route.back()));
    for (std::size_t i = 1; i < nodes.size(); ++i) {
      // The shortest segment joining the two nodes that does not fold back on the way in (two
      // segments may join them: a loop goes out by one and back by the other).
      std::vector<std::pair<double, RouteStep>> joining;
      for (std::size_t k = 0; k < g.segments.size(); ++k) {
        const auto& s = g.segments[k];
        const bool fwd = s.from == nodes[i - 1] && s.to == nodes[i], back = s.to == nodes[i - 1] && s.from == nodes[i];
        if (fwd || back) joining.push_back({s.length, {static_cast<int>(k), fwd}});
      }
      if (joining.empty())
        fail("/vessels/route/" + std::to_string(i),
             "no segment joins \"" + spec.route[i - 1] + "\" and \"" + spec.route[i] + "\"");
      std::stable_sort(joining.begin(), joining.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      const RouteStep* chosen = nullptr;
      Vec2 in, out;
      for (const auto& [length, step] : joining)
        if (route.empty() || !route_folds_back(g, route.back(), step, in, out)) {
          chosen = &step;
          break;
        }
      if (!chosen)
        fail("/vessels/route/" + std::to_string(i),
             "the route turns by " + number(turn_degrees(in, out)) + " degrees at " + quoted(spec.route[i - 1]) + " to go on to " +
                 quoted(spec.route[i]) + ", back along " +
                 (joining.front().second.segment == route.back().segment ? "the segment" : "a segment overlapping the one") +
                 " it came by: a catheter cannot turn round in a vessel");
      route.push_back(*chosen);
    }
    return route;
  }
  // Dijkstra over nodes, by arc length.
  std::vector<double> dist(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  std::vector<RouteStep> via(static_cast<std::size_t>(n));
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  dist[static_cast<std::size_t>(g.start)] = 0.0;
  queue.push({0.0, g.start});
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > dist[static_cast<std::size_t>(u)]) continue;
    for (std::size_t k = 0; k < g.segments.size(); ++k) {
      const auto& s = g.segments[k];
      if (s.from != u && s.to != u) continue;
      const int v = s.from == u ? s.to : s.from;
      const double nd = d + s.length;
      if (nd < dist[static_cast<std::size_t>(v)]) {
        dist[static_cast<std::size_t>(v)] = nd;
        via[static_cast<std::size_t>(v)] = {static_cast<int>(k), s.from == u};
        queue.push({nd, v});
      }
    }
  }
  if (!std::isfinite(dist[static_cast<std::size_t>(g.goal)])) {
    std::string hint;
    // Two names for one junction is the likely slip: a node reached from the start at the same
    // point as one that is not.
    for (int a = 0; a < n && hint.empty(); ++a)
      for (int b = 0; b < n && hint.empty(); ++b)
        if (std::isfinite(dist[static_cast<std::size_t>(a)]) && !std::isfinite(dist[static_cast<std::size_t>(b)]) &&
            g.positions[static_cast<std::size_t>(a)] == g.positions[static_cast<std::size_t>(b)])
          hint = " (nodes " + quoted(g.names[static_cast<std::size_t>(a)]) + " and " + quoted(g.names[static_cast<std::size_t>(b)]) +
                 " are at the same point but are two nodes: segments meet only at a node they both name)";
    fail("/vessels/goal", "\"" + spec.goal + "\" is not connected to the start \"" + spec.start + "\"" + hint);
  }
  for (int v = g.goal; v != g.start;) {
    const RouteStep step = via[static_cast<std::size_t>(v)];
    route.push_back(step);
    const auto& s = g.segments[static_cast<std::size_t>(step.segment)];
    v = step.forward ? s.from : s.to;
  }
  std::reverse(route.begin(), route.end());
  // Segments that overlap can make even the shortest route fold back (A to B past C, then back to C).
  for (std::size_t i = 1; i < route.size(); ++i) {
    Vec2 in, out;
    if (route_folds_back(g, route[i - 1], route[i], in, out)) {
      const auto& s = g.segments[static_cast<std::size_t>(route[i - 1].segment)];
      const int node = route[i - 1].forward ? s.to : s.from;
      fail("/vessels/goal", "the shortest route from the start turns by " + number(turn_degrees(in, out)) + " degrees at " +
                                quoted(g.names[static_cast<std::size_t>(node)]) +
                                ", back along the way it came (overlapping segments?): a catheter cannot turn round in a "
                                "vessel; name a route (/vessels/route) that does not");
    }
  }
  return route;
}

std::vector<VesselSample> route_samples(const VesselGraph& g, const std::vector<RouteStep>& route) {
  std::vector<VesselSample> out;
  for (const RouteStep& step : route) {
    std::vector<VesselSample> samples = g.segments[static_cast<std::size_t>(step.segment)].samples;
    if (!step.forward) std::reverse(samples.begin(), samples.end());
    for (std::size_t k = out.empty() ? 0 : 1; k < samples.size(); ++k) out.push_back(samples[k]);
  }
  return out;
}

}  // namespace vascsim

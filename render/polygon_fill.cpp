#include "render/polygon_fill.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace vascsim::render {

namespace {

// A ring edge that is not horizontal, lower end first.
struct Edge {
  Vec2 lo, hi;
};

// x where `e` crosses height y; its end points exactly at their own heights, so neighbouring
// trapezoids along the edge share their corners bit for bit.
double x_at(const Edge& e, double y) {
  if (y <= e.lo.y()) return e.lo.x();
  if (y >= e.hi.y()) return e.hi.x();
  return e.lo.x() + (e.hi.x() - e.lo.x()) * ((y - e.lo.y()) / (e.hi.y() - e.lo.y()));
}

double cross(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Builds the triangles slab by slab, bottom to top. A trapezoid stays open while the next slab
// pairs the same two edges, so a tube between two long edges is one trapezoid, not one per slab
// (fewer triangles and fewer horizontal joins).
class Decomposer {
 public:
  explicit Decomposer(const std::vector<Edge>& edges) : edges_(edges) {}

  // The slab [y0, y1] crossed by `active` (indices into the edges).
  void slab(std::vector<std::size_t> active, double y0, double y1, int depth = 0) {
    struct Crossing {
      std::size_t edge;
      double x0, x1;  // at y0 and y1
    };
    std::vector<Crossing> c;
    c.reserve(active.size());
    for (std::size_t i : active) c.push_back({i, x_at(edges_[i], y0), x_at(edges_[i], y1)});
    // By the x at mid-height: edges that do not cross keep this order over the whole slab.
    std::sort(c.begin(), c.end(), [](const Crossing& a, const Crossing& b) {
      return a.x0 + a.x1 < b.x0 + b.x1 || (a.x0 + a.x1 == b.x0 + b.x1 && a.edge < b.edge);
    });
    // Edges that cross inside the slab (rings that intersect): if any do, some neighbours in
    // this order do; cut the slab at the lowest such crossing and start again on both halves.
    if (depth < 64) {
      double cut = y1;
      for (std::size_t k = 0; k + 1 < c.size(); ++k) {
        const double d0 = c[k + 1].x0 - c[k].x0, d1 = c[k + 1].x1 - c[k].x1;
        if (!(d0 < 0 && d1 > 0) && !(d0 > 0 && d1 < 0)) continue;
        const double y = y0 + (y1 - y0) * (d0 / (d0 - d1));
        if (y > y0 && y < y1) cut = std::min(cut, y);
      }
      // A cut too close to an end (rounding) would not make progress: leave that slab as it is.
      if (cut < y1 && cut > y0 + 1e-12 * (y1 - y0) && cut < y1 - 1e-12 * (y1 - y0)) {
        slab(active, y0, cut, depth + 1);
        slab(active, cut, y1, depth + 1);
        return;
      }
    }
    std::vector<Open> next;
    for (std::size_t k = 0; k + 1 < c.size(); k += 2) {
      const std::size_t left = c[k].edge, right = c[k + 1].edge;
      auto same = [&](const Open& o) { return o.left == left && o.right == right && o.y1 == y0; };
      const auto it = std::find_if(open_.begin(), open_.end(), same);
      if (it != open_.end()) {
        next.push_back({left, right, it->y0, y1});
        open_.erase(it);
      } else {
        next.push_back({left, right, y0, y1});
      }
    }
    for (const Open& o : open_) emit(o);
    open_ = std::move(next);
  }

  std::vector<Triangle> finish() {
    for (const Open& o : open_) emit(o);
    open_.clear();
    return std::move(triangles_);
  }

 private:
  struct Open {  // a trapezoid between two edges from y0 to y1 that may still grow upwards
    std::size_t left, right;
    double y0, y1;
  };

  void emit(const Open& o) {
    const Edge &l = edges_[o.left], &r = edges_[o.right];
    const Vec2 bl(x_at(l, o.y0), o.y0), br(x_at(r, o.y0), o.y0);
    const Vec2 tr(x_at(r, o.y1), o.y1), tl(x_at(l, o.y1), o.y1);
    add(bl, br, tr);
    add(bl, tr, tl);
  }
  void add(const Vec2& a, const Vec2& b, const Vec2& c) {
    if (cross(a, b, c) != 0) triangles_.push_back({a, b, c});
  }

  const std::vector<Edge>& edges_;
  std::vector<Open> open_;
  std::vector<Triangle> triangles_;
};

}  // namespace

std::vector<Triangle> triangulate_even_odd(const std::vector<Polyline>& rings) {
  std::vector<Edge> edges;
  std::vector<double> ys;
  for (const Polyline& ring : rings) {
    // A ring with a non-finite point has no interior to speak of; one missing edge would
    // unbalance the pairing of every slab it spans.
    const bool finite = std::all_of(ring.begin(), ring.end(), [](const Vec2& p) { return p.allFinite(); });
    if (ring.size() < 3 || !finite) continue;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
      ys.push_back(a.y());
      // Horizontal edges bound no slab: the slabs above and below them already differ.
      if (a.y() == b.y()) continue;
      edges.push_back(a.y() < b.y() ? Edge{a, b} : Edge{b, a});
    }
  }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.lo.y() < b.lo.y(); });

  // Sweep upwards: an edge is active in the slabs between its end points' heights, all of
  // which are slab boundaries.
  Decomposer d(edges);
  std::vector<std::size_t> active;
  std::size_t next = 0;
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
    const double y0 = ys[k], y1 = ys[k + 1];
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t i) { return edges[i].hi.y() <= y0; }),
                 active.end());
    while (next < edges.size() && edges[next].lo.y() <= y0) active.push_back(next++);
    if (active.size() >= 2) d.slab(active, y0, y1);
  }
  return d.finish();
}

bool axis_aligned_rectangle(const Polyline& ring, Box2& box) {
  std::size_t n = ring.size();
  if (n == 5 && ring.front() == ring.back()) n = 4;
  if (n != 4) return false;
  // Four corners of a rectangle: each side horizontal or vertical, alternating.
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec2 &a = ring[i], &b = ring[(i + 1) % 4], &c = ring[(i + 2) % 4];
    const bool ab_horizontal = a.y() == b.y() && a.x() != b.x(), ab_vertical = a.x() == b.x() && a.y() != b.y();
    const bool bc_horizontal = b.y() == c.y() && b.x() != c.x(), bc_vertical = b.x() == c.x() && b.y() != c.y();
    if (!((ab_horizontal && bc_vertical) || (ab_vertical && bc_horizontal))) return false;
  }
  box.min = ring[0].cwiseMin(ring[1]).cwiseMin(ring[2]).cwiseMin(ring[3]);
  box.max = ring[0].cwiseMax(ring[1]).cwiseMax(ring[2]).cwiseMax(ring[3]);
  return true;
}

}  // namespace vascsim::render

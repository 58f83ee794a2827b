// Triangles that tile the even-odd interior of a set of closed rings: how the canvas fills a
// vessel lumen of any shape (curved tubes, junctions, sacs, rings with holes). Computed once in
// world coordinates and transformed per frame. Pure geometry: no GL, so it is unit-tested alone.
//
// The method is a trapezoid decomposition. Horizontal lines through every vertex cut the plane
// into slabs; no edge starts or ends inside a slab, so the edges crossing it, sorted by x, bound
// the interior in pairs (even-odd: 1st-2nd, 3rd-4th, ...). Each pair is a trapezoid, merged with
// the one above while the same two edges bound it, and split into two triangles. Every slanted
// side of a trapezoid lies on a ring edge and every other side is horizontal, so neighbouring
// triangles meet along exactly shared lines: GL rasterises them with no seam and no pixel twice.
// Rings that cross themselves or each other are handled too: a slab is split where two of its
// edges cross, so the pairing stays right.
#pragma once

#include <vector>

#include "sim/env/geometry.h"

namespace vascsim::render {

struct Triangle {
  Vec2 a, b, c;  // same unit as the rings; orientation unspecified
};

// The even-odd interior of `rings` (each closed: the last point joins the first; a repeated first
// point at the end is allowed) as non-degenerate, non-overlapping triangles. Horizontal and
// zero-length edges are fine; rings with fewer than 3 points or a non-finite point contribute
// nothing. About 2 triangles per vertex; 5000 vertices take about 2 ms (each slab costs the edges
// crossing it, so many long edges spanning many vertex heights cost more).
std::vector<Triangle> triangulate_even_odd(const std::vector<Polyline>& rings);

// If `ring` is an axis-aligned rectangle with non-zero area (4 corners in either order, from any
// corner, optionally with the first point repeated at the end), stores it in `box` and returns
// true. A maze logs its lumen as such a ring, which the painter fills as before with a clear.
bool axis_aligned_rectangle(const Polyline& ring, Box2& box);

}  // namespace vascsim::render

// Lumen polygons for vessel networks: the convex pieces a network is made of (a tube between two
// centreline samples is the convex hull of its two end discs, a sac is a disc), their union, and
// the walls along the union's outline. The union and the smoothing of its joins are Clipper's
// (libpolyclipping, Angus Johnson's Vatti clipper): exact integer arithmetic on a 0.1 um grid, so
// the outline is the same bytes on every run. Rings are closed implicitly (the last point joins
// the first); the lumen is their even-odd interior, outer boundaries counter-clockwise, holes
// clockwise.
#pragma once

#include <vector>

#include "sim/env/geometry.h"

namespace vascsim {

// A regular polygon inscribed in the circle (centre, radius), counter-clockwise, with enough
// vertices that no chord lies farther than chord_error (m) from the arc (at least 16).
Polyline disc_ring(const Vec2& centre, double radius, double chord_error);

// The convex hull of the discs (a, ra) and (b, rb): a tube tapering linearly from a to b with
// round ends, counter-clockwise.
Polyline tapered_tube_ring(const Vec2& a, double ra, const Vec2& b, double rb, double chord_error);

// The union of `pieces` (non-zero winding: give each piece counter-clockwise; clockwise rings cut
// holes), its concave corners then rounded to `rounding_radius` (m; 0: none) by a morphological
// closing (offset out, then back in, with round joins): the carina between two daughters becomes a
// smooth ridge, a bend's inner corner a fillet; convex parts and straight walls do not move.
std::vector<Polyline> lumen_union(const std::vector<Polyline>& pieces, double rounding_radius, double chord_error);

// Zero-thickness walls along every edge of every ring: the contact geometry of the lumen.
std::vector<WallSegment> walls_along(const std::vector<Polyline>& rings);

// Even-odd inside test against all rings (a point exactly on an edge may go either way).
bool inside_lumen(const std::vector<Polyline>& rings, const Vec2& p);

// Area (m^2) of the even-odd interior, from the shoelace formula (holes count negative).
double lumen_area(const std::vector<Polyline>& rings);
// Signed area (m^2) of one ring: positive counter-clockwise (an outer boundary), negative clockwise.
double ring_area(const Polyline& ring);

}  // namespace vascsim

// Distance from a point to the walls, for contact: the signed distance to the nearest wall surface,
// the closest surface point and the outward normal, or every wall within a radius (a rod node in a
// corner touches two). A wall is a capsule: the points within thickness/2 of its segment
// (geometry.h), so wall ends are round and the normal is defined everywhere. Queries go through a
// uniform grid of buckets built once, each listing the walls that can be within max_query_radius of
// a point in it, so a query looks at one bucket instead of every wall.
//
// Sign conventions: distance > 0 in free space, 0 on the surface, < 0 inside a wall (down to
// -thickness/2 on the centre line). normal points from the wall into free space: (p - q)/|p - q| for
// q the closest point of the wall's segment. On the segment itself (always so for a point exactly on
// a zero-thickness wall) that direction is undefined and normal is the segment's left normal
// (b - a rotated +90 degrees), or +x for a zero-length wall; never NaN.
#pragma once

#include <vector>

#include "sim/env/geometry.h"

namespace vascsim {

struct WallHit {
  double distance = 0.0;         // m, signed, from the point to the wall surface (negative inside)
  Vec2 closest = Vec2::Zero();   // m, the closest point on that surface
  Vec2 normal = Vec2::UnitX();   // unit vector from the wall into free space, at the point
  int wall = -1;                 // index into the wall list
};

// The pure element function: point p against one wall. The field and the brute force both use it, so
// they agree to the last bit.
WallHit wall_hit(const WallSegment& wall, int index, const Vec2& p);

class WallDistanceField {
 public:
  // max_query_radius (m, >= 0): the largest radius later queries may ask for.
  WallDistanceField(const std::vector<WallSegment>& walls, double max_query_radius);

  // The nearest wall (smallest signed distance; the lowest index on a tie) whose surface is within
  // `radius` of p (distance <= radius). radius <= max_query_radius, else std::invalid_argument.
  // Returns false, leaving `hit` alone, if there is none.
  bool nearest(const Vec2& p, double radius, WallHit& hit) const;
  // Every wall whose surface is within `radius` of p, in wall index order; clears `hits` first.
  void near(const Vec2& p, double radius, std::vector<WallHit>& hits) const;

  // A superset of near()'s walls, found without computing any hit: for callers that compute
  // their own distance (with derivatives) anyway. Clears `walls` first; ascending indices.
  void candidates(const Vec2& p, double radius, std::vector<int>& walls) const;

  // Reference: loop over every wall, no radius limit. False only if `walls` is empty.
  static bool nearest_brute_force(const std::vector<WallSegment>& walls, const Vec2& p, WallHit& hit);

  double max_query_radius() const { return max_query_radius_; }
  const std::vector<WallSegment>& walls() const { return walls_; }
  // Grid size, for the benchmark and the docs: buckets along x and y, and bucket edge (m).
  int buckets_x() const { return nx_; }
  int buckets_y() const { return ny_; }
  double bucket_size() const { return cell_; }

 private:
  int bucket_of(const Vec2& p) const;                // -1 outside the grid
  // Cheap rejection before wall_hit (no sqrt, no division): true if wall i's surface is surely
  // farther than radius from p. Most walls of a bucket are, for contact-sized radii.
  bool beyond(int i, const Vec2& p, double radius) const;
  struct Axis {
    Vec2 a, d;               // m, segment start and b - a
    double inverse_length2;  // 1/m^2, 0 for a point wall
    double half_thickness;   // m
  };
  void check_radius(double radius) const;

  std::vector<WallSegment> walls_;
  std::vector<Axis> axes_;         // per wall, for beyond()
  double max_query_radius_ = 0.0;  // m
  Vec2 origin_ = Vec2::Zero();     // m, lower-left corner of bucket (0, 0)
  double cell_ = 1.0;              // m, bucket edge
  int nx_ = 0, ny_ = 0;            // buckets along x, y
  std::vector<int> bucket_begin_;  // nx*ny + 1 offsets into bucket_walls_ (CSR)
  std::vector<int> bucket_walls_;  // wall indices, ascending within each bucket
};

}  // namespace vascsim

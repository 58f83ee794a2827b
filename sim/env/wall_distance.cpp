#include "sim/env/wall_distance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vascsim {

namespace {

// Below this squared distance (m^2) the point is taken to be on the segment and the normal falls
// back to the left normal: dividing by a distance whose square underflows would not give a unit vector.
constexpr double kOnSegmentSquared = 1e-200;
// Limits the grid to ~0.26 M buckets (1 MB of offsets) when the query radius is tiny against the maze.
constexpr int kMaxBucketsPerAxis = 512;

}  // namespace

// Closest point of segment a-b: q = a + t (b - a), t = clamp(((p - a).(b - a)) / |b - a|^2, 0, 1).
// Capsule of radius r = thickness/2: signed distance |p - q| - r, surface point q + r n.
WallHit wall_hit(const WallSegment& wall, int index, const Vec2& p) {
  const Vec2 d = wall.b - wall.a;
  const double len2 = d.squaredNorm();
  double t = 0.0;
  if (len2 > 0.0) t = std::clamp((p - wall.a).dot(d) / len2, 0.0, 1.0);
  const Vec2 q = wall.a + t * d;
  const Vec2 diff = p - q;
  const double dist2 = diff.squaredNorm();
  WallHit hit;
  hit.wall = index;
  double dist = 0.0;
  if (dist2 > kOnSegmentSquared) {
    dist = std::sqrt(dist2);
    hit.normal = diff / dist;
  } else if (len2 > 0.0) {
    hit.normal = Vec2(-d.y(), d.x()) / std::sqrt(len2);
  } else {
    hit.normal = Vec2::UnitX();
  }
  const double r = 0.5 * wall.thickness;
  hit.distance = dist - r;
  hit.closest = q + r * hit.normal;
  return hit;
}

WallDistanceField::WallDistanceField(const std::vector<WallSegment>& walls, double max_query_radius)
    : walls_(walls), max_query_radius_(max_query_radius) {
  if (!(max_query_radius >= 0.0) || !std::isfinite(max_query_radius))
    throw std::invalid_argument("WallDistanceField: max_query_radius must be finite and >= 0, got " +
                                std::to_string(max_query_radius));
  if (walls_.empty()) return;
  for (const auto& w : walls_) {
    const Vec2 d = w.b - w.a;
    const double len2 = d.squaredNorm();
    axes_.push_back({w.a, d, len2 > 0.0 ? 1.0 / len2 : 0.0, 0.5 * w.thickness});
  }

  // A wall can matter to a point only within reach = thickness/2 + max_query_radius of its segment.
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  for (const auto& w : walls_) {
    if (!w.a.allFinite() || !w.b.allFinite() || !(w.thickness >= 0.0) || !std::isfinite(w.thickness))
      throw std::invalid_argument("WallDistanceField: wall with a non-finite point or a bad thickness");
    const double reach = 0.5 * w.thickness + max_query_radius_;
    lo = lo.cwiseMin(w.a.cwiseMin(w.b) - Vec2::Constant(reach));
    hi = hi.cwiseMax(w.a.cwiseMax(w.b) + Vec2::Constant(reach));
  }
  // Bucket edge about the query radius: a bucket then holds only the walls near it. Never so small
  // that the grid exceeds kMaxBucketsPerAxis, never zero.
  const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  cell_ = std::max({max_query_radius_, extent / (kMaxBucketsPerAxis - 2), 1e-9});
  // Half a bucket of margin on every side, so a point on the edge of the reachable box is inside.
  origin_ = lo - Vec2::Constant(0.5 * cell_);
  nx_ = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell_)) + 1;
  ny_ = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell_)) + 1;

  // Two passes (count, then fill) into compressed rows. A wall goes into every bucket whose centre is
  // within reach + half a bucket diagonal of its segment: conservative (any point of the bucket within
  // reach qualifies) yet tight for long diagonal walls, whose bounding box would cover far buckets.
  const double half_diagonal = (0.5 * std::sqrt(2.0) + 1e-9) * cell_;  // + rounding margin
  std::vector<int> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  std::vector<int> fill;
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < static_cast<int>(walls_.size()); ++i) {
      const auto& w = walls_[static_cast<std::size_t>(i)];
      const double reach = 0.5 * w.thickness + max_query_radius_;
      const Vec2 wlo = (w.a.cwiseMin(w.b) - Vec2::Constant(reach) - origin_) / cell_;
      const Vec2 whi = (w.a.cwiseMax(w.b) + Vec2::Constant(reach) - origin_) / cell_;
      const int x0 = std::max(0, static_cast<int>(wlo.x())), x1 = std::min(nx_ - 1, static_cast<int>(whi.x()));
      const int y0 = std::max(0, static_cast<int>(wlo.y())), y1 = std::min(ny_ - 1, static_cast<int>(whi.y()));
      WallSegment axis = w;
      axis.thickness = 0.0;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const Vec2 centre = origin_ + cell_ * Vec2(x + 0.5, y + 0.5);
          if (wall_hit(axis, i, centre).distance > reach + half_diagonal) continue;
          const int b = y * nx_ + x;
          if (pass == 0) ++count[static_cast<std::size_t>(b) + 1];
          else bucket_walls_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = i;
        }
    }
    if (pass == 0) {
      for (std::size_t b = 1; b < count.size(); ++b) count[b] += count[b - 1];
      bucket_begin_ = count;
      fill.assign(count.begin(), count.end() - 1);
      bucket_walls_.assign(static_cast<std::size_t>(count.back()), 0);
    }
  }
}

int WallDistanceField::bucket_of(const Vec2& p) const {
  // Compare in double before converting: a far or NaN point must not overflow the integer cast.
  const double fx = (p.x() - origin_.x()) / cell_, fy = (p.y() - origin_.y()) / cell_;
  if (!(fx >= 0.0 && fx < nx_ && fy >= 0.0 && fy < ny_)) return -1;
  return static_cast<int>(fy) * nx_ + static_cast<int>(fx);
}

void WallDistanceField::check_radius(double radius) const {
  if (radius > max_query_radius_)
    throw std::invalid_argument("WallDistanceField: query radius " + std::to_string(radius) +
                                " m exceeds max_query_radius " + std::to_string(max_query_radius_) + " m");
}

bool WallDistanceField::beyond(int i, const Vec2& p, double radius) const {
  const Axis& w = axes_[static_cast<std::size_t>(i)];
  const Vec2 ap = p - w.a;
  const double t = std::clamp(ap.dot(w.d) * w.inverse_length2, 0.0, 1.0);
  const double reach = radius + w.half_thickness;
  // Conservative against wall_hit's own rounding (it divides where this multiplies): a slack
  // relative to the coordinates' size, so a point exactly on a line wall is never rejected. A
  // negative reach (radius < -thickness/2) keeps everything for the exact test to decide.
  const double slack = 1e-20 * (ap.squaredNorm() + w.d.squaredNorm());
  return reach >= 0.0 && (ap - t * w.d).squaredNorm() > reach * reach * (1.0 + 1e-9) + slack;
}

bool WallDistanceField::nearest(const Vec2& p, double radius, WallHit& hit) const {
  check_radius(radius);
  const int b = bucket_of(p);
  if (b < 0) return false;
  bool found = false;
  WallHit best;
  for (int k = bucket_begin_[static_cast<std::size_t>(b)]; k < bucket_begin_[static_cast<std::size_t>(b) + 1]; ++k) {
    const int i = bucket_walls_[static_cast<std::size_t>(k)];
    if (beyond(i, p, radius)) continue;
    const WallHit h = wall_hit(walls_[static_cast<std::size_t>(i)], i, p);
    // Indices ascend within a bucket, so strict < keeps the lowest index on a tie, like the brute force.
    if (h.distance <= radius && (!found || h.distance < best.distance)) {
      best = h;
      found = true;
    }
  }
  if (found) hit = best;
  return found;
}

void WallDistanceField::near(const Vec2& p, double radius, std::vector<WallHit>& hits) const {
  check_radius(radius);
  hits.clear();
  const int b = bucket_of(p);
  if (b < 0) return;
  for (int k = bucket_begin_[static_cast<std::size_t>(b)]; k < bucket_begin_[static_cast<std::size_t>(b) + 1]; ++k) {
    const int i = bucket_walls_[static_cast<std::size_t>(k)];
    if (beyond(i, p, radius)) continue;
    const WallHit h = wall_hit(walls_[static_cast<std::size_t>(i)], i, p);
    if (h.distance <= radius) hits.push_back(h);
  }
}

void WallDistanceField::candidates(const Vec2& p, double radius, std::vector<int>& walls) const {
  check_radius(radius);
  walls.clear();
  const int b = bucket_of(p);
  if (b < 0) return;
  for (int k = bucket_begin_[static_cast<std::size_t>(b)]; k < bucket_begin_[static_cast<std::size_t>(b) + 1]; ++k) {
    const int i = bucket_walls_[static_cast<std::size_t>(k)];
    if (!beyond(i, p, radius)) walls.push_back(i);
  }
}

bool WallDistanceField::nearest_brute_force(const std::vector<WallSegment>& walls, const Vec2& p, WallHit& hit) {
  bool found = false;
  WallHit best;
  for (int i = 0; i < static_cast<int>(walls.size()); ++i) {
    const WallHit h = wall_hit(walls[static_cast<std::size_t>(i)], i, p);
    if (!found || h.distance < best.distance) {
      best = h;
      found = true;
    }
  }
  if (found) hit = best;
  return found;
}

}  // namespace vascsim

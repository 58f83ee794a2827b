#include "sim/contact/contact_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vascsim {

namespace {

std::vector<WallSegment> wall_corners(const std::vector<WallSegment>& walls) {
  std::vector<WallSegment> corners;
  auto add = [&](const Vec2& p, double thickness) {
    for (const auto& c : corners)
      if (c.a == p && c.thickness == thickness) return;
    corners.push_back({p, p, thickness});
  };
  for (const auto& w : walls) {
    add(w.a, w.thickness);
    add(w.b, w.thickness);
  }
  return corners;
}

}  // namespace

ContactGeometry::ContactGeometry(const std::vector<WallSegment>& walls, double rod_radius, double reach,
                                 double max_edge_length)
    : walls_(walls),
      corners_(wall_corners(walls)),
      rod_radius_(rod_radius),
      reach_(reach),
      max_edge_length_(max_edge_length),
      // Twice the contact distance: half the rebuilds of one contact distance for lists a little
      // longer, whose extra pairs cost one distance each (for_each_pair drops them before their
      // derivatives). maze_body_drag at fast: 2.5 % fewer instructions; three times: 2.5 % more on
      // vessel_tree (many short wall segments).
      skin_(2.0 * (rod_radius + reach)),
      // Queries reach a little beyond the barrier so max_step_fraction can see walls ahead.
      wall_field_(walls, 4.0 * (rod_radius + reach) + max_edge_length),
      corner_field_(corners_, 4.0 * (rod_radius + reach) + max_edge_length) {}

double ContactGeometry::refresh_neighbours(const Eigen::VectorXd& x, ContactNeighbours& c) const {
  const int nodes = static_cast<int>(x.size() / 2);
  if (c.anchor.size() == x.size()) {
    double drift2 = 0.0;
    for (int i = 0; i < nodes; ++i) drift2 = std::max(drift2, (x.segment<2>(2 * i) - c.anchor.segment<2>(2 * i)).squaredNorm());
    if (drift2 <= 0.25 * skin_ * skin_) return drift2;
  }
  // Every pair within reach at any x whose nodes lie within skin/2 of the anchor is listed: a
  // node (or any point of an edge) moves at most skin/2, so its distance to a wall changes by at
  // most that much. max_step_fraction also reads the lists for moves up to reach + skin/2; an
  // edge's midpoint and half-length each drift by skin/2, hence the edges' extra skin/2.
  c.anchor = x;
  c.node_begin.assign(1, 0);
  c.node_walls.clear();
  c.edge_begin.assign(1, 0);
  c.edge_corners.clear();
  c.node_clearance.assign(static_cast<std::size_t>(nodes), std::numeric_limits<double>::infinity());
  c.edge_clearance.assign(static_cast<std::size_t>(std::max(nodes - 1, 0)), std::numeric_limits<double>::infinity());
  std::vector<int> found;
  for (int i = 0; i < nodes; ++i) {
    const Vec2 p = x.segment<2>(2 * i);
    wall_field_.candidates(p, rod_radius_ + reach_ + skin_, found);
    c.node_walls.insert(c.node_walls.end(), found.begin(), found.end());
    c.node_begin.push_back(static_cast<int>(c.node_walls.size()));
    double& clearance = c.node_clearance[static_cast<std::size_t>(i)];
    for (const int w : found)
      clearance = std::min(clearance, wall_hit(walls_[static_cast<std::size_t>(w)], w, p).distance - rod_radius_);
  }
  for (int i = 0; i + 1 < nodes; ++i) {
    const Vec2 a = x.segment<2>(2 * i), b = x.segment<2>(2 * i + 2);
    edge_corner_candidates(a, b, rod_radius_ + reach_ + 1.5 * skin_, found);
    c.edge_corners.insert(c.edge_corners.end(), found.begin(), found.end());
    c.edge_begin.push_back(static_cast<int>(c.edge_corners.size()));
    double& clearance = c.edge_clearance[static_cast<std::size_t>(i)];
    for (const int k : found) {
      const WallSegment& corner = corners_[static_cast<std::size_t>(k)];
      clearance = std::min(clearance, point_segment_distance_value(corner.a, a, b) - 0.5 * corner.thickness - rod_radius_);
    }
  }
  return 0.0;
}

void ContactGeometry::for_each_pair(const Eigen::VectorXd& x, bool with_hessian,
                                    const std::function<void(const ContactPair&)>& visit, ContactNeighbours& c,
                                    bool nodes_only) const {
  const int nodes = static_cast<int>(x.size() / 2);
  refresh_neighbours(x, c);
  ContactPair pair;
  for (int i = 0; i < nodes; ++i) {
    const Vec2 p = x.segment<2>(2 * i);
    for (int k = c.node_begin[static_cast<std::size_t>(i)]; k < c.node_begin[static_cast<std::size_t>(i) + 1]; ++k) {
      const WallSegment& w = walls_[static_cast<std::size_t>(c.node_walls[static_cast<std::size_t>(k)])];
      if (point_segment_distance_value(p, w.a, w.b) - 0.5 * w.thickness - rod_radius_ >= reach_) continue;
      pair.first_dof = 2 * i;
      pair.is_edge = false;
      pair.geometry = point_segment_distance(p, w.a, w.b, with_hessian);
      pair.gap = pair.geometry.distance - 0.5 * w.thickness - rod_radius_;
      pair.normal = pair.geometry.gradient.head<2>();
      if (pair.gap < reach_) visit(pair);
    }
  }
  if (nodes_only) return;
  for (int i = 0; i + 1 < nodes; ++i) {
    const Vec2 a = x.segment<2>(2 * i), b = x.segment<2>(2 * i + 2);
    for (int k = c.edge_begin[static_cast<std::size_t>(i)]; k < c.edge_begin[static_cast<std::size_t>(i) + 1]; ++k) {
      const WallSegment& corner = corners_[static_cast<std::size_t>(c.edge_corners[static_cast<std::size_t>(k)])];
      if (point_segment_distance_value(corner.a, a, b) - 0.5 * corner.thickness - rod_radius_ >= reach_) continue;
      pair.first_dof = 2 * i;
      pair.is_edge = true;
      pair.geometry = point_segment_distance(corner.a, a, b, with_hessian);
      pair.gap = pair.geometry.distance - 0.5 * corner.thickness - rod_radius_;
      pair.normal = -pair.geometry.gradient.head<2>();  // from the corner towards the edge
      if (pair.gap < reach_) visit(pair);
    }
  }
}

void ContactGeometry::edge_corner_candidates(const Vec2& a, const Vec2& b, double margin, std::vector<int>& found) const {
  const double radius = 0.5 * (b - a).norm() + margin;
  if (radius <= corner_field_.max_query_radius()) {
    corner_field_.candidates(0.5 * (a + b), radius, found);
    return;
  }
  // The grid is sized for the rod's longest rest edge; an edge stretched far beyond it (or a
  // search wider than the grid's) checks every corner rather than miss one.
  found.resize(corners_.size());
  for (std::size_t k = 0; k < corners_.size(); ++k) found[k] = static_cast<int>(k);
}

double ContactGeometry::min_gap(const Eigen::VectorXd& x, double search) const {
  double gap = std::numeric_limits<double>::infinity();
  const int nodes = static_cast<int>(x.size() / 2);
  const double radius = std::min(search + rod_radius_, wall_field_.max_query_radius());
  WallHit hit;
  for (int i = 0; i < nodes; ++i)
    if (wall_field_.nearest(x.segment<2>(2 * i), radius, hit)) gap = std::min(gap, hit.distance - rod_radius_);
  std::vector<int> found;
  for (int i = 0; i + 1 < nodes; ++i) {
    const Vec2 a = x.segment<2>(2 * i), b = x.segment<2>(2 * i + 2);
    edge_corner_candidates(a, b, radius, found);
    for (const int k : found) {
      const WallSegment& c = corners_[static_cast<std::size_t>(k)];
      gap = std::min(gap, point_segment_distance_value(c.a, a, b) - 0.5 * c.thickness - rod_radius_);
    }
  }
  return gap;
}

double ContactGeometry::min_pair_gap(const Eigen::VectorXd& x, ContactNeighbours& c) const {
  refresh_neighbours(x, c);
  double gap = std::numeric_limits<double>::infinity();
  const int nodes = static_cast<int>(x.size() / 2);
  for (int i = 0; i < nodes; ++i) {
    const Vec2 p = x.segment<2>(2 * i);
    for (int k = c.node_begin[static_cast<std::size_t>(i)]; k < c.node_begin[static_cast<std::size_t>(i) + 1]; ++k) {
      const WallSegment& w = walls_[static_cast<std::size_t>(c.node_walls[static_cast<std::size_t>(k)])];
      gap = std::min(gap, point_segment_distance_value(p, w.a, w.b) - 0.5 * w.thickness - rod_radius_);
    }
  }
  for (int i = 0; i + 1 < nodes; ++i) {
    const Vec2 a = x.segment<2>(2 * i), b = x.segment<2>(2 * i + 2);
    for (int k = c.edge_begin[static_cast<std::size_t>(i)]; k < c.edge_begin[static_cast<std::size_t>(i) + 1]; ++k) {
      const WallSegment& corner = corners_[static_cast<std::size_t>(c.edge_corners[static_cast<std::size_t>(k)])];
      gap = std::min(gap, point_segment_distance_value(corner.a, a, b) - 0.5 * corner.thickness - rod_radius_);
    }
  }
  // The lists hold every pair within reach and some beyond it.
  return gap < reach_ ? gap : std::numeric_limits<double>::infinity();
}

double ContactGeometry::max_step_fraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx, double safety,
                                          ContactNeighbours& c) const {
  const int nodes = static_cast<int>(x.size() / 2);
  // Limit the move so that every wall it could reach is inside the query radius.
  const double reach_limit = 0.5 * wall_field_.max_query_radius() - rod_radius_;
  // Moves within the neighbour lists' margin (the usual Newton update) need no grid search: x is
  // within skin/2 of the anchor, so every wall within move + r of a node is on its list.
  const double drift2 = refresh_neighbours(x, c);
  double alpha = 1.0;
  std::vector<double> move2(static_cast<std::size_t>(nodes));  // m^2, of the full move
  for (int i = 0; i < nodes; ++i) {
    move2[static_cast<std::size_t>(i)] = dx.segment<2>(2 * i).squaredNorm();
    if (move2[static_cast<std::size_t>(i)] > reach_limit * reach_limit)
      alpha = std::min(alpha, reach_limit / std::sqrt(move2[static_cast<std::size_t>(i)]));
  }
  const double listed_move = reach_ + 0.5 * skin_;
  // A move within a `safety` share of every gap it could close cuts nothing. Most nodes in most
  // Newton updates are such: passing over them, on a lower bound of their gaps (the lists'
  // clearance less the rod's largest drift from the anchor; walls off the lists are at least
  // listed_move away) and without a square root, took a third of this function's cost away
  // (maze_default). The slack covers round-off.
  const double drift = std::sqrt(drift2);
  const auto no_cut = [&](double full_move2, double clearance) {
    const double bound = safety * (std::min(clearance - drift, listed_move) - 1e-15);
    return bound > 0.0 && alpha * alpha * full_move2 <= bound * bound;
  };
  WallHit hit;
  for (int i = 0; i < nodes; ++i) {
    if (move2[static_cast<std::size_t>(i)] == 0.0 || no_cut(move2[static_cast<std::size_t>(i)], c.node_clearance[static_cast<std::size_t>(i)])) continue;
    const double move = alpha * dx.segment<2>(2 * i).norm();
    if (move == 0.0) continue;
    const Vec2 p = x.segment<2>(2 * i);
    double gap = std::numeric_limits<double>::infinity();
    // The closest the node comes to a listed wall along its move (exact for a straight move).
    double path_gap = std::numeric_limits<double>::infinity();
    if (move <= listed_move) {
      const Vec2 end = p + alpha * dx.segment<2>(2 * i);
      for (int k = c.node_begin[static_cast<std::size_t>(i)]; k < c.node_begin[static_cast<std::size_t>(i) + 1]; ++k) {
        const int w = c.node_walls[static_cast<std::size_t>(k)];
        const WallSegment& wall = walls_[static_cast<std::size_t>(w)];
        const double distance = wall_hit(wall, w, p).distance;
        if (distance > move + rod_radius_) continue;  // as nearest() would
        gap = std::min(gap, distance - rod_radius_);
        path_gap = std::min(path_gap, segment_segment_distance(p, end, wall.a, wall.b) - 0.5 * wall.thickness - rod_radius_);
      }
    } else if (wall_field_.nearest(p, move + rod_radius_, hit)) {
      gap = hit.distance - rod_radius_;
      path_gap = -1.0;  // not computed: the bound below
    }
    // Keep a `safety` share of the gap all along the move. A move that slides past the walls
    // keeps it whatever its length; otherwise the gap shrinks at most as fast as the node moves.
    if (move > safety * gap && path_gap < (1.0 - safety) * gap)
      alpha = std::min(alpha, safety * gap / dx.segment<2>(2 * i).norm());
  }
  std::vector<int> listed;
  for (int i = 0; i + 1 < nodes; ++i) {
    const double edge_move2 = std::max(move2[static_cast<std::size_t>(i)], move2[static_cast<std::size_t>(i) + 1]);
    if (edge_move2 == 0.0 || no_cut(edge_move2, c.edge_clearance[static_cast<std::size_t>(i)])) continue;
    const double move = alpha * std::max(dx.segment<2>(2 * i).norm(), dx.segment<2>(2 * i + 2).norm());
    if (move == 0.0) continue;
    const Vec2 a = x.segment<2>(2 * i), b = x.segment<2>(2 * i + 2);
    const int* first = nullptr;
    const int* last = nullptr;
    if (move <= listed_move) {
      first = c.edge_corners.data() + c.edge_begin[static_cast<std::size_t>(i)];
      last = c.edge_corners.data() + c.edge_begin[static_cast<std::size_t>(i) + 1];
    } else {
      edge_corner_candidates(a, b, move + rod_radius_, listed);
      first = listed.data();
      last = listed.data() + listed.size();
    }
    const double radius = 0.5 * (b - a).norm() + move + rod_radius_;
    const Vec2 a_end = a + alpha * dx.segment<2>(2 * i), b_end = b + alpha * dx.segment<2>(2 * i + 2);
    for (const int* k = first; k != last; ++k) {
      const WallSegment& corner = corners_[static_cast<std::size_t>(*k)];
      if (wall_hit(corner, *k, 0.5 * (a + b)).distance > radius) continue;  // as near() would
      const double gap = point_segment_distance_value(corner.a, a, b) - 0.5 * corner.thickness - rod_radius_;
      if (move <= safety * gap) continue;
      // The edge sweeps a region inside the hull of its two positions: a corner that stays far
      // enough from that hull keeps its gap whatever the move's length.
      const double swept = point_hull_distance(corner.a, a, b, a_end, b_end) - 0.5 * corner.thickness - rod_radius_;
      if (swept < (1.0 - safety) * gap) alpha = std::min(alpha, safety * gap * alpha / move);
    }
  }
  return std::max(alpha, 0.0);
}

}  // namespace vascsim

// The rod-wall contact pairs, shared by the contact barrier and friction. Two kinds, as in IPC's
// 2D constraint set (Li et al. 2020):
//   - node-wall: a rod node against a wall capsule; gap = |p - segment| - thickness/2 - r;
//   - corner-edge: a wall end (a round cap of radius thickness/2) against a rod edge; this is what
//     stops an edge from cutting a convex wall corner between two nodes (the paper's Fig. 14
//     shows the rod crossing a wall at a corner).
// Where a corner's nearest rod point is a node both kinds see it; the double count only stiffens
// that contact and never changes where equilibrium lies, since every force is a gradient.
#pragma once

#include <functional>
#include <vector>

#include "sim/contact/point_segment_distance.h"
#include "sim/env/wall_distance.h"

namespace vascsim {

struct ContactPair {
  int first_dof = 0;     // first degree of freedom of the rod node (node pair) or edge (corner pair)
  bool is_edge = false;  // corner-edge pair: derivatives over 4 dofs (edge ends); node pair: 2 dofs
  double gap = 0.0;      // m, surface-to-surface distance
  PointSegmentDistance geometry;  // derivatives of the centre distance (6 coordinates: p, a, b)
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  // unit, from the wall towards the rod
};

// Verlet neighbour lists for one user of a ContactGeometry: the walls near each node and the
// corners near each edge, found in the grids for an anchor configuration with a margin (the
// skin), and reused until some node has moved skin/2 from the anchor. A step moves the rod far
// less than that, so the Newton iterations of many steps share one grid search. Per-run state
// (a module keeps its lists in its Workspace cache), so the geometry itself stays const and
// shareable.
struct ContactNeighbours {
  Eigen::VectorXd anchor;                     // m, positions the lists were built for
  std::vector<int> node_begin, node_walls;    // CSR: walls near node i
  std::vector<int> edge_begin, edge_corners;  // CSR: corners near edge i
  // m, at the anchor: the smallest gap of node i to its listed walls and of edge i to its listed
  // corners (+inf if none). A node (or an edge's end) that has moved d from the anchor has no gap
  // below clearance - d, which lets the step cap pass over the nodes far from every wall.
  std::vector<double> node_clearance, edge_clearance;
};

// The walls and their corners, with grids for distance queries: immutable after construction,
// built once per run and shared by contact, friction and the run's gap statistics.
class ContactGeometry {
 public:
  // walls: the environment; rod_radius, reach: pairs are reported while gap < reach (m).
  ContactGeometry(const std::vector<WallSegment>& walls, double rod_radius, double reach, double max_edge_length);

  // Calls `visit` for every pair with gap < reach at positions x (2N). With `with_hessian` false
  // the pair's Hessian is not computed.
  // `nodes_only` skips the corner-edge pairs (friction acts on node pairs only).
  // `neighbours` are the caller's lists, refreshed here when x has moved too far from them.
  void for_each_pair(const Eigen::VectorXd& x, bool with_hessian, const std::function<void(const ContactPair&)>& visit,
                     ContactNeighbours& neighbours, bool nodes_only = false) const;
  // The smallest gap of any node or edge against any wall within `search` (m) of it, or +inf.
  double min_gap(const Eigen::VectorXd& x, double search) const;
  // The smallest gap of the pairs for_each_pair would visit (gap < reach), or +inf: distances
  // only, for the checks that need no force (a frame's gaps, the run's statistics).
  double min_pair_gap(const Eigen::VectorXd& x, ContactNeighbours& neighbours) const;
  // Largest fraction of the move x -> x + dx that keeps every gap positive, shrunk by `safety`
  // (conservative: a distance changes no faster than the points that define it move).
  double max_step_fraction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx, double safety,
                           ContactNeighbours& neighbours) const;

  double rod_radius() const { return rod_radius_; }

 private:
  // Rebuilds the lists when a node of x has drifted more than skin/2 from their anchor. Returns
  // the largest squared drift (m^2) of a node from the anchor the lists now have: 0 after a rebuild.
  double refresh_neighbours(const Eigen::VectorXd& x, ContactNeighbours& c) const;
  // Corners (indices into corners_) whose capsule may lie within `margin` (m) of edge ab: a
  // superset, from the corner grid around the midpoint.
  void edge_corner_candidates(const Vec2& a, const Vec2& b, double margin, std::vector<int>& found) const;

  std::vector<WallSegment> walls_;
  std::vector<WallSegment> corners_;  // zero-length capsules at the wall ends, deduplicated
  double rod_radius_;
  double reach_;
  double max_edge_length_;
  double skin_;  // m, neighbour-list margin
  WallDistanceField wall_field_;
  WallDistanceField corner_field_;
};

}  // namespace vascsim

// Distance from a point to a segment, with its gradient and Hessian with respect to all six
// coordinates (point p, segment ends a and b). Contact uses it both ways round: a rod node
// against a fixed wall segment (only the p-derivatives matter) and a fixed wall corner against a
// moving rod edge (only the a- and b-derivatives matter).
//
// The distance to a convex set is C1 away from the set (Danskin), so the three cases below
// (closest point at a, at b, or inside) join with a continuous gradient; the Hessian jumps where
// the case changes, which Newton tolerates.
#pragma once

#include <Eigen/Core>

namespace vascsim {

struct PointSegmentDistance {
  double distance = 0.0;             // m
  double parameter = 0.0;            // closest point = a + parameter (b - a), in [0, 1]
  Eigen::Matrix<double, 6, 1> gradient;  // d distance / d (px py ax ay bx by)
  Eigen::Matrix<double, 6, 6> hessian;   // symmetric
};

// Requires the point not to lie on the segment (distance > 0): contact keeps it there.
// With `with_hessian` false the Hessian is left zero (cheaper, for queries that need no Newton).
PointSegmentDistance point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                            const Eigen::Vector2d& b, bool with_hessian = true);

// The distance alone, bit for bit the one point_segment_distance returns: contact tests a pair
// against its reach with it before paying for the derivatives (most listed pairs are out of reach).
double point_segment_distance_value(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// The distance between segments [p0, p1] and [a, b] (0 if they cross or touch): the closest a
// point moving in a straight line from p0 to p1 comes to segment ab. Contact's step cap uses it
// to let a node slide along a wall instead of bounding the gap's shrinking by the whole move.
double segment_segment_distance(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b);

// The distance from p to the convex hull of q0..q3 (0 inside it). A segment whose ends move in
// straight lines from (q0, q1) to (q2, q3) stays inside that hull, so the step cap bounds from it
// how close a moving rod edge comes to a wall corner.
double point_hull_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& q0, const Eigen::Vector2d& q1,
                           const Eigen::Vector2d& q2, const Eigen::Vector2d& q3);

}  // namespace vascsim

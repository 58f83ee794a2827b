#include "sim/contact/point_segment_distance.h"

#include <algorithm>
#include <cmath>

namespace vascsim {

namespace {

using Mat2 = Eigen::Matrix2d;
using Vec2 = Eigen::Vector2d;

// Closest point at an end c of the segment: d = |p - c|. Only p and that end move d.
void endpoint_case(const Vec2& p, const Vec2& c, int end_block, bool with_hessian, PointSegmentDistance& out) {
  const Vec2 w = p - c;
  out.distance = w.norm();
  const Vec2 n = w / out.distance;
  out.gradient.setZero();
  out.gradient.segment<2>(0) = n;
  out.gradient.segment<2>(end_block) = -n;
  out.hessian.setZero();
  if (!with_hessian) return;
  const Mat2 h = (Mat2::Identity() - n * n.transpose()) / out.distance;
  out.hessian.block<2, 2>(0, 0) = h;
  out.hessian.block<2, 2>(end_block, end_block) = h;
  out.hessian.block<2, 2>(0, end_block) = -h;
  out.hessian.block<2, 2>(end_block, 0) = -h;
}

}  // namespace

double point_segment_distance_value(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const Vec2 w = p - a;
  const double beta = e.squaredNorm();
  const double alpha = w.dot(e);
  if (beta == 0.0 || alpha <= 0.0) return w.norm();
  if (alpha >= beta) return (p - b).norm();
  return std::sqrt(std::max(w.squaredNorm() - alpha * alpha / beta, 0.0));
}

namespace {

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

bool in_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const double s0 = cross(b - a, p - a), s1 = cross(c - b, p - b), s2 = cross(a - c, p - c);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

}  // namespace

// In the plane every point of the hull lies in a triangle of three of the points
// (Caratheodory), and the hull's edges are among the six segments between them, the others
// lying inside it, so outside the hull the nearest of the six is the distance.
double point_hull_distance(const Vec2& p, const Vec2& q0, const Vec2& q1, const Vec2& q2, const Vec2& q3) {
  if (in_triangle(p, q0, q1, q2) || in_triangle(p, q0, q1, q3) || in_triangle(p, q0, q2, q3) || in_triangle(p, q1, q2, q3))
    return 0.0;
  return std::min({point_segment_distance_value(p, q0, q1), point_segment_distance_value(p, q0, q2),
                   point_segment_distance_value(p, q0, q3), point_segment_distance_value(p, q1, q2),
                   point_segment_distance_value(p, q1, q3), point_segment_distance_value(p, q2, q3)});
}

double segment_segment_distance(const Vec2& p0, const Vec2& p1, const Vec2& a, const Vec2& b) {
  // Two segments in the plane that do not cross are closest at an end of one of them.
  const double d0 = cross(b - a, p0 - a), d1 = cross(b - a, p1 - a);
  const double d2 = cross(p1 - p0, a - p0), d3 = cross(p1 - p0, b - p0);
  if (((d0 > 0 && d1 < 0) || (d0 < 0 && d1 > 0)) && ((d2 > 0 && d3 < 0) || (d2 < 0 && d3 > 0))) return 0.0;
  return std::min(std::min(point_segment_distance_value(p0, a, b), point_segment_distance_value(p1, a, b)),
                  std::min(point_segment_distance_value(a, p0, p1), point_segment_distance_value(b, p0, p1)));
}

// Interior case. With w = p - a, e = b - a, alpha = w.e, beta = e.e, the squared distance is
//   f = w.w - alpha^2 / beta,
//   df/dw = 2 w - 2 alpha e / beta,          df/de = -2 alpha w / beta + 2 alpha^2 e / beta^2,
//   d2f/dw2 = 2 I - 2 e e^T / beta,
//   d2f/dw de = -2 (e w^T + alpha I) / beta + 4 alpha e e^T / beta^2,
//   d2f/de2 = -2 w w^T / beta + 4 alpha (w e^T + e w^T) / beta^2 - 8 alpha^2 e e^T / beta^3 + 2 alpha^2 I / beta^2,
// and d = sqrt(f): grad d = grad f / (2 d), hess d = hess f / (2 d) - grad f grad f^T / (4 d^3).
// (w, e) = T (p, a, b) with T = [[I, -I, 0], [0, -I, I]] maps both back to the six coordinates.
PointSegmentDistance point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b, bool with_hessian) {
  PointSegmentDistance out;
  const Vec2 e = b - a;
  const Vec2 w = p - a;
  const double beta = e.squaredNorm();
  const double alpha = w.dot(e);
  if (beta == 0.0 || alpha <= 0.0) {
    out.parameter = 0.0;
    endpoint_case(p, a, 2, with_hessian, out);
    return out;
  }
  if (alpha >= beta) {
    out.parameter = 1.0;
    endpoint_case(p, b, 4, with_hessian, out);
    return out;
  }
  out.parameter = alpha / beta;
  const double f = std::max(w.squaredNorm() - alpha * alpha / beta, 0.0);
  const double d = std::sqrt(f);
  out.distance = d;

  Eigen::Matrix<double, 4, 1> grad_we;
  grad_we.head<2>() = 2.0 * w - 2.0 * alpha * e / beta;
  grad_we.tail<2>() = -2.0 * alpha * w / beta + 2.0 * alpha * alpha * e / (beta * beta);
  Eigen::Matrix<double, 4, 6> T = Eigen::Matrix<double, 4, 6>::Zero();
  T.block<2, 2>(0, 0) = Mat2::Identity();
  T.block<2, 2>(0, 2) = -Mat2::Identity();
  T.block<2, 2>(2, 2) = -Mat2::Identity();
  T.block<2, 2>(2, 4) = Mat2::Identity();
  const Eigen::Matrix<double, 6, 1> grad_f = T.transpose() * grad_we;
  out.gradient = grad_f / (2.0 * d);
  out.hessian.setZero();
  if (!with_hessian) return out;

  const Mat2 I = Mat2::Identity();
  Eigen::Matrix4d hess_we;
  hess_we.block<2, 2>(0, 0) = 2.0 * I - 2.0 * e * e.transpose() / beta;
  const Mat2 we = -2.0 * (e * w.transpose() + alpha * I) / beta + 4.0 * alpha * e * e.transpose() / (beta * beta);
  hess_we.block<2, 2>(0, 2) = we;
  hess_we.block<2, 2>(2, 0) = we.transpose();
  hess_we.block<2, 2>(2, 2) = -2.0 * w * w.transpose() / beta +
                              4.0 * alpha * (w * e.transpose() + e * w.transpose()) / (beta * beta) -
                              8.0 * alpha * alpha * e * e.transpose() / (beta * beta * beta) +
                              2.0 * alpha * alpha * I / (beta * beta);
  const Eigen::Matrix<double, 6, 6> hess_f = T.transpose() * hess_we * T;
  out.hessian = hess_f / (2.0 * d) - grad_f * grad_f.transpose() / (4.0 * d * d * d);
  return out;
}

}  // namespace vascsim

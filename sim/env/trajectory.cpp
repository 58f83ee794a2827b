#include "sim/env/trajectory.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vascsim {

namespace {

constexpr double kPi = 3.14159265358979323846;

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

// Drops consecutive duplicates and straight-through points, which would otherwise take a share of
// their legs from the real corners. Tolerances are relative to the polyline's size. `radii` (one
// per point) follows the points kept.
Polyline clean(const Polyline& in, std::vector<double>& radii) {
  double scale = 0.0;
  for (std::size_t i = 1; i < in.size(); ++i) scale += (in[i] - in[i - 1]).norm();
  const double same = 1e-12 * scale;
  Polyline out;
  std::vector<double> out_radii;
  for (std::size_t i = 0; i < in.size(); ++i)
    if (out.empty() || (in[i] - out.back()).norm() > same) out.push_back(in[i]), out_radii.push_back(radii[i]);
  Polyline kept;
  radii.clear();
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (i > 0 && i + 1 < out.size()) {
      const Vec2 u = (out[i] - kept.back()).normalized(), w = (out[i + 1] - out[i]).normalized();
      if (std::abs(cross(u, w)) <= 1e-12 && u.dot(w) > 0.0) continue;
    }
    kept.push_back(out[i]);
    radii.push_back(out_radii[i]);
  }
  return kept;
}

}  // namespace

Trajectory::Trajectory(const Polyline& corners, double corner_radius, double speed, double ramp_time)
    : Trajectory(corners, std::vector<double>(corners.size(), corner_radius), speed, ramp_time) {}

Trajectory::Trajectory(const Polyline& corners, const std::vector<double>& corner_radii, double speed, double ramp_time)
    : speed_(speed), peak_speed_(speed) {
  if (corners.empty()) throw std::invalid_argument("Trajectory: the polyline has no points");
  if (corner_radii.size() != corners.size())
    throw std::invalid_argument("Trajectory: one corner radius per polyline point expected");
  for (double r : corner_radii)
    if (!(r >= 0.0) || !std::isfinite(r)) throw std::invalid_argument("Trajectory: corner_radius must be finite and >= 0");
  if (!(speed > 0.0) || !std::isfinite(speed)) throw std::invalid_argument("Trajectory: speed must be finite and > 0");
  if (!(ramp_time >= 0.0) || !std::isfinite(ramp_time))
    throw std::invalid_argument("Trajectory: ramp_time must be finite and >= 0");
  for (const Vec2& p : corners)
    if (!p.allFinite()) throw std::invalid_argument("Trajectory: a polyline point is not finite");
  std::vector<double> radii = corner_radii;
  const Polyline p = clean(corners, radii);
  origin_ = p.front();
  const std::size_t n = p.size();
  if (n < 2) return;

  std::vector<double> leg(n - 1);  // m, leg i joins p[i] and p[i+1]
  for (std::size_t i = 0; i + 1 < n; ++i) leg[i] = (p[i + 1] - p[i]).norm();

  double s = 0.0;
  Vec2 at = p.front();  // where the next piece starts
  const auto add_line = [&](const Vec2& to) {
    const double len = (to - at).norm();
    if (len <= 0.0) return;
    Piece line;
    line.s0 = s;
    line.length = len;
    line.start = at;
    line.direction = (to - at) / len;
    pieces_.push_back(line);
    s += len;
    at = to;
  };
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Vec2 u = (p[i] - p[i - 1]) / leg[i - 1], w = (p[i + 1] - p[i]) / leg[i];
    const double theta = std::atan2(cross(u, w), u.dot(w));  // signed turn, rad
    const double half_tan = std::tan(0.5 * std::abs(theta));
    // A reversal has no finite tangent length: leave it sharp.
    const double corner_radius = radii[i];
    if (corner_radius == 0.0 || std::abs(theta) > kPi - 1e-9) {
      add_line(p[i]);
      continue;
    }
    const double room = std::min(i == 1 ? leg[i - 1] : 0.5 * leg[i - 1], i + 2 == n ? leg[i] : 0.5 * leg[i]);
    const double radius = std::min(corner_radius, room / half_tan);
    const double tangent = radius * half_tan;  // m, from the corner to each end of the arc
    add_line(p[i] - tangent * u);
    Piece arc;
    arc.s0 = s;
    arc.radius = radius;
    arc.turn = theta;
    arc.length = radius * std::abs(theta);
    arc.start = at;
    const Vec2 left(-u.y(), u.x());
    arc.centre = at + (theta > 0.0 ? radius : -radius) * left;
    arc.angle0 = std::atan2(at.y() - arc.centre.y(), at.x() - arc.centre.x());
    pieces_.push_back(arc);
    s += arc.length;
    at = p[i] + tangent * w;  // the arc's end, exactly on the outgoing leg
  }
  add_line(p.back());
  length_ = s;
  if (ramp_time > 0.0) {
    // Accelerating at speed / ramp_time over a distance of half the path reaches sqrt(a L).
    const double rate = speed_ / ramp_time;  // m/s^2
    peak_speed_ = std::min(speed_, std::sqrt(rate * length_));
    ramp_ = peak_speed_ / rate;
  }
  // Each ramp covers peak * ramp / 2, half of what cruising would: ramps add ramp_ in all.
  duration_ = length_ / peak_speed_ + ramp_;
}

Trajectory::Progress Trajectory::progress(double t) const {
  const double time = std::clamp(t, 0.0, duration_);
  Progress p;
  if (ramp_ > 0.0 && time < ramp_) {  // speeding up from rest
    const double rate = peak_speed_ / ramp_;
    p = {0.5 * rate * time * time, rate * time, rate};
  } else if (ramp_ > 0.0 && time > duration_ - ramp_) {  // slowing down to rest at the end
    const double rate = peak_speed_ / ramp_, left = duration_ - time;
    p = {length_ - 0.5 * rate * left * left, rate * left, -rate};
  } else {  // cruising; without ramps also past the end, where the velocity keeps its end value
    p = {peak_speed_ * (time - 0.5 * ramp_), peak_speed_, 0.0};
  }
  p.s = std::clamp(p.s, 0.0, length_);
  return p;
}

std::vector<double> Trajectory::breakpoints() const {
  std::vector<double> times = {0.0};
  if (ramp_ > 0.0) times.insert(times.end(), {ramp_, duration_ - ramp_});
  // Piece ends: the time law is monotone in t, so bisection finds when it reaches each.
  for (std::size_t k = 1; k < pieces_.size(); ++k) {
    double lo = 0.0, hi = duration_;
    for (int i = 0; i < 100 && hi - lo > 1e-12 * std::max(1.0, duration_); ++i) {
      const double mid = 0.5 * (lo + hi);
      (progress(mid).s < pieces_[k].s0 ? lo : hi) = mid;
    }
    times.push_back(hi);
  }
  times.push_back(duration_);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

double Trajectory::Piece::angle_at(double s) const {
  return angle0 + std::copysign(std::clamp(s - s0, 0.0, length) / radius, turn);
}

Vec2 Trajectory::direction_at(double s) const {
  const Piece& q = piece_at(s);
  if (q.radius == 0.0) return q.direction;
  const double phi = q.angle_at(s);
  return std::copysign(1.0, q.turn) * Vec2(-std::sin(phi), std::cos(phi));
}

Vec2 Trajectory::curvature_at(double s) const {
  const Piece& q = piece_at(s);
  if (q.radius == 0.0) return Vec2::Zero();
  const double phi = q.angle_at(s);
  return -Vec2(std::cos(phi), std::sin(phi)) / q.radius;
}

const Trajectory::Piece& Trajectory::piece_at(double s) const {
  // The last piece starting at or before s.
  const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s,
                                   [](double value, const Piece& piece) { return value < piece.s0; });
  return it == pieces_.begin() ? pieces_.front() : *(it - 1);
}

Vec2 Trajectory::position(double t) const {
  if (pieces_.empty()) return origin_;
  const double s = progress(t).s;
  const Piece& q = piece_at(s);
  if (q.radius == 0.0) return q.start + std::clamp(s - q.s0, 0.0, q.length) * q.direction;
  const double phi = q.angle_at(s);
  return q.centre + q.radius * Vec2(std::cos(phi), std::sin(phi));
}

Vec2 Trajectory::velocity(double t) const {
  if (pieces_.empty()) return Vec2::Zero();
  const Progress p = progress(t);
  return p.rate * direction_at(p.s);
}

Vec2 Trajectory::acceleration(double t) const {
  if (pieces_.empty()) return Vec2::Zero();
  const Progress p = progress(t);
  // Along the path s'' and centripetal s'^2 / R towards the arc centre.
  return p.rate_change * direction_at(p.s) + p.rate * p.rate * curvature_at(p.s);
}

Polyline Trajectory::sample(double max_chord_error) const {
  if (!(max_chord_error > 0.0)) throw std::invalid_argument("Trajectory::sample: max_chord_error must be > 0");
  Polyline out{origin_};
  for (const Piece& q : pieces_) {
    if (q.radius == 0.0) {
      out.push_back(q.start + q.length * q.direction);
      continue;
    }
    // A chord spanning angle a lies R (1 - cos(a/2)) from its arc at most.
    const double step = max_chord_error >= q.radius ? 0.5 * kPi : 2.0 * std::acos(1.0 - max_chord_error / q.radius);
    const int parts = std::max(1, static_cast<int>(std::ceil(std::abs(q.turn) / step)));
    for (int k = 1; k <= parts; ++k) {
      const double phi = q.angle0 + q.turn * k / parts;
      out.push_back(q.centre + q.radius * Vec2(std::cos(phi), std::sin(phi)));
    }
  }
  return out;
}

}  // namespace vascsim

// The reference motion of the tip: a polyline (the centreline, centreline.h) whose corners are
// rounded with circular arcs, traversed at constant speed. A tip cannot turn a sharp corner at finite
// speed without unbounded acceleration; with arcs the position is C1 (velocity continuous, |v| =
// speed) and the acceleration is v^2/R towards the arc centre on arcs and zero on straights.
//
// Start and stop: with ramp_time 0 the speed jumps from 0 to `speed` at t = 0 and back at the end
// (the paper's constant-speed reference; a tip at rest then meets an instant velocity error). With
// ramp_time T > 0 the speed rises at the constant rate speed / T from rest and falls at the same
// rate to rest at the end (a trapezoidal profile; a path too short to reach `speed` peaks lower),
// so velocity is continuous everywhere and the acceleration bounded by speed / T + speed^2 / R.
//
// Corner radius: each corner gets min(corner_radius, what fits). A corner turning by angle theta
// needs a tangent length R tan(|theta|/2) on both legs; a leg shared by two corners gives each half of
// itself, the first and last legs give all of themselves to their one corner. corner_radius 0, or a
// reversal (theta = 180 degrees), gives a sharp corner where the velocity jumps.
#pragma once

#include <vector>

#include "sim/env/geometry.h"

namespace vascsim {

class Trajectory {
 public:
  // One piece of the path: a straight line (radius == 0) or a circular arc.
  struct Piece {
    double s0 = 0.0;              // m, arc length along the path where the piece starts
    double length = 0.0;          // m
    Vec2 start = Vec2::Zero();    // m, first point
    Vec2 direction = Vec2::Zero();// line: unit direction of travel
    double radius = 0.0;          // m, arc radius; 0 for a line
    Vec2 centre = Vec2::Zero();   // m, arc centre
    double angle0 = 0.0;          // rad, polar angle of `start` about `centre`
    double turn = 0.0;            // rad, signed sweep, > 0 counter-clockwise (a left turn)
    // rad, polar angle about `centre` of the point at path length s (clamped to the arc).
    double angle_at(double s) const;
  };

  // corners: at least one point, m (consecutive duplicates and straight-through points are
  // dropped); corner_radius >= 0, m; speed > 0, m/s; ramp_time >= 0, s. Throws
  // std::invalid_argument otherwise.
  Trajectory(const Polyline& corners, double corner_radius, double speed, double ramp_time = 0.0);
  // Each corner its own largest radius: corner_radii[i] (m, >= 0) for corners[i] (the ends' values
  // are unused). A vessel network's lumen allows more rounding in a wide bend than in a narrow one.
  Trajectory(const Polyline& corners, const std::vector<double>& corner_radii, double speed, double ramp_time = 0.0);

  double length() const { return length_; }      // m
  double duration() const { return duration_; }  // s, length / speed, plus ramp_time with ramps
  double speed() const { return speed_; }        // m/s, the cruising speed asked for
  // At time t (s), clamped to [0, duration()]: past the end these stay at their end values
  // (without ramps the velocity does not drop to zero: a caller that stops at the goal checks
  // t >= duration(); with ramps it is zero there).
  // A single-point trajectory has zero velocity and acceleration.
  Vec2 position(double t) const;      // m
  Vec2 velocity(double t) const;      // m/s
  Vec2 acceleration(double t) const;  // m/s^2
  // A polyline through the path for drawing and logging: every piece end, and arcs divided so that
  // no chord is further than max_chord_error (m, > 0) from its arc.
  Polyline sample(double max_chord_error) const;

  const std::vector<Piece>& pieces() const { return pieces_; }
  // The times (s, sorted, from 0 to duration()) where the velocity or the acceleration jumps:
  // the start and the end, the ends of the ramps, and where one piece meets the next (the
  // centripetal acceleration starts or stops). A reference-following force is discontinuous
  // there, so error-controlled stepping ends a step on each and starts afresh.
  std::vector<double> breakpoints() const;

 private:
  const Piece& piece_at(double s) const;
  // The time law along the path at time t (clamped to [0, duration()]): arc length s (m), its
  // rate (m/s) and its second derivative (m/s^2).
  struct Progress {
    double s = 0.0, rate = 0.0, rate_change = 0.0;
  };
  Progress progress(double t) const;
  // Geometry at arc length s: unit direction of travel, and the curvature vector (1/m, towards
  // the arc centre, |k| = 1/R; zero on lines).
  Vec2 direction_at(double s) const;
  Vec2 curvature_at(double s) const;

  std::vector<Piece> pieces_;  // in order along the path; empty for a single point
  Vec2 origin_ = Vec2::Zero(); // m, the first point
  double length_ = 0.0;        // m
  double speed_ = 0.0;         // m/s, asked for
  double peak_speed_ = 0.0;    // m/s, reached: speed_, or less on a path too short for the ramps
  double ramp_ = 0.0;          // s, time to reach peak_speed_ from rest (0: no ramps)
  double duration_ = 0.0;      // s
};

}  // namespace vascsim

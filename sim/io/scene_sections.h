// Internal to the io layer: one reader and one writer per top-level scene section, each in its
// own file (read_<section>.cpp), so that a new part of the simulation adds a section without
// touching the others.
#pragma once

#include <nlohmann/json.hpp>

#include "sim/io/json_fields.h"
#include "sim/scene/scene.h"

namespace vascsim {
class Trajectory;
}

namespace vascsim::io {

// Scene geometry lies within 1000 m of the origin on each axis, as lengths and radii are at most
// 1000 m: a vessel lumen is built on a 0.1 um integer grid (sim/env/vessel_lumen.cpp), which a
// point far beyond would overflow, and a rod far from the origin has no digits left for its
// edges (a start at 1e20 m made every edge zero and the first step fail).
inline constexpr double kMaxCoordinate = 1e3;  // m
// Loads are bounded so that they stay finite once multiplied out (1e300 overflowed before the
// first step), far beyond any physical use.
inline constexpr double kMaxAcceleration = 1e4;  // m/s^2, about 1000 g
inline constexpr double kMaxForce = 1e6;         // N
inline constexpr double kMaxSpeed = 1e3;         // m/s

void read_maze(FieldReader& in, MazeSpec& out);
void read_vessels(FieldReader& in, VesselsSpec& out);
// The mask's pixels, from spec.resolved; fills width, height and pixel_hash. An InputError naming
// the scene file, `pointer` and the image if it is unreadable, not a PNG or over 8192 px a side.
std::vector<std::uint8_t> load_mask_pixels(VesselMaskSpec& spec, const std::string& scene_file, const std::string& pointer);
// The mask's pixels (size and grey levels) as 16 hex digits: the canonical scene carries it, so
// that a scene hash names the image too and a scene re-read from a log notices a changed image.
std::string mask_pixel_hash(int width, int height, const std::vector<std::uint8_t>& grey);
void read_path(FieldReader& in, PathSpec& out);
void read_rod(FieldReader& in, RodSpec& out);
void read_run(FieldReader& in, RunSpec& out);
void read_control(FieldReader& in, ControlSpec& out);
void read_contact(FieldReader& in, ContactSpec& out);
void read_shape(FieldReader& in, ShapeSpec& out);
void read_boundary(FieldReader& in, BoundarySpec& out);
void read_loads(FieldReader& in, LoadSpec& out);
void read_solver(FieldReader& in, SolverSpec& out);

nlohmann::json write_maze(const MazeSpec& spec);
nlohmann::json write_vessels(const VesselsSpec& spec);
nlohmann::json write_path(const PathSpec& spec);
nlohmann::json write_rod(const RodSpec& spec);
nlohmann::json write_run(const RunSpec& spec);
nlohmann::json write_control(const ControlSpec& spec);
// control.mode as a scene file names it; summary.json's navigation.control_mode too.
const char* actuation_mode_name(ActuationMode mode);
nlohmann::json write_contact(const ContactSpec& spec);
nlohmann::json write_shape(const ShapeSpec& spec);
nlohmann::json write_boundary(const BoundarySpec& spec);
nlohmann::json write_loads(const LoadSpec& spec);
nlohmann::json write_solver(const SolverSpec& spec);

nlohmann::json to_json(const Vec2& p);
nlohmann::json to_json(const Polyline& line);  // [[x, y], ...]
// The reference's timing and its points every 0.1 ms, as the maze and vessels documents give them
// under "path": length, speed, ramp_time, duration and samples.
nlohmann::json route_timing_json(const PathSpec& path, const Trajectory& trajectory);

}  // namespace vascsim::io

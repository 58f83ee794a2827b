#include "sim/io/scene_reader.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "sim/io/bounded_read.h"
#include "sim/io/file_kind.h"
#include "sim/env/trajectory.h"
#include "sim/io/scene_sections.h"
#include "sim/scene/input_error.h"
#include "sim/scene/unused_fields.h"

namespace vascsim {

using nlohmann::json;

Scene read_scene_text(const std::string& text, const std::string& label) {
  const json root = io::parse_json_strictly(text, label);
  Scene scene;
  scene.file = label;
  io::FieldReader in(root, label, "");
  io::check_format(root, "vascsim-scene/1", label);  // reserved for future format versions
  in.text("format", "vascsim-scene/1");
  scene.name = in.text("name", scene.name);
  in.text("description", "");
  // Each section has its reader in sim/io/read_<section>.cpp.
  const auto section = [&in](const char* key, auto reader, auto& spec) {
    io::FieldReader fields = in.object(key);
    reader(fields, spec);
  };
  if (in.has("vessels")) {
    if (in.has("maze")) in.fail("maze", "no \"maze\" beside \"vessels\" (a scene has one environment)", root["maze"]);
    scene.environment = EnvironmentKind::kVessels;
    section("vessels", io::read_vessels, scene.vessels);
  } else if (const json* maze = in.raw("maze"); maze && maze->is_null()) {
    scene.has_environment = false;
  } else {
    section("maze", io::read_maze, scene.maze);
  }
  // A vessel scene rounds each corner as far as its lumen allows; a corner_radius it gives caps that.
  if (scene.environment == EnvironmentKind::kVessels) scene.path.corner_radius = std::numeric_limits<double>::infinity();
  section("path", io::read_path, scene.path);
  section("rod", io::read_rod, scene.rod);
  section("run", io::read_run, scene.run);
  scene.run.duration_from_path = scene.has_environment && !(root.contains("run") && root["run"].contains("duration"));
  section("control", io::read_control, scene.control);
  section("contact", io::read_contact, scene.contact);
  section("shape", io::read_shape, scene.shape);
  section("boundary", io::read_boundary, scene.boundary);
  section("loads", io::read_loads, scene.loads);
  section("solver", io::read_solver, scene.solver);
  // A maze run places the rod at the maze's entry port; a shape there would be silently ignored.
  if (scene.has_environment && in.has("shape"))
    in.fail("shape", "no \"shape\" in a maze or vessel scene (the rod starts at the inlet, docs/navigation.md)",
            root["shape"]);
  // The tip controller follows the route through a maze or vessels: without one it would be
  // silently ignored (a fixed field on a tip magnet is `loads.magnet`, which needs no route).
  if (!scene.has_environment && in.has("control"))
    in.fail("control", "no \"control\" in a scene without a maze or vessels (the controller follows their route)",
            root["control"]);
  // The controller follows a trajectory in time; an equilibrium has no time to follow it in.
  if (scene.has_environment && scene.solver.mode == SolveMode::kStatic)
    in.object("solver").fail("mode", "\"dynamic\" in a maze scene (static equilibrium has no trajectory to follow)",
                             root["solver"]["mode"]);
  // Static mode solves under the loads' values at t = 0 (it ramps them itself): a ramp or sine
  // profile would be zero or meaningless there, so it is refused rather than silently dropped.
  if (scene.solver.mode == SolveMode::kStatic)
    for (std::size_t i = 0; i < scene.loads.point_loads.size(); ++i)
      if (scene.loads.point_loads[i].profile != LoadProfile::kConstant)
        io::FieldReader(root["loads"]["point"][i], in.file(), "/loads/point/" + std::to_string(i))
            .fail("profile", "\"constant\" with solver mode \"static\"", root["loads"]["point"][i]["profile"]);
  // A prescribed velocity moves a node in time; an equilibrium would hold it where it starts.
  if (scene.solver.mode == SolveMode::kStatic && !scene.boundary.prescribed.empty())
    in.object("boundary").fail("prescribed", "[] with solver mode \"static\" (no motion in an equilibrium; hold the node with \"pinned\")",
                               root["boundary"]["prescribed"]);
  // The static solver factorises the band only; self-contact's entries lie beyond it.
  if (scene.contact.self && scene.solver.mode == SolveMode::kStatic)
    in.object("contact").fail("self", "false with solver mode \"static\" (self-contact needs the dynamic solver)",
                              root["contact"]["self"]);
  const MagnetSpec& magnet = scene.loads.magnet;
  if (magnet.enabled && scene.solver.mode == SolveMode::kStatic && (magnet.ramp_time > 0 || magnet.rotation_rate != 0))
    io::FieldReader(root["loads"]["magnet"], in.file(), "/loads/magnet")
        .fail(magnet.ramp_time > 0 ? "ramp_time" : "rotation_rate", "0 with solver mode \"static\" (it solves under the field at t = 0)",
              root["loads"]["magnet"][magnet.ramp_time > 0 ? "ramp_time" : "rotation_rate"]);
  if (magnet.enabled && scene.has_environment && scene.control.mode == ActuationMode::kField)
    io::FieldReader(root["loads"], in.file(), "/loads")
        .fail("magnet", "no fixed-field magnet beside control mode \"field\" (the controller's field already turns the tip magnet)",
              root["loads"]["magnet"]);
  in.finish();
  for (UnusedField& u : unused_fields(scene))
    if (root.contains(json::json_pointer(u.pointer))) scene.unused_given.push_back(std::move(u));
  return scene;
}

Scene read_scene_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) throw InputError(path + ": is a directory, not a scene file");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(path + ": not a regular file (a scene is read from a file, not a device or a pipe)");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open scene file (" + std::strerror(errno) + ")");
  const std::string text = io::read_at_most(file, kMaxSceneBytes);
  if (file.bad()) throw InputError(path + ": cannot read scene file");
  if (text.size() > kMaxSceneBytes)
    throw InputError(path + ": larger than " + std::to_string(kMaxSceneBytes >> 20) + " MiB, the limit for a scene file");
  return read_scene_text(text, path);
}

namespace {

json scene_fields(const Scene& scene) {
  json root;
  root["format"] = "vascsim-scene/1";
  root["name"] = scene.name;
  if (scene.has_environment && scene.environment == EnvironmentKind::kVessels)
    root["vessels"] = io::write_vessels(scene.vessels);
  else
    root["maze"] = scene.has_environment ? io::write_maze(scene.maze) : json(nullptr);
  root["path"] = io::write_path(scene.path);
  root["rod"] = io::write_rod(scene.rod);
  root["run"] = io::write_run(scene.run);
  if (scene.has_environment) root["control"] = io::write_control(scene.control);
  root["contact"] = io::write_contact(scene.contact);
  // A maze or vessel run places the rod at the inlet, and the reader refuses a "shape" there:
  // writing one would make the canonical text (stored in every log) unreadable as a scene.
  if (!scene.has_environment) root["shape"] = io::write_shape(scene.shape);
  root["boundary"] = io::write_boundary(scene.boundary);
  root["loads"] = io::write_loads(scene.loads);
  root["solver"] = io::write_solver(scene.solver);
  return root;
}

}  // namespace

std::string scene_fields_json(const Scene& scene) { return scene_fields(scene).dump(2); }

std::string scene_to_json(const Scene& scene) {
  json root = scene_fields(scene);
  // What the configuration does not use is left out (a section left empty with it), so the
  // text reads back without a warning and names only what the run depends on.
  for (const UnusedField& u : unused_fields(scene)) {
    const json::json_pointer field(u.pointer);
    if (!root.contains(field)) continue;
    json& parent = root[field.parent_pointer()];
    parent.erase(field.back());
    if (parent.empty() && field.parent_pointer().parent_pointer().empty()) root.erase(field.parent_pointer().back());
  }
  return root.dump(2);
}

namespace io {
json to_json(const Vec2& p) { return json::array({p.x(), p.y()}); }
json to_json(const Polyline& line) {
  json out = json::array();
  for (const auto& p : line) out.push_back(to_json(p));
  return out;
}

json route_timing_json(const PathSpec& path, const Trajectory& trajectory) {
  return {{"length", trajectory.length()},
          {"speed", path.speed},
          {"ramp_time", path.ramp_time},
          {"duration", trajectory.duration()},
          {"samples", to_json(trajectory.sample(1e-4))}};
}
}  // namespace io

}  // namespace vascsim

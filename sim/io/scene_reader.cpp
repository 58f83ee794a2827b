#include "sim/io/scene_reader.h"

#include <fstream>
#include <sstream>

#include "sim/io/scene_sections.h"
#include "sim/scene/input_error.h"

namespace vascsim {

using nlohmann::json;

Scene read_scene_text(const std::string& text, const std::string& label) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    // nlohmann reports the byte offset; that is enough to find the mistake.
    throw InputError(label + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  Scene scene;
  scene.file = label;
  io::FieldReader in(root, label, "");
  in.text("format", "vascsim-scene/1");  // reserved for future format versions
  if (in.has("format") && root["format"] != "vascsim-scene/1")
    in.fail("format", "\"vascsim-scene/1\"", root["format"]);
  scene.name = in.text("name", scene.name);
  in.text("description", "");
  if (const json* maze = in.raw("maze"); maze && maze->is_null()) {
    scene.has_maze = false;
  } else {
    auto section = in.object("maze");
    io::read_maze(section, scene.maze);
  }
  {
    auto section = in.object("path");
    io::read_path(section, scene.path);
  }
  {
    auto section = in.object("rod");
    io::read_rod(section, scene.rod);
  }
  {
    auto section = in.object("run");
    io::read_run(section, scene.run);
  }
  {
    auto section = in.object("control");
    io::read_control(section, scene.control);
  }
  {
    auto section = in.object("contact");
    io::read_contact(section, scene.contact);
  }
  {
    auto section = in.object("shape");
    io::read_shape(section, scene.shape);
  }
  {
    auto section = in.object("boundary");
    io::read_boundary(section, scene.boundary);
  }
  {
    auto section = in.object("loads");
    io::read_loads(section, scene.loads);
  }
  {
    auto section = in.object("solver");
    io::read_solver(section, scene.solver);
  }
  in.finish();
  return scene;
}

Scene read_scene_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open scene file");
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw InputError(path + ": cannot read scene file");
  return read_scene_text(text.str(), path);
}

std::string scene_to_json(const Scene& scene) {
  json root;
  root["format"] = "vascsim-scene/1";
  root["name"] = scene.name;
  root["maze"] = scene.has_maze ? io::write_maze(scene.maze) : json(nullptr);
  root["path"] = io::write_path(scene.path);
  root["rod"] = io::write_rod(scene.rod);
  root["run"] = io::write_run(scene.run);
  root["control"] = io::write_control(scene.control);
  root["contact"] = io::write_contact(scene.contact);
  root["shape"] = io::write_shape(scene.shape);
  root["boundary"] = io::write_boundary(scene.boundary);
  root["loads"] = io::write_loads(scene.loads);
  root["solver"] = io::write_solver(scene.solver);
  return root.dump(2);
}

namespace io {
json to_json(const Vec2& p) { return json::array({p.x(), p.y()}); }
}  // namespace io

}  // namespace vascsim

#include "sim/io/sweep_expand.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/io/json_fields.h"
#include "sim/io/scene_reader.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;  // the scene as written keeps its key order in each run's copy
namespace fs = std::filesystem;

// Whether `doc` has a value at `pointer`; an index into an array that is not a number, or one
// past its end, is simply absent.
template <class Json>
bool has_value(const Json& doc, const std::string& pointer) {
  try {
    return doc.contains(typename Json::json_pointer(pointer));
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

// The parent pointer of "/a/b/c" ("/a/b"); "" for "/a".
std::string parent_of(const std::string& pointer) { return pointer.substr(0, pointer.rfind('/')); }

// Refuses a pointer that names no field of the scene: neither in the file nor among the fields
// the reader fills with defaults (`canonical`, the scene written back with every default). A
// field absent from the file is added with any objects above it; one inside a list cannot be,
// since the list's other entries would be made up.
void check_field(const ordered_json& doc, const json& canonical, const std::string& pointer, const std::string& where,
                 const std::string& sweep_file, const std::string& scene_file) {
  const std::string prefix = sweep_file + ": " + where + ": ";
  if (has_value(doc, pointer)) return;
  if (has_value(canonical, pointer)) {
    for (std::string p = parent_of(pointer); !p.empty(); p = parent_of(p))
      if (!has_value(doc, p) && !canonical.at(json::json_pointer(p)).is_object())
        throw InputError(prefix + pointer + " lies inside " + p + ", which " + scene_file +
                         " does not give: write the list in the scene file to override an entry of it");
    return;
  }
  // Name what is there, from the deepest part of the pointer that exists.
  std::string p = parent_of(pointer);
  while (!p.empty() && !has_value(canonical, p) && !has_value(doc, p)) p = parent_of(p);
  std::string known;
  const json& here = has_value(canonical, p) ? canonical.at(json::json_pointer(p)) : canonical;
  if (here.is_object())
    for (auto it = here.begin(); it != here.end(); ++it) known += (known.empty() ? "" : ", ") + it.key();
  throw InputError(prefix + "the scene " + scene_file + " has no field " + pointer +
                   (known.empty() ? std::string() : " (fields of " + (p.empty() ? std::string("/") : p) + ": " + known + ")"));
}

// Sets `pointer` in `doc`, creating the objects above it that check_field allowed.
void apply(ordered_json& doc, const std::string& pointer, const std::string& value_json) {
  doc[ordered_json::json_pointer(pointer)] = ordered_json::parse(value_json);
}

// A relative file named by the scene (a vessel mask image) is relative to the base scene; each
// run's scene lives in DIR/runs/<id>/, so the name is made absolute.
void rebase_scene_paths(ordered_json& doc, const fs::path& scene_dir) {
  const std::string pointer = "/vessels/mask/file";
  if (!has_value(doc, pointer)) return;
  ordered_json& file = doc[ordered_json::json_pointer(pointer)];
  if (!file.is_string() || file.get<std::string>().empty() || fs::path(file.get<std::string>()).is_absolute()) return;
  file = fs::absolute(scene_dir / file.get<std::string>()).lexically_normal().string();
}

std::string read_text_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  if (!f) throw InputError(path + ": cannot read scene file");
  return s.str();
}

// "/control/kp = 4, /maze/seed = 3" for messages.
std::string describe_run(const SweepSpec& spec, const SweepRun& run) {
  std::string out;
  for (std::size_t k = 0; k < spec.axes.size(); ++k)
    out += (k ? ", " : "") + spec.axes[k].pointer + " = " + run.values[k];
  if (spec.repeats > 1) out += ", repeat " + std::to_string(run.repeat);
  return out;
}

}  // namespace

std::string sweep_run_id(std::size_t index, std::size_t count) {
  const std::size_t width = std::max<std::size_t>(4, std::to_string(count > 0 ? count - 1 : 0).size());
  std::string id = std::to_string(index);
  return std::string(width - std::min(width, id.size()), '0') + id;
}

SweepPlan expand_sweep_with_scene(const SweepSpec& spec, const std::string& scene_text, const std::string& scene_label) {
  // The base scene must itself be a valid scene; its fields (used or not) are what axes may set.
  Scene base;
  try {
    base = read_scene_text(scene_text, scene_label);
  } catch (const InputError& e) {
    throw InputError(spec.file + ": /scene: " + e.what());
  }
  const json canonical = json::parse(scene_fields_json(base));
  ordered_json doc = ordered_json::parse(scene_text);
  rebase_scene_paths(doc, fs::path(scene_label).parent_path());

  for (const auto& [pointer, value] : spec.overrides)
    check_field(doc, canonical, pointer, "/overrides/" + io::escape_pointer_token(pointer), spec.file, scene_label);
  for (const auto& axis : spec.axes)
    check_field(doc, canonical, axis.pointer, "/axes/" + io::escape_pointer_token(axis.pointer), spec.file, scene_label);
  for (const auto& [pointer, value] : spec.overrides) {
    try {
      apply(doc, pointer, value);
    } catch (const nlohmann::json::exception& e) {
      throw InputError(spec.file + ": /overrides/" + io::escape_pointer_token(pointer) + ": cannot set " + pointer + " (" + e.what() + ")");
    }
  }

  SweepPlan plan;
  plan.spec = spec;
  const std::size_t count = sweep_run_count(spec);
  const std::size_t combinations = count / static_cast<std::size_t>(spec.repeats);
  plan.runs.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    SweepRun run;
    run.index = i;
    run.id = sweep_run_id(i, count);
    // Repeats are the outer loop, so the first `combinations` runs already cover the sweep.
    run.repeat = static_cast<int>(i / combinations);
    std::size_t rest = i % combinations;
    run.values.resize(spec.axes.size());
    for (std::size_t k = spec.axes.size(); k-- > 0;) {
      const auto& values = spec.axes[k].values;
      if (spec.combine == SweepCombine::kZip) {
        run.values[k] = values[rest];
      } else {
        run.values[k] = values[rest % values.size()];
        rest /= values.size();
      }
    }
    ordered_json scene = doc;
    for (std::size_t k = 0; k < spec.axes.size(); ++k) {
      try {
        apply(scene, spec.axes[k].pointer, run.values[k]);
      } catch (const nlohmann::json::exception& e) {
        throw InputError(spec.file + ": /axes/" + io::escape_pointer_token(spec.axes[k].pointer) + ": run " + run.id +
                         ": cannot set " + spec.axes[k].pointer + " (" + e.what() + ")");
      }
    }
    run.scene_json = scene.dump(2) + "\n";
    try {
      for (const UnusedField& u : read_scene_text(run.scene_json, scene_label).unused_given) {
        auto it = std::find_if(plan.unused.begin(), plan.unused.end(), [&](const auto& f) { return f.pointer == u.pointer; });
        if (it == plan.unused.end()) it = plan.unused.insert(plan.unused.end(), {u.pointer, u.why, 0});
        ++it->runs;
      }
    } catch (const InputError& e) {
      throw InputError(spec.file + ": run " + run.id + " (" + describe_run(spec, run) + "): " + e.what());
    }
    plan.runs.push_back(std::move(run));
  }
  return plan;
}

SweepPlan expand_sweep(const SweepSpec& spec) {
  try {
    read_scene_file(spec.scene_path);  // the file checks: missing, a directory, too large, not JSON
  } catch (const InputError& e) {
    throw InputError(spec.file + ": /scene: " + e.what());
  }
  return expand_sweep_with_scene(spec, read_text_file(spec.scene_path), spec.scene_path);
}

}  // namespace vascsim

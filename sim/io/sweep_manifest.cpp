#include "sim/io/sweep_manifest.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/io/json_fields.h"
#include "sim/io/provenance.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;  // written in a fixed, readable order: axes as the sweep file has them

}  // namespace

std::string run_scene_path(const std::string& id) { return "runs/" + id + "/scene.json"; }

SweepManifest manifest_of(const SweepPlan& plan) {
  SweepManifest m;
  m.name = plan.spec.name;
  m.scene = plan.spec.scene;
  m.combine = plan.spec.combine == SweepCombine::kZip ? "zip" : "product";
  m.repeats = plan.spec.repeats;
  m.axes = plan.spec.axes;
  m.overrides = plan.spec.overrides;
  for (const auto& r : plan.runs) m.runs.push_back({r.index, r.id, r.repeat, r.values, scene_hash(r.scene_json)});
  return m;
}

std::string sweep_manifest_json(const SweepManifest& m) {
  ordered_json j;
  j["format"] = "vascsim-sweep-manifest/1";
  j["name"] = m.name;
  j["scene"] = m.scene;
  j["combine"] = m.combine;
  j["repeats"] = m.repeats;
  j["axes"] = ordered_json::array();
  for (const auto& a : m.axes) {
    ordered_json values = ordered_json::array();
    for (const auto& v : a.values) values.push_back(ordered_json::parse(v));
    j["axes"].push_back({{"pointer", a.pointer}, {"values", values}});
  }
  j["overrides"] = ordered_json::object();
  for (const auto& [pointer, value] : m.overrides) j["overrides"][pointer] = ordered_json::parse(value);
  j["runs"] = ordered_json::array();
  for (const auto& r : m.runs) {
    ordered_json overrides = ordered_json::object();
    for (std::size_t k = 0; k < m.axes.size(); ++k) overrides[m.axes[k].pointer] = ordered_json::parse(r.values[k]);
    ordered_json run = {{"index", r.index}, {"id", r.id}, {"repeat", r.repeat}, {"overrides", overrides},
                        {"scene", run_scene_path(r.id)}};
    if (!r.scene_hash.empty()) run["scene_hash"] = r.scene_hash;
    j["runs"].push_back(run);
  }
  // One run per line keeps a large manifest readable and diffable.
  std::string out = "{\n";
  bool first = true;
  for (auto it = j.begin(); it != j.end(); ++it) {
    out += std::string(first ? "" : ",\n") + "  " + json(it.key()).dump() + ": ";
    first = false;
    if (it.key() == "runs" || it.key() == "axes") {
      out += "[";
      for (std::size_t i = 0; i < it->size(); ++i) out += std::string(i ? ",\n    " : "\n    ") + (*it)[i].dump();
      out += it->empty() ? "]" : "\n  ]";
    } else {
      out += it->dump();
    }
  }
  return out + "\n}\n";
}

SweepManifest read_sweep_manifest(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::error_code ec;
  if (!f || !std::filesystem::is_regular_file(path, ec))
    throw InputError(path + ": cannot open the sweep manifest (is this a directory made by vascsim sweep?)");
  // The size first: a buffer of the limit would cost more than reading a typical manifest.
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxManifestBytes)
    throw InputError(path + ": larger than " + std::to_string(kMaxManifestBytes >> 20) + " MiB, the limit for a sweep manifest");
  std::string text(static_cast<std::size_t>(size), '\0');
  f.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (static_cast<std::uintmax_t>(f.gcount()) != size) throw InputError(path + ": cannot read the sweep manifest");
  const json root = io::parse_json_strictly(text, path);
  io::FieldReader in(root, path, "");
  if (in.text("format", "") != "vascsim-sweep-manifest/1")
    in.fail("format", "\"vascsim-sweep-manifest/1\"", root.value("format", json()));
  SweepManifest m;
  m.name = in.text("name", "");
  m.scene = in.text("scene", "");
  m.combine = in.choice("combine", "product", {"product", "zip"});
  m.repeats = static_cast<int>(in.integer("repeats", 1, 1, 10000));
  const json* axes = in.raw("axes");
  if (!axes || !axes->is_array() || axes->empty()) in.fail("axes", "a non-empty list of axes", axes ? *axes : json());
  for (std::size_t k = 0; k < axes->size(); ++k) {
    io::FieldReader a((*axes)[k], path, "/axes/" + std::to_string(k));
    SweepAxis axis;
    axis.pointer = a.text("pointer", "");
    const json* values = a.raw("values");
    if (!values || !values->is_array() || values->empty()) a.fail("values", "a non-empty list", values ? *values : json());
    for (const auto& v : *values) axis.values.push_back(v.dump());
    a.finish();
    m.axes.push_back(axis);
  }
  if (const json* overrides = in.raw("overrides")) {
    if (!overrides->is_object()) in.fail("overrides", "an object", *overrides);
    // Order does not matter when reading: the overrides are already in every run's scene.
    for (auto it = overrides->begin(); it != overrides->end(); ++it) m.overrides.emplace_back(it.key(), it->dump());
  }
  const json* runs = in.raw("runs");
  if (!runs || !runs->is_array() || runs->empty()) in.fail("runs", "a non-empty list of runs", runs ? *runs : json());
  for (std::size_t i = 0; i < runs->size(); ++i) {
    const std::string where = "/runs/" + std::to_string(i);
    io::FieldReader r((*runs)[i], path, where);
    SweepManifestRun run;
    run.index = static_cast<std::size_t>(r.integer("index", -1, 0, static_cast<long long>(kMaxSweepRuns)));
    if (run.index != i) r.fail("index", std::to_string(i) + " (runs are listed in index order)", (*runs)[i]["index"]);
    run.id = r.text("id", "");
    if (run.id != sweep_run_id(i, runs->size()))
      r.fail("id", json(sweep_run_id(i, runs->size())).dump(), (*runs)[i].value("id", json()));
    run.repeat = static_cast<int>(r.integer("repeat", 0, 0, m.repeats - 1));
    io::FieldReader o = r.object("overrides");
    for (const auto& axis : m.axes) {
      const json* v = o.raw(axis.pointer);
      if (!v) throw InputError(path + ": " + where + "/overrides: missing the value of axis " + axis.pointer);
      run.values.push_back(v->dump());
    }
    o.finish();
    if (r.text("scene", "") != run_scene_path(run.id))
      r.fail("scene", json(run_scene_path(run.id)).dump(), (*runs)[i].value("scene", json()));
    run.scene_hash = r.text("scene_hash", "");
    r.finish();
    m.runs.push_back(run);
  }
  in.finish();
  return m;
}

}  // namespace vascsim

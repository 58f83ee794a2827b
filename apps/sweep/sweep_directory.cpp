#include "apps/sweep/sweep_directory.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/io/output_file.h"
#include "sim/io/provenance.h"
#include "sim/scene/input_error.h"

namespace vascsim::sweep {

namespace {

namespace fs = std::filesystem;

bool read_file(const fs::path& path, std::string& text) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::ostringstream s;
  s << f.rdbuf();
  text = s.str();
  return true;
}

// Writes `content` unless the file already holds exactly that (a resumed sweep rewrites nothing).
void write_if_different(const fs::path& path, const std::string& content) {
  std::string existing;
  if (read_file(path, existing) && existing == content) return;
  write_file_atomically(path.string(), content);
}

// What --force removes: everything a sweep writes in DIR, and nothing else.
void remove_sweep_outputs(const fs::path& dir) {
  std::error_code ec;
  for (const char* name : {"manifest.json", "sweep.json", "results.csv", "results.json"}) fs::remove(dir / name, ec);
  for (const char* name : {"runs", "plots", "parallel", "slurm"}) fs::remove_all(dir / name, ec);
}

// What a sweep stopped while it wrote its directory leaves (the manifest is written last): the
// copy of its sweep file and run directories holding nothing but their scene, all of them the
// program's. Stale temporaries of the stopped writer are removed on the way.
bool is_unfinished_sweep_directory(const fs::path& root) {
  std::error_code ec;
  remove_stale_temporaries(root.string());
  bool has_copy = false;
  for (const auto& entry : fs::directory_iterator(root, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == "sweep.json" && entry.is_regular_file(ec)) {
      has_copy = true;
    } else if (name == "runs" && entry.is_directory(ec)) {
      for (const auto& run : fs::directory_iterator(entry.path(), ec)) {
        if (!run.is_directory(ec)) return false;
        remove_stale_temporaries(run.path().string());
        for (const auto& file : fs::directory_iterator(run.path(), ec))
          if (file.path().filename() != "scene.json") return false;
      }
    } else {
      return false;
    }
  }
  return has_copy && !ec;
}

}  // namespace

bool is_sweep_directory(const std::string& path) {
  std::error_code ec;
  return fs::is_directory(path, ec) && fs::is_regular_file(fs::path(path) / "manifest.json", ec);
}

std::string run_directory(const SweepDirectory& sweep, std::size_t index) {
  return (fs::path(sweep.dir) / "runs" / sweep.manifest.runs.at(index).id).string();
}

void check_run_scene(const SweepDirectory& sweep, std::size_t index) {
  const SweepManifestRun& run = sweep.manifest.runs.at(index);
  if (run.scene_hash.empty()) return;
  const fs::path path = fs::path(sweep.dir) / run_scene_path(run.id);
  std::string scene;
  if (!read_file(path, scene))
    throw InputError(path.string() + ": cannot read the run's scene (the sweep wrote it; run the sweep file again)");
  if (scene_hash(scene) != run.scene_hash)
    throw InputError(path.string() + ": changed since the sweep wrote it (manifest.json holds another scene_hash): its "
                     "results would be filed under the manifest's values; restore it, or run the sweep file again "
                     "with --force");
}

SweepDirectory open_sweep_directory(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir + ": not a directory (expected a sweep directory made by vascsim sweep)");
  SweepDirectory s;
  s.dir = dir;
  s.manifest = read_sweep_manifest((fs::path(dir) / "manifest.json").string());
  return s;
}

SweepDirectory prepare_sweep_directory(const SweepPlan& plan, const std::string& sweep_text, const std::string& dir,
                                       bool force, bool& resumed) {
  const fs::path root(dir);
  const SweepManifest manifest = manifest_of(plan);
  const std::string manifest_text = sweep_manifest_json(manifest);
  resumed = false;
  std::error_code ec;
  if (fs::exists(root, ec)) {
    if (!fs::is_directory(root, ec)) throw InputError(dir + ": exists and is not a directory");
    std::string existing;
    if (read_file(root / "manifest.json", existing)) {
      bool same = existing == manifest_text;
      std::string differing;
      for (std::size_t i = 0; same && i < plan.runs.size(); ++i) {
        std::string scene;
        const fs::path path = root / run_scene_path(plan.runs[i].id);
        if (read_file(path, scene) && scene != plan.runs[i].scene_json) {
          same = false;
          differing = run_scene_path(plan.runs[i].id);
        }
      }
      if (!same && !force)
        throw InputError(dir + ": holds a different sweep (" +
                         (differing.empty() ? std::string("its manifest.json differs")
                                            : differing + " differs: the base scene changed since") +
                         "): choose another --out, or pass --force to delete its runs and start again");
      if (same) resumed = true;
      else remove_sweep_outputs(root);
    } else if (is_unfinished_sweep_directory(root)) {
      // Made again from the start: the same sweep takes it up, another one only with --force.
      std::string copy;
      const bool same = read_file(root / "sweep.json", copy) && copy == sweep_text;
      if (!same && !force)
        throw InputError(dir + ": holds the start of another sweep, stopped before its manifest.json was written: "
                               "choose another --out, or pass --force to start again");
      if (same) resumed = true;
      else remove_sweep_outputs(root);
    } else if (!fs::is_empty(root, ec)) {
      throw InputError(dir + ": is not empty and holds no sweep (no manifest.json); choose a new or empty directory");
    }
  } else if (!fs::create_directories(root, ec)) {
    throw InputError(dir + ": cannot create directory (" + ec.message() + ")");
  }
  write_if_different(root / "sweep.json", sweep_text);
  for (const auto& run : plan.runs) {
    fs::create_directories(root / "runs" / run.id, ec);
    if (ec) throw InputError((root / "runs" / run.id).string() + ": cannot create directory (" + ec.message() + ")");
    write_if_different(root / run_scene_path(run.id), run.scene_json);
  }
  write_if_different(root / "manifest.json", manifest_text);
  SweepDirectory s;
  s.dir = dir;
  s.manifest = manifest;
  return s;
}

}  // namespace vascsim::sweep

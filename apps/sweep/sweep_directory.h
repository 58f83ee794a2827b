// The sweep directory DIR that `vascsim sweep SWEEP --out DIR` makes and every engine works in:
//   DIR/manifest.json        every run's index, id, overrides and scene (sim/io/sweep_manifest.h)
//   DIR/sweep.json           a copy of the sweep file, for the record
//   DIR/runs/<id>/scene.json the run's scene; `vascsim run` writes frames.vlog and summary.json
//                            beside it, the sweep run.log (its output) and status.json
//   DIR/results.csv, results.json, plots/   written by `vascsim sweep merge DIR`
//   DIR/parallel/, DIR/slurm/               written by --emit
// The manifest is written last, so a directory with a manifest has every run's scene.
#pragma once

#include <string>

#include "sim/io/sweep_expand.h"
#include "sim/io/sweep_manifest.h"

namespace vascsim::sweep {

struct SweepDirectory {
  std::string dir;
  SweepManifest manifest;
};

// Makes DIR for `plan`, or resumes it when DIR already holds this very sweep (the same manifest
// and run scenes, byte for byte). A DIR holding another sweep is refused unless `force`, which
// deletes its runs and merged results first; a DIR that is not empty and holds no manifest is
// always refused (it is somebody's folder). Throws InputError. Sets `resumed`.
SweepDirectory prepare_sweep_directory(const SweepPlan& plan, const std::string& sweep_text, const std::string& dir,
                                       bool force, bool& resumed);
// Opens an existing sweep directory (reads and checks its manifest). Throws InputError.
SweepDirectory open_sweep_directory(const std::string& dir);
// Whether `path` is a sweep directory (holds a manifest.json).
bool is_sweep_directory(const std::string& path);
// DIR/runs/<id>.
std::string run_directory(const SweepDirectory& sweep, std::size_t index);
// Throws InputError if entry `index`'s scene file is not the one the sweep wrote (the manifest's
// scene_hash): its results would be filed under the manifest's values. Manifests without hashes
// are not checked.
void check_run_scene(const SweepDirectory& sweep, std::size_t index);

}  // namespace vascsim::sweep

// DIR/manifest.json of a sweep (`vascsim-sweep-manifest/1`, docs/sweeps.md): every run's index,
// id, overrides and scene file, and the axes they come from. It is the one thing an engine
// needs: `vascsim sweep DIR --run-index K` runs entry K from it, and `vascsim sweep merge DIR`
// tabulates the runs it lists. It holds nothing that depends on when, where or by which build
// it was written, so the same sweep always gives the same manifest, byte for byte; that is how a
// re-invocation knows it is resuming the same sweep.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "sim/io/sweep_expand.h"
#include "sim/io/sweep_spec.h"

namespace vascsim {

struct SweepManifestRun {
  std::size_t index = 0;
  std::string id;                   // the directory DIR/runs/<id>/
  int repeat = 0;
  std::vector<std::string> values;  // one per axis, compact JSON text
  // scene_hash() of its scene file as the sweep wrote it, so a runner can tell an edited scene
  // (whose results would be filed under these values); empty in manifests written before.
  std::string scene_hash;
};

struct SweepManifest {
  std::string name;
  std::string scene;    // the base scene as the sweep file names it
  std::string combine;  // "product" or "zip"
  int repeats = 1;
  std::vector<SweepAxis> axes;
  std::vector<std::pair<std::string, std::string>> overrides;  // fixed for every run
  std::vector<SweepManifestRun> runs;
};

SweepManifest manifest_of(const SweepPlan& plan);
std::string sweep_manifest_json(const SweepManifest& manifest);
// The largest manifest read: kMaxSweepRuns entries of a few hundred bytes.
inline constexpr std::size_t kMaxManifestBytes = std::size_t(256) << 20;
// Reads DIR/manifest.json strictly. Throws InputError naming the file and the JSON path.
SweepManifest read_sweep_manifest(const std::string& path);
// A run's scene, relative to the sweep directory: "runs/<id>/scene.json".
std::string run_scene_path(const std::string& id);

}  // namespace vascsim

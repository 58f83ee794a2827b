// A sweep's runs: the axes of a SweepSpec (sim/io/sweep_spec.h) combined into one entry per
// run, each with its overrides applied to the base scene's JSON and the result read exactly as
// a scene file is (sim/io/scene_reader.h), so a pointer to no field of the scene or a value the
// scene refuses is an error before anything runs, naming the sweep file, the run and the field.
//
// An override replaces the value at its pointer in the scene file as written. A pointer to a
// field the file leaves at its default (docs/scenes.md: "/solver/dt" in a scene that names only
// a preset) is added to the file, with the objects above it; a pointer to anything that is not
// a scene field is refused. The rest of the scene is left as written, so a preset, a duration
// taken from the path or a relative mask file mean what they meant in the base scene.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sim/io/sweep_spec.h"

namespace vascsim {

struct SweepRun {
  std::size_t index = 0;            // 0-based position in the manifest: --run-index, array task id
  std::string id;                   // zero-padded index, the run's directory name: "0007"
  int repeat = 0;                   // 0 .. repeats - 1
  std::vector<std::string> values;  // one per axis, in axis order, compact JSON text
  std::string scene_json;           // the run's scene file (DIR/runs/<id>/scene.json)
};

// A field some runs' scenes give but do not use (sim/scene/unused_fields.h): each such run warns
// of it when it runs; the sweep says so once, before any runs.
struct SweepUnusedField {
  std::string pointer, why;  // why: as the first run that leaves it unused says
  std::size_t runs = 0;      // how many runs
};
struct SweepPlan {
  SweepSpec spec;
  std::vector<SweepRun> runs;  // in index order: product with the first axis varying slowest
  std::vector<SweepUnusedField> unused;  // in the order first met
};

// Reads the base scene (spec.scene_path), expands and checks every run. Throws InputError.
SweepPlan expand_sweep(const SweepSpec& spec);
// As expand_sweep, with the base scene's text given (tests; `scene_label` names it).
SweepPlan expand_sweep_with_scene(const SweepSpec& spec, const std::string& scene_text, const std::string& scene_label);
// The id of run `index` of `count`: at least 4 digits, as many as the largest index needs, so ids
// sort as the runs do.
std::string sweep_run_id(std::size_t index, std::size_t count);

}  // namespace vascsim

// The merged table of a sweep: DIR/results.csv and DIR/results.json (docs/sweeps.md), one row
// per run of the manifest, whatever became of it (a missing or failed run is a row that says
// so, never left out), and the per-axis summary that `vascsim sweep merge` prints and plots.
//
// Determinism: every column but the timing ones (wall_time_s, real_time_factor,
// process_time_s, cpu_time_s, host) depends only on the scenes, so the same sweep gives the same
// bytes there on any engine. The timing columns come last, so `cut` or a prefix compare can
// drop them; results.json keeps them in a separate "timing" object per run.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sim/io/sweep_manifest.h"
#include "sim/io/sweep_outcome.h"

namespace vascsim {

// Names of the timing columns, which results.csv writes after all the others.
const std::vector<std::string>& sweep_timing_columns();
// results.csv: header, then one row per run (outcomes[i] belongs to manifest.runs[i]).
std::string sweep_results_csv(const SweepManifest& manifest, const std::vector<RunOutcome>& outcomes);
// results.json: the same rows with their overrides as JSON values, and the per-axis summary.
std::string sweep_results_json(const SweepManifest& manifest, const std::vector<RunOutcome>& outcomes);

// One value of one axis, over every run that has it (the spread over the other axes).
struct SweepValueSummary {
  std::string value;       // compact JSON text
  std::size_t runs = 0, done = 0, failed = 0, missing = 0, goal_reached = 0;
  // Per metric (sweep_metrics() order) over the done runs where it is known; NaN when none.
  std::vector<double> mean, min, max;
  std::vector<std::size_t> count;  // how many runs each figure is over
};
struct SweepAxisSummary {
  std::string pointer;
  std::vector<SweepValueSummary> values;  // in the axis's order
};
std::vector<SweepAxisSummary> summarise_sweep(const SweepManifest& manifest, const std::vector<RunOutcome>& outcomes);

// A JSON value as a table cell: strings without their quotes, anything else as JSON.
std::string sweep_value_text(const std::string& value_json);
// Whether every value of the axis is a JSON number; sets `numbers` to them.
bool sweep_axis_numbers(const SweepAxis& axis, std::vector<double>& numbers);

}  // namespace vascsim

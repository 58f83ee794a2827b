// `vascsim sweep merge DIR`: reads what every run of the manifest left (sim/io/sweep_outcome.h),
// writes DIR/results.csv and DIR/results.json (sim/io/sweep_results.h), one figure per axis in
// DIR/plots/ (render/sweep_plot.h; not in a build without the renderer) and returns the summary
// table it prints: per axis value, the runs, failures and the mean, min and max of the main
// figures over the other axes.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "apps/sweep/sweep_directory.h"
#include "sim/io/sweep_outcome.h"
#include "sim/io/sweep_results.h"

namespace vascsim::sweep {

struct MergeReport {
  std::vector<std::string> written;  // results.csv, results.json, the figures
  std::string table;                 // the summary table, as printed
  std::size_t done = 0, failed = 0, missing = 0;
  std::string note;                  // why there are no plots, if there are none
};

// Refuses to replace results or plots that exist unless `force`. Throws InputError.
MergeReport merge_sweep(const SweepDirectory& sweep, bool force, bool plots = true);
// The files a merge writes (results.csv, results.json, the plots) that exist already: those a
// merge without `force` would refuse to replace.
std::vector<std::string> earlier_merge_outputs(const SweepDirectory& sweep);
// What a sweep's runs do, which decides the figures its table and plots show.
struct SweepKind {
  bool navigation = false;  // in a maze or vessels
  bool steered = false;     // some run steers its tip (control.mode other than "none")
  bool fed = false;         // some run's root is fed through the inlet (control.advance)
};
// From the runs' figures or, while no run has completed, the first run's scene (an unreadable
// one: a free-space sweep).
SweepKind sweep_kind(const SweepDirectory& sweep, const std::vector<RunOutcome>& outcomes);
// The figures a table and the plots show: for a sweep that navigates, the tip error of a steered
// one and the feed's push of a fed one, then the goal time and penetration; else the solver's
// counts (a sweep of free-space scenes).
std::vector<std::size_t> headline_metrics(const SweepKind& kind);
std::string summary_table(const SweepManifest& manifest, const std::vector<RunOutcome>& outcomes, const SweepKind& kind);

}  // namespace vascsim::sweep

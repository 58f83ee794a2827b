// The figure `vascsim sweep merge` draws for each axis of a sweep: up to four panels, each a
// figure of the runs against the axis's values: every run as a dot (spread sideways a little,
// so the spread over the other axes, e.g. over maze seeds, shows), the min-max range as a bar
// and the mean as a line; runs that failed or are missing are counted above their value in red,
// completed runs without the figure (a goal not reached has no goal time) in grey.
// Drawn with the plots' canvas, axes and frame (render/plots.h), so it reads like them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vascsim::render {

struct SweepPanel {
  std::string title;                        // "tip error RMS"
  std::string ylabel;                       // "tip error RMS (mm)"
  std::vector<std::vector<double>> values;  // per axis value: the completed runs' figures
  std::vector<std::size_t> failed;          // per axis value: runs failed or missing
  std::vector<std::size_t> unknown;         // per axis value: completed runs without this figure
  std::string unknown_label;                // what those are: "not reached" for a goal time
};

struct SweepFigure {
  std::string xlabel;                   // the axis: "/control/kp"
  std::vector<double> x;                // the values' positions
  std::vector<std::string> x_labels;    // one per value when not numeric ticks (names, uneven values)
  std::vector<SweepPanel> panels;       // 1 to 4, two per row
};

// Writes the figure as PNG (width x height px for the whole figure). Throws InputError.
void write_sweep_figure(const SweepFigure& figure, const std::string& path, int width = 1200, int height = 900);

}  // namespace vascsim::render

// Plots of a run as PNG, drawn with the same canvas as the video: the tip trajectory against
// the reference with actuation arrows (paper Fig. 11), the actuation force over time (Fig. 12),
// whole-body snapshots with contact arrows (Fig. 14), and the tracking error and contact force
// over time. Each has axes, ticks, labels and units.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "render/canvas.h"
#include "render/frame_source.h"

namespace vascsim::render {

// A plot area on a canvas and the data range it shows.
struct Axes {
  float left = 0, top = 0, right = 0, bottom = 0;  // px
  double xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  glm::vec2 map(double x, double y) const;
  // Widens one range so one data unit is as long in x as in y (for maps).
  void equal_aspect();
};

// Grid lines, drawn first, under the data.
void draw_grid(Canvas& canvas, const Axes& axes);
// Drawn after the data: paints the margins in `page` (clipping the data to the axes), then the
// frame, ticks with labels, axis labels and the title. `x_ticks`, when given, replaces the
// x axis's numeric ticks by these positions and labels (names of categories, uneven values).
void draw_frame(Canvas& canvas, const Axes& axes, const std::string& xlabel, const std::string& ylabel,
                const std::string& title, Rgba page,
                const std::vector<std::pair<double, std::string>>& x_ticks = {});

// Logged frames first..last (inclusive; `last` past the log means its end).
struct FrameRange {
  std::size_t first = 0, last = static_cast<std::size_t>(-1);
};

// Writes the plots of the logged frames in `frames` into `dir` and returns their paths: the tip
// trajectory and the snapshots always, the magnetic force, tracking error, wall contact and
// feed where the log has them. Refuses to overwrite an existing plot unless `force`, which also
// removes the plots of those names this log has none of. Throws InputError on failure.
std::vector<std::string> write_plots(const FrameSource& source, const std::string& dir, bool force,
                                     FrameRange frames = {}, int width = 1200, int height = 800);

}  // namespace vascsim::render

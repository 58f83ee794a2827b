// The names of the plots a run directory holds (DIR/plots/), in one place for the renderer that
// draws them (render/plots.h) and for `vascsim run --force`, which removes an earlier run's
// outputs without linking the renderer (sim/ never depends on render/).
#pragma once

namespace vascsim {

// Each but the trajectory and snapshots is drawn only where the log has its data (a free rod's
// run has no magnetic force, tracking error or wall contact).
inline constexpr const char* kRunPlotFiles[] = {"tip_trajectory.png", "actuation_force.png", "snapshots.png",
                                                "tracking_error.png", "contact_force.png"};
// Drawn besides those for a run whose rod is fed through the inlet (control.advance).
inline constexpr const char* kFeedPlotFile = "feed_force.png";

}  // namespace vascsim

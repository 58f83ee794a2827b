// The cost of a fixed-step run of exactly a given error, for `vascsim bench accuracy`'s
// comparisons: "the fastest fixed step of equal or smaller error" depends on the grid of steps
// run (a controlled run 3 % more accurate than the nearest grid step is compared with one twice
// as fine), so the benches also interpolate along the fixed runs' own front.
#pragma once

#include <vector>

namespace vascsim::cli {

struct ErrorCost {
  double error = 0.0;      // any positive error measure
  double wall_time = 0.0;  // s
};

// s, the wall time at `error`, interpolated log-log between the two points of the front of
// `runs` (no faster run more accurate) that bracket it; NaN outside the front.
double wall_time_at_error(std::vector<ErrorCost> runs, double error);

}  // namespace vascsim::cli

// Time series for the replay page's plots: one value per logged frame reduced from a channel
// (the largest node force, the magnitude of the summed force, a scalar), and min/max
// decimation to a few hundred buckets so a plot of 10^6 frames keeps every spike and costs a
// few kilobytes.
#pragma once

#include <string>
#include <vector>

#include "sim/log/frame_log.h"

namespace vascsim::replay {

enum class SeriesReduce {
  kMax,   // node vectors: largest node magnitude
  kSum,   // node vectors: magnitude of the sum over nodes (e.g. the magnetic force on the robot)
  kNorm,  // Euclidean norm of all values
  kX,     // vectors: x component
  kY,     // vectors: y component
  kValue, // scalars: the first value; vectors: magnitude
};

// "max", "sum", "norm", "x", "y"; `reduce_for` picks what a name means for a channel's layout
// and throws std::invalid_argument (message names the expected values) if it does not apply.
SeriesReduce reduce_for(const LogChannel& channel, const std::string& name);

// The reduced value of one channel's `values` (channel.count doubles).
double reduce_values(const double* values, const LogChannel& channel, SeriesReduce reduce);

struct DecimatedSeries {
  std::vector<double> t, min, max;  // bucket centre (s), smallest and largest value in the bucket
};
// Buckets [from, to] into `points` equal spans and keeps the min and max of the values whose
// time falls in each; empty buckets are left out. `times` is non-decreasing.
DecimatedSeries decimate_min_max(const std::vector<double>& times, const std::vector<float>& values, double from,
                                 double to, int points);

}  // namespace vascsim::replay

// What connects a Run to its frame log: the header every run's log carries (its channels, and
// the metadata a renderer or a replay needs: the canonical scene, provenance, the resolved
// walls, lumen and reference path), and a FrameSink that appends each frame to a
// FrameLogWriter. `vascsim run` uses both, and so can a program that embeds vascsim
// (examples/embed/): a log written this way renders and replays like one from the command line.
#pragma once

#include "sim/io/log_metadata.h"
#include "sim/log/frame_log.h"
#include "sim/run/run.h"

namespace vascsim {

// The metadata of a run's log: the run's resolved scene (run.scene()) and its environment; for
// a free-space scene, the bounds of the initial rod padded by a tenth of its length.
LogMetadata run_log_metadata(const Run& run);

// Node count, channels and metadata of the run's log, ready for FrameLogWriter.
FrameLogHeader run_log_header(const Run& run);

// Appends every frame the run records to `writer` (which must outlive it).
class FrameLogSink : public FrameSink {
 public:
  explicit FrameLogSink(FrameLogWriter& writer) : writer_(writer) {}
  void write(double time, const std::vector<double>& values) override { writer_.append(time, values); }

 private:
  FrameLogWriter& writer_;
};

}  // namespace vascsim

// Helpers shared by the tests that run a whole scene and read what it reports: the shipped default
// maze cut to a given duration, and a run's summary.json as JSON.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/run_summary.h"
#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"

namespace vascsim::test {

// scenes/maze_default.json run for `duration` seconds; its first wall contacts come at about 17 s.
inline Scene default_maze(double duration) {
  Scene s = read_scene_file(std::string(VASCSIM_SOURCE_DIR) + "/scenes/maze_default.json");
  s.run.duration = duration;
  s.run.duration_from_path = false;
  return s;
}

// Runs the scene to its end, frames discarded, and returns its summary.json.
inline nlohmann::json summary_of(const Scene& scene) {
  struct DiscardSink : FrameSink {
    void write(double, const std::vector<double>&) override {}
  };
  Run run(compile(scene));
  DiscardSink sink;
  EXPECT_TRUE(run.run(sink)) << run.statistics().failure;
  return nlohmann::json::parse(run_summary_json(run.scene(), run));
}

}  // namespace vascsim::test

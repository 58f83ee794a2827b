// A run asked to stop (Run::run's stop_reason: `vascsim run` asks on Ctrl-C or SIGTERM) ends before
// the next step or load increment: a failed run whose statistics and summary name who stopped it,
// with every frame it had recorded, each the same as an uninterrupted run's.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "tests/run_test_support.h"

namespace vascsim {
namespace {

struct RecordingSink : FrameSink {
  std::vector<std::vector<double>> frames;  // each: time, then the channels
  void write(double time, const std::vector<double>& values) override {
    frames.push_back({time});
    frames.back().insert(frames.back().end(), values.begin(), values.end());
  }
};

// A stop_reason that answers `who` from its `asks`-th question on.
std::function<std::string()> stop_on_ask(int asks, const std::string& who, int& asked) {
  return [asks, who, &asked] { return ++asked >= asks ? who : std::string(); };
}

TEST(RunStop, ADynamicRunStopsBeforeItsNextStepKeepingItsFrames) {
  const Scene scene = test::default_maze(0.5);
  RecordingSink whole, stopped;
  vascsim::Run uninterrupted(compile(scene));
  ASSERT_TRUE(uninterrupted.run(whole)) << uninterrupted.statistics().failure;
  vascsim::Run run(compile(scene));
  int asked = 0;
  EXPECT_FALSE(run.run(stopped, {}, stop_on_ask(40, "SIGINT (Ctrl-C)", asked)));
  EXPECT_EQ(asked, 40) << "asked again after the answer";
  const RunStatistics& s = run.statistics();
  EXPECT_TRUE(s.failed);
  EXPECT_EQ(s.stopped_by, "SIGINT (Ctrl-C)");
  EXPECT_EQ(s.steps, 39);
  EXPECT_EQ(s.failure.rfind("stopped by SIGINT (Ctrl-C) at t = ", 0), 0u) << s.failure;
  ASSERT_GE(stopped.frames.size(), 2u);
  ASSERT_LT(stopped.frames.size(), whole.frames.size());
  EXPECT_EQ(s.frames, stopped.frames.size());
  for (std::size_t i = 0; i < stopped.frames.size(); ++i) EXPECT_EQ(stopped.frames[i], whole.frames[i]) << "frame " << i;
  EXPECT_GE(s.simulated_time, stopped.frames.back()[0]);
  const nlohmann::json summary = nlohmann::json::parse(run_summary_json(run.scene(), run));
  EXPECT_EQ(summary["ok"], false);
  EXPECT_EQ(summary["stopped_by"], "SIGINT (Ctrl-C)");
  EXPECT_EQ(summary["failure"], s.failure);
  const nlohmann::json finished = nlohmann::json::parse(run_summary_json(uninterrupted.scene(), uninterrupted));
  EXPECT_TRUE(finished["stopped_by"].is_null());
}

TEST(RunStop, AStaticSolveStopsBeforeItsNextLoadIncrement) {
  // A cantilever bent far by its tip load, in small increments (docs/references.md section 1).
  Scene scene = read_scene_text(R"({"maze": null, "rod": {"nodes": 41}, "boundary": {"clamp": "centred"},
      "solver": {"mode": "static", "load_steps": 50}, "loads": {"point": [{"node": -1, "force": [0, -0.05]}]}})",
                                "static.json");
  RecordingSink sink;
  vascsim::Run run(compile(scene));
  int asked = 0;
  EXPECT_FALSE(run.run(sink, {}, stop_on_ask(3, "SIGTERM", asked)));
  EXPECT_EQ(asked, 3);
  const RunStatistics& s = run.statistics();
  EXPECT_EQ(s.stopped_by, "SIGTERM");
  EXPECT_EQ(s.steps, 2) << "load increments taken before the stop";
  EXPECT_EQ(s.failure.rfind("static equilibrium: stopped by SIGTERM at load factor ", 0), 0u) << s.failure;
  EXPECT_EQ(sink.frames.size(), 1u) << "only the unloaded rod: the equilibrium was not reached";
  // Without a stop the same solve reaches full load.
  RecordingSink whole;
  vascsim::Run uninterrupted(compile(scene));
  EXPECT_TRUE(uninterrupted.run(whole, {}, [] { return std::string(); })) << uninterrupted.statistics().failure;
  EXPECT_EQ(whole.frames.size(), 2u);
  EXPECT_GT(uninterrupted.statistics().steps, 2);
}

}  // namespace
}  // namespace vascsim

// The mean over several mazes of `vascsim bench accuracy --seeds K`
// (apps/vascsim/bench_accuracy_traversal.h): each setting's rows averaged across the mazes, with
// wall time summed and real time recomputed from the sums, checked on two hand-made mazes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "apps/vascsim/bench_accuracy_traversal.h"

namespace vascsim::cli {
namespace {

TraversalRow row(const char* stepping, int steps, double mean_dt, double newton_per_step, double wall, double deviation,
                 double goal, double contact) {
  TraversalRow r;
  r.scene = "maze_body_drag";
  r.stepping = stepping;
  r.steps = steps;
  r.mean_dt = mean_dt;
  r.newton_per_step = newton_per_step;
  r.wall_time = wall;
  r.real_time = steps * mean_dt / wall;
  r.body_deviation = deviation;
  r.goal_time = goal;
  r.tip_rms = deviation / 2;
  r.tip_max = deviation * 3;
  r.contact_force_max = contact;
  r.steps_over_tolerance = steps / 10;
  return r;
}

TEST(MeanOverMazes, AveragesEachSettingAcrossMazesAndSumsWallTime) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Maze 1: 48 s in 4800 and 3000 steps; maze 2: 48 s in 4800 and 6000 steps (the controlled
  // run steps twice as often there), and its controlled run misses the goal.
  const std::vector<std::vector<TraversalRow>> mazes = {
      {row("fixed 1e-2", 4800, 1e-2, 1.5, 0.10, 3e-4, 45.0, 0.02), row("preset fast", 3000, 0.016, 1.0, 0.05, 2e-4, 45.5, 0.01)},
      {row("fixed 1e-2", 4800, 1e-2, 1.1, 0.20, 1e-4, 47.0, 0.03), row("preset fast", 6000, 0.008, 2.0, 0.15, 4e-4, nan, 0.05)}};
  const std::vector<TraversalRow> mean = mean_over_mazes(mazes);
  ASSERT_EQ(mean.size(), 2u);

  const TraversalRow& fixed = mean[0];
  EXPECT_EQ(fixed.stepping, "fixed 1e-2");
  EXPECT_EQ(fixed.scene, "maze_body_drag x2");
  EXPECT_EQ(fixed.steps, 4800);
  EXPECT_DOUBLE_EQ(fixed.mean_dt, 1e-2);
  EXPECT_DOUBLE_EQ(fixed.newton_per_step, 1.3);   // equal step counts: the plain mean
  EXPECT_DOUBLE_EQ(fixed.wall_time, 0.30);        // summed
  EXPECT_NEAR(fixed.real_time, 96.0 / 0.30, 1e-9);  // both mazes' 48 s over both wall times
  EXPECT_DOUBLE_EQ(fixed.body_deviation, 2e-4);
  EXPECT_DOUBLE_EQ(fixed.goal_time, 46.0);
  EXPECT_DOUBLE_EQ(fixed.tip_rms, 1e-4);
  EXPECT_DOUBLE_EQ(fixed.tip_max, 6e-4);
  EXPECT_DOUBLE_EQ(fixed.contact_force_max, 0.03);  // the largest, not the mean
  EXPECT_EQ(fixed.steps_over_tolerance, 960);       // summed

  const TraversalRow& fast = mean[1];
  EXPECT_EQ(fast.steps, 4500);
  EXPECT_NEAR(fast.mean_dt, 96.0 / 9000.0, 1e-15);                      // simulated time over steps
  EXPECT_NEAR(fast.newton_per_step, (3000 * 1.0 + 6000 * 2.0) / 9000.0, 1e-15);  // weighted by steps
  EXPECT_NEAR(fast.body_deviation, 3e-4, 1e-18);
  EXPECT_TRUE(std::isnan(fast.goal_time)) << "a maze whose goal was not reached shows in the mean";
  EXPECT_TRUE(fast.ok);
}

TEST(MeanOverMazes, OneFailedMazeFailsTheSetting) {
  std::vector<std::vector<TraversalRow>> mazes = {{row("error 1e-4", 100, 0.48, 1.0, 0.01, 1e-4, 45.0, 0.01)},
                                                  {row("error 1e-4", 100, 0.48, 1.0, 0.01, 1e-4, 45.0, 0.01)}};
  mazes[1][0].ok = false;
  EXPECT_FALSE(mean_over_mazes(mazes).at(0).ok);
}

}  // namespace
}  // namespace vascsim::cli

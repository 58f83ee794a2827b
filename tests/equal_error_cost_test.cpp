// The benches' cost of a fixed step of exactly a controlled run's error (apps/vascsim/equal_error_cost.h):
// log-log interpolation along the fixed runs' front, which a power law error = C dt^p, cost ~ 1/dt
// follows exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/vascsim/equal_error_cost.h"

namespace vascsim::cli {
namespace {

TEST(EqualErrorCost, ExactOnAPowerLawAndOnlyAlongTheFront) {
  // error = 3 dt^2, wall time = 1e-3 / dt: a second-order method on a grid of steps.
  std::vector<ErrorCost> runs;
  for (double dt : {1e-2, 4e-3, 1e-3, 2.5e-4}) runs.push_back({3 * dt * dt, 1e-3 / dt});
  // A run off the front (slower and less accurate than the 4e-3 one) must not be used.
  runs.push_back({3 * 5e-3 * 5e-3, 10.0});
  for (double dt : {7e-3, 2e-3, 5e-4}) {
    const double error = 3 * dt * dt;
    EXPECT_NEAR(wall_time_at_error(runs, error), 1e-3 / dt, 1e-12 * (1e-3 / dt)) << "dt " << dt;
  }
  EXPECT_DOUBLE_EQ(wall_time_at_error(runs, 3 * 1e-3 * 1e-3), 1.0) << "a grid point itself";
  EXPECT_TRUE(std::isnan(wall_time_at_error(runs, 1.0))) << "coarser than every run";
  EXPECT_TRUE(std::isnan(wall_time_at_error(runs, 1e-12))) << "finer than every run";
  EXPECT_TRUE(std::isnan(wall_time_at_error({}, 1e-3)));
}

}  // namespace
}  // namespace vascsim::cli

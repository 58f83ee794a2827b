// Labels of round values (legend arrows, scale bars): one significant digit must survive the
// unit. A kinematic run's legend chose mN for its contact forces and labelled its 2e-5 N
// magnetic reference arrow "0.0 mN" (render/number_format.h).
#include <gtest/gtest.h>

#include "render/number_format.h"

namespace vascsim::render {
namespace {

TEST(NumberFormat, ARoundValueKeepsItsDigitInAnyUnit) {
  const DisplayUnit mn{1e3, "mN"}, mm{1e3, "mm"};
  EXPECT_EQ(format_round_value(2e-5, mn), "0.02 mN");
  EXPECT_EQ(format_round_value(5e-4, mn), "0.5 mN");
  EXPECT_EQ(format_round_value(1e-3, mn), "1 mN");
  EXPECT_EQ(format_round_value(0.2, mm), "200 mm");
  EXPECT_EQ(format_round_value(1e-7, mn), "0.0001 mN");
  EXPECT_EQ(format_round_value(0.0, mn), "0 mN");
  // Far below the unit, an exponent rather than zeros to count.
  EXPECT_EQ(format_round_value(5e-14, mn), "5e-11 mN");
  EXPECT_EQ(format_round_value(-2e-9, mm), "-2e-06 mm");
  // A value nice_floor made from an arbitrary one keeps its digit too.
  EXPECT_EQ(format_round_value(nice_floor(3.7e-5), mn), "0.02 mN");
}

// Tick labels read distinctly at the step, and stay short far from 1 (1e300 printed 301 digits).
TEST(NumberFormat, TickLabelsAreShortAtAnyMagnitude) {
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(40, 20), "40");
  EXPECT_EQ(format_tick(3e300, 1e300), "3e+300");
  EXPECT_EQ(format_tick(2.5e7, 5e6), "2.5e+07");
  EXPECT_EQ(format_tick(-1.2e-8, 2e-9), "-1.2e-08");
  EXPECT_EQ(format_tick(1.000000004, 2e-9), "1.000000004");
  for (const double v : nice_ticks(-1e300, 1e300, 5)) EXPECT_LE(format_tick(v, 5e299).size(), 8u) << v;
}

}  // namespace
}  // namespace vascsim::render

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
  // A value nice_floor made from an arbitrary one keeps its digit too.
  EXPECT_EQ(format_round_value(nice_floor(3.7e-5), mn), "0.02 mN");
}

}  // namespace
}  // namespace vascsim::render

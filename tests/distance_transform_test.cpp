// The exact Euclidean distance transform behind mask tracing (sim/env/distance_transform.h),
// against the brute-force minimum over every background pixel (the frame outside the image
// included) on random images of several densities, and its nearest pixel being one at that distance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/env/distance_transform.h"

namespace vascsim {
namespace {

TEST(VesselMaskDistance, MatchesBruteForceOnRandomImages) {
  std::mt19937 rng(12);
  for (const double fill : {0.5, 0.9, 0.99, 1.0}) {
    const int w = 37, h = 23;
    std::vector<std::uint8_t> inside(w * h);
    std::bernoulli_distribution lumen(fill);
    for (auto& v : inside) v = lumen(rng) ? 1 : 0;
    const DistanceMap dm = distance_to_background(inside, w, h);
    for (int r = 0; r < h; ++r) {
      for (int c = 0; c < w; ++c) {
        double best = 1e300;
        for (int br = -1; br <= h; ++br)
          for (int bc = -1; bc <= w; ++bc) {
            const bool bg = br < 0 || bc < 0 || br >= h || bc >= w || !inside[br * w + bc];
            if (bg) best = std::min(best, std::hypot(bc - c, br - r));
          }
        const int i = r * w + c;
        ASSERT_NEAR(dm.distance[i], best, 1e-12) << "fill " << fill << " pixel (" << c << ", " << r << ")";
        ASSERT_NEAR(std::hypot(dm.nearest_col[i] - c, dm.nearest_row[i] - r), best, 1e-12);
        const int nc = dm.nearest_col[i], nr = dm.nearest_row[i];
        EXPECT_TRUE(nr < 0 || nc < 0 || nr >= h || nc >= w || !inside[nr * w + nc]) << "nearest is background";
      }
    }
  }
}

}  // namespace
}  // namespace vascsim

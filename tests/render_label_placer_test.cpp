// Labels placed by LabelPlacer never overlap while there is room: six labels wanted on one spot
// (the snapshot plot of a rod that hardly moved) come out stacked, each a few heights from it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/label_placer.h"

namespace vascsim::render {
namespace {

TEST(RenderLabelPlacer, LabelsWantedOnOneSpotAreStackedNearIt) {
  LabelPlacer placer({{0, 0}, {1200, 800}});
  const LabelBox wanted{{100, 400}, {180, 416}};  // 16 px high
  std::vector<LabelBox> placed;
  for (int i = 0; i < 6; ++i) placed.push_back(placer.place(wanted));
  EXPECT_EQ(placed[0].min, wanted.min) << "the first label goes where it was wanted";
  for (std::size_t i = 0; i < placed.size(); ++i) {
    EXPECT_EQ(placed[i].min.x, wanted.min.x) << i;
    EXPECT_FLOAT_EQ(placed[i].max.y - placed[i].min.y, 16.0f) << i;
    EXPECT_LE(std::abs(placed[i].min.y - wanted.min.y), 3 * 16.0f) << i << ": moved further than six labels need";
    for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(placed[i].overlaps(placed[j])) << i << " over " << j;
  }
}

TEST(RenderLabelPlacer, ALabelClearOfTheOthersStaysWhereItWasWanted) {
  LabelPlacer placer({{0, 0}, {1200, 800}});
  placer.place({{100, 400}, {180, 416}});
  const LabelBox beside{{190, 400}, {260, 416}}, below{{100, 417}, {180, 433}};
  EXPECT_EQ(placer.place(beside).min, beside.min);
  EXPECT_EQ(placer.place(below).min, below.min);
}

TEST(RenderLabelPlacer, LabelsStayWithinTheirBoundsAndOverlapOnlyWithoutRoom) {
  // At the bottom edge the second label goes above, not below the plot.
  LabelPlacer edge({{0, 0}, {1200, 420}});
  edge.place({{100, 400}, {180, 416}});
  const LabelBox second = edge.place({{100, 400}, {180, 416}});
  EXPECT_LT(second.min.y, 400.0f);
  EXPECT_LE(second.max.y, 420.0f);
  // Room for one label only: the second is drawn where wanted (over the first) rather than lost.
  LabelPlacer tight({{0, 400}, {1200, 416}});
  tight.place({{100, 400}, {180, 416}});
  EXPECT_EQ(tight.place({{100, 400}, {180, 416}}).min, glm::vec2(100, 400));
}

// A label wanted past the right edge of the axes (ahead of a tip at the edge) is moved left
// into them, where it is not clipped; one past the left edge, right.
TEST(RenderLabelPlacer, ALabelPastAnEdgeIsMovedInside) {
  LabelPlacer placer({{100, 0}, {1100, 800}});
  const LabelBox right = placer.place({{1080, 400}, {1160, 416}});
  EXPECT_FLOAT_EQ(right.max.x, 1100.0f);
  EXPECT_FLOAT_EQ(right.min.x, 1020.0f);
  EXPECT_FLOAT_EQ(right.min.y, 400.0f);
  const LabelBox left = placer.place({{60, 200}, {140, 216}});
  EXPECT_FLOAT_EQ(left.min.x, 100.0f);
  EXPECT_FLOAT_EQ(left.max.x, 180.0f);
}

// A label is moved off what it should not hide (another snapshot's rod): a vertical rod through
// the spot wanted, which no move up or down clears, sends it sideways, by half its width; where
// nothing clears it, it goes where the labels alone allow, as without anything to avoid.
TEST(RenderLabelPlacer, ALabelIsMovedOffWhatItShouldNotHide) {
  LabelPlacer placer({{0, 0}, {1200, 800}});
  const LabelBox wanted{{100, 400}, {180, 416}};
  for (float y = 0; y < 800; y += 4) placer.avoid({{128, y}, {132, y + 4}});  // a rod at x = 130
  const LabelBox placed = placer.place(wanted);
  EXPECT_EQ(placed.min.y, wanted.min.y) << "moved up or down, along the rod";
  EXPECT_TRUE(placed.min.x >= 132 || placed.max.x <= 128) << "still over the rod at x " << placed.min.x << ".." << placed.max.x;
  EXPECT_FLOAT_EQ(std::abs(placed.min.x - wanted.min.x), 40.0f) << "moved by half its width, the nearest sideways spot clear of the rod";
  // A rod clear of the spot wanted changes nothing.
  LabelPlacer beside({{0, 0}, {1200, 800}});
  beside.avoid({{300, 0}, {304, 800}});
  EXPECT_EQ(beside.place(wanted).min, wanted.min);
  // Covered everywhere: placed as the labels alone allow (the second below the first).
  LabelPlacer covered({{0, 0}, {1200, 800}});
  covered.avoid({{0, 0}, {1200, 800}});
  EXPECT_EQ(covered.place(wanted).min, wanted.min);
  EXPECT_EQ(covered.place(wanted).min, wanted.min + glm::vec2(0, 16));
}

}  // namespace
}  // namespace vascsim::render

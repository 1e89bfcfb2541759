// validate/tradeoff/pareto_plot.h: the label placement on hand-made points.
#include <gtest/gtest.h>

#include <cmath>

#include "validate/tradeoff/pareto_plot.h"

using namespace xval;

namespace {

// Plot-area pixels of a label's anchor.
double ax(const PlacedLabel& l) { return l.x * kPlotArea.width * (kPlotArea.right - kPlotArea.left); }
double ay(const PlacedLabel& l) { return l.y * kPlotArea.height * (kPlotArea.top - kPlotArea.bottom); }
const double kAreaW = kPlotArea.width * (kPlotArea.right - kPlotArea.left);   // 880
const double kAreaH = kPlotArea.height * (kPlotArea.top - kPlotArea.bottom);  // 588

}  // namespace

// The point at the centre of log axes [1, 100] x [1, 100] is at the plot
// area's centre; a front label goes to its left, one line below (the base
// row is free), an off-front label to its right on the point's row.
TEST(ParetoLabels, BaseSlotsWhenFree) {
  const PlotAxes axes{1, 100, 1, 100};
  const auto labels = placeLabels({{"front", 10, 10, true}, {"other", 1.5, 60, false}}, axes, 0.0);
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_TRUE(labels[0].left);
  EXPECT_TRUE(labels[0].front);
  EXPECT_FALSE(labels[0].leader);
  EXPECT_NEAR(ax(labels[0]), kAreaW / 2 - 9, 1e-9);
  EXPECT_NEAR(ay(labels[0]), kAreaH / 2 - 14, 1e-9);
  EXPECT_FALSE(labels[1].left);
  EXPECT_FALSE(labels[1].leader);
  const double px = kAreaW * std::log(1.5) / std::log(100.0), py = kAreaH * std::log(60.0) / std::log(100.0);
  EXPECT_NEAR(ax(labels[1]), px + 9, 1e-9);
  EXPECT_NEAR(ay(labels[1]), py, 1e-9);
  EXPECT_EQ(labels[1].seconds, 1.5);
  EXPECT_EQ(labels[1].error, 60.0);
}

// Three front points at one place: the labels take different rows, none
// overlaps another, and the ones moved off their base row get a leader.
TEST(ParetoLabels, CrowdedLabelsDoNotOverlap) {
  const PlotAxes axes{1, 100, 1, 100};
  const auto labels =
      placeLabels({{"aaaa", 10, 10, true}, {"bbbb", 10, 10, true}, {"cccc", 10, 10, true}}, axes, 0.0);
  ASSERT_EQ(labels.size(), 3u);
  EXPECT_FALSE(labels[0].leader);
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = i + 1; j < 3; ++j) {
      // Same side and text height 14: rows at least 14 apart, or on different sides.
      const bool apart = std::abs(ay(labels[i]) - ay(labels[j])) >= 14 - 1e-9 || labels[i].left != labels[j].left;
      EXPECT_TRUE(apart) << labels[i].id << " and " << labels[j].id;
    }
  int leaders = 0;
  for (const auto& l : labels) leaders += l.leader;
  EXPECT_GE(leaders, 1);
}

// A label never leaves the plot area when a slot inside is free: a front
// point at the left edge has no room on its left, so its label goes right.
TEST(ParetoLabels, StaysInsideThePlotArea) {
  const PlotAxes axes{1, 100, 1, 100};
  const auto labels = placeLabels({{"a-long-front-label", 1.01, 10, true}}, axes, 0.0);
  ASSERT_EQ(labels.size(), 1u);
  EXPECT_FALSE(labels[0].left);
  EXPECT_GE(ax(labels[0]), 0.0);
  EXPECT_LE(ax(labels[0]) + 7.5 * 18, kAreaW);
  EXPECT_GE(ay(labels[0]) - 7, 0.0);
}

// The tolerance's caption (along its line, from the left edge) is kept free.
TEST(ParetoLabels, KeepsTheToleranceCaptionFree) {
  const PlotAxes axes{1, 100, 1, 100};
  // An off-front point just right of the left edge whose right-hand base
  // slot would lie on the caption's band.
  const auto with = placeLabels({{"x", 1.2, 10, false}}, axes, 10.0);
  const auto without = placeLabels({{"x", 1.2, 10, false}}, axes, 0.0);
  EXPECT_NEAR(ay(without[0]), kAreaH / 2, 1e-9);
  EXPECT_GT(std::abs(ay(with[0]) - kAreaH / 2), 1.0);
}

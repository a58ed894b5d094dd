// The wear profile's lobe count (reference/contact/liner_wear.hpp; the rule
// of data/README.md's rubbing.liner row) on hand-made rings whose count is
// read off by eye: counts are integers, so every assertion is exact.

#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "liner_wear.hpp"

namespace rsi {
namespace {

TEST(LinerWear, TwoPeaksOfAnOvalCountTwice) {
  // Two bumps half a ring apart (what the oval's two closures wear).
  const std::vector<double> ring = {0, 1, 3, 1, 0, 0, 1, 2.5, 1, 0};
  std::printf("lobes %d (expected 2)\n", ring_lobes(ring, 3.0));
  EXPECT_EQ(ring_lobes(ring, 3.0), 2);
}

TEST(LinerWear, AFlatTopCountsOnce) {
  const std::vector<double> ring = {0, 2, 2, 2, 0, 0};
  EXPECT_EQ(ring_lobes(ring, 2.0), 1);
}

TEST(LinerWear, APeakAcrossTheSeamCountsOnce) {
  // Cells n - 1 and 0 are neighbours: the run {2, 2} at the ends is one lobe.
  const std::vector<double> ring = {2, 1, 0, 0, 1, 2};
  EXPECT_EQ(ring_lobes(ring, 2.0), 1);
}

TEST(LinerWear, PeaksBelowHalfTheDeepestAreRipples) {
  // 0.9 is below half of 2: a ripple, not a lobe; 1.1 is above.
  EXPECT_EQ(ring_lobes({0, 2, 0, 0.9, 0}, 2.0), 1);
  EXPECT_EQ(ring_lobes({0, 2, 0, 1.1, 0}, 2.0), 2);
}

TEST(LinerWear, AFlatRingHasOneLobeIfWornElseNone) {
  EXPECT_EQ(ring_lobes({1, 1, 1}, 1.0), 1);
  EXPECT_EQ(ring_lobes({0, 0, 0}, 0.0), 0);
  // A flat row under half of another row's deepest cell: none.
  EXPECT_EQ(ring_lobes({0.4, 0.4}, 1.0), 0);
}

TEST(LinerWear, TheLinerCountIsTheMostOverItsRows) {
  // Row 0 one lobe of depth 4, row 1 three lobes of depth 3 (above 2).
  const std::vector<double> depth = {0, 4, 0, 0, 0, 0, 3, 0, 3, 0, 3, 0};
  EXPECT_EQ(wear_lobes(depth, 6, 2), 3);
  EXPECT_EQ(wear_lobes({0, 0, 0}, 3, 1), 0);
}

} // namespace
} // namespace rsi

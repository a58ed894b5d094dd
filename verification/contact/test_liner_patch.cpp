// The tip patch on the abradable liner (reference/contact/liner_patch): the
// cells under a patch on hand-worked windows (inside a cell, three centres,
// across the seam, wider than the ring, rows), and the patch's compliant
// root against an independent bisection on the common depth, against the
// one-bar solve, and against the sum of its bars' forces.

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "abradable_liner.hpp"
#include "liner_patch.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// 8 sectors (centres at pi/8 + i pi/4), 4 rows over [0, 40] (centres 5,
/// 15, 25, 35); r 250, h 2 [mm]; E 1e4, sigma_y 10, H 1e3 [MPa].
AbradableLiner liner(int n_theta = 8) {
  LinerGeometry g;
  g.radius = 250.0;
  g.thickness = 2.0;
  g.n_theta = n_theta;
  g.n_axial = 4;
  g.z_min = 0.0;
  g.z_max = 40.0;
  LinerMaterial m;
  m.young = 1e4;
  m.yield = 10.0;
  m.hardening = 1e3;
  return AbradableLiner(g, m);
}

TEST(LinerPatch, SectorsWhoseCentresLieInTheWindow) {
  const AbradableLiner l = liner();
  // Window [pi/8 - 0.05, pi/8 + 0.05] holds sector 0's centre only.
  EXPECT_EQ(patch_sectors(l, M_PI / 8, 0.1), std::vector<int>({0}));
  // [-0.04, 0.06] holds no centre: the sector holding 0.01.
  EXPECT_EQ(patch_sectors(l, 0.01, 0.1), std::vector<int>({0}));
  // [pi/4, pi] about 5 pi/8 holds the centres 3 pi/8, 5 pi/8, 7 pi/8.
  EXPECT_EQ(patch_sectors(l, 5 * M_PI / 8, 3 * M_PI / 4), std::vector<int>({1, 2, 3}));
  // [-pi/4, pi/4] across the seam: -pi/8 (sector 7) and pi/8 (sector 0).
  EXPECT_EQ(patch_sectors(l, 0.0, M_PI / 2), std::vector<int>({7, 0}));
  // Wider than the ring: every sector once.
  EXPECT_EQ(patch_sectors(l, 1.0, 7.0), std::vector<int>({0, 1, 2, 3, 4, 5, 6, 7}));
  // 100 turns on: the same window.
  EXPECT_EQ(patch_sectors(l, 200 * M_PI + 5 * M_PI / 8, 3 * M_PI / 4), std::vector<int>({1, 2, 3}));
  EXPECT_THROW(patch_sectors(l, 0.0, -1.0), std::invalid_argument);
}

TEST(LinerPatch, RowsWhoseCentresLieInTheWindow) {
  const AbradableLiner l = liner();
  EXPECT_EQ(patch_rows(l, 12.0, 2.0), std::vector<int>({1}));  // [11, 13]: none, the row of 12
  EXPECT_EQ(patch_rows(l, 12.0, 8.0), std::vector<int>({1}));  // [8, 16] holds 15
  EXPECT_EQ(patch_rows(l, 20.0, 20.0), std::vector<int>({1, 2})); // [10, 30]: 15, 25
  EXPECT_EQ(patch_rows(l, 0.0, 100.0), std::vector<int>({0, 1, 2, 3}));
  EXPECT_EQ(patch_rows(l, 40.0, 12.0), std::vector<int>({3}));  // [34, 46] holds 35
  EXPECT_THROW(patch_rows(l, 41.0, 1.0), std::invalid_argument); // not over the liner
}

/// Bars in every state the law has: virgin, worn and hardened by
/// different amounts (one cell's state after a plastic load each).
std::vector<LinerCellState> mixed_states(const AbradableLiner& l) {
  std::vector<LinerCellState> s(1);
  for (double delta : {0.004, 0.01, 0.05, 0.2}) s.push_back(l.bar_force(LinerCellState{}, delta).state);
  LinerCellState twice = l.bar_force(s[2], 0.1 + s[2].wear).state;
  s.push_back(twice);
  return s;
}

/// S(d): the bars' summed force at the common depth d (the law itself).
double summed_force(const AbradableLiner& l, const std::vector<LinerCellState>& s, double d) {
  double f = 0.0;
  for (const LinerCellState& x : s) f += l.bar_force(x, d - x.wear).force;
  return f;
}

TEST(LinerPatch, CompliantRootAgainstBisectionOnTheDepth) {
  const AbradableLiner l = liner();
  const std::vector<LinerCellState> s = mixed_states(l);
  const double n = static_cast<double>(s.size());
  const double k = l.stiffness();
  for (double ck : {0.0, 0.1, 1.0, 1e3}) {
    const double c = ck / k;
    for (int j = -5; j <= 120; ++j) {
      const double depth = 0.004 * j;
      const LinerPatchResponse r = patch_compliant_force(l, s, depth, c);
      ASSERT_EQ(r.bars.size(), s.size());
      // Bisection on G(d) = d + c S(d) = depth (G increasing): G(depth) >= depth,
      // and at lo = depth - 1 - c S(depth), G(lo) <= lo + c S(depth) < depth.
      double lo = depth - 1.0 - c * summed_force(l, s, depth), hi = depth;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        (mid + c * summed_force(l, s, mid) <= depth ? lo : hi) = mid;
      }
      const double expected = summed_force(l, s, lo);
      // G is evaluated with a rounding of 2 n eps (|d| + c S): the root moves
      // by that (G' >= 1) and S by its slope, at most n k, times that.
      const double tolerance =
          8.0 * n * n * eps * k * (std::abs(depth) + c * expected) + 8.0 * n * eps * expected;
      EXPECT_NEAR(r.force, expected, tolerance) << "c k = " << ck << ", depth = " << depth;
      // Each bar's force at (depth - p) - c F carries k times that
      // difference's rounding, eps (|depth| + c F) (abradable_liner.hpp).
      double sum = 0.0;
      for (const LinerBarResponse& b : r.bars) sum += b.force;
      EXPECT_NEAR(sum, r.force, 8.0 * n * eps * (k * (std::abs(depth) + c * r.force) + r.force))
          << "c k = " << ck;
    }
  }
}

TEST(LinerPatch, OneBarIsTheBarsCompliantSolve) {
  const AbradableLiner l = liner();
  const double k = l.stiffness();
  for (const LinerCellState& s : mixed_states(l))
    for (double ck : {0.0, 0.1, 1.0, 1e3})
      for (int j = -5; j <= 120; ++j) {
        const double depth = 0.004 * j;
        const LinerPatchResponse r = patch_compliant_force(l, {s}, depth, ck / k);
        const LinerBarResponse one = l.compliant_force(s, depth - s.wear, ck / k);
        // The same operations on the same branch (liner_patch.hpp): bit for bit.
        EXPECT_EQ(r.force, one.force) << "c k = " << ck << ", depth = " << depth;
        EXPECT_EQ(r.bars[0].state.wear, one.state.wear);
        EXPECT_EQ(r.bars[0].state.hardening, one.state.hardening);
        EXPECT_EQ(r.bars[0].plastic_work, one.plastic_work);
      }
}

TEST(LinerPatch, RefusesAnEmptyPatchAndBadNumbers) {
  const AbradableLiner l = liner();
  EXPECT_THROW(patch_compliant_force(l, {}, 0.1, 0.0), std::invalid_argument);
  EXPECT_THROW(patch_compliant_force(l, {LinerCellState{}}, NAN, 0.0), std::invalid_argument);
  EXPECT_THROW(patch_compliant_force(l, {LinerCellState{}}, 0.1, -1.0), std::invalid_argument);
}

} // namespace
} // namespace rsi

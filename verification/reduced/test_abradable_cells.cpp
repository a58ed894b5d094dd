// The reduced solver's own abradable bar (reduced/abradable_cells) against
// the closed form of a linear-hardening bar loaded and unloaded by a moving
// rigid indenter, and against the reference's independent kernel
// (reference/contact/abradable_liner) on the same paths: the two
// derivations (force variables here, stress and return mapping there) must
// give the same forces, wear and plastic work to round-off. Then the tip
// patch (reduced/liner_patch_cells): its cell selection against hand-worked
// windows, and its joint compliant root against an independent bisection on
// the depth and, for one bar, against AbradableCells::compliant.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "abradable_cells.hpp"
#include "abradable_cells_fixture.hpp"
#include "abradable_liner.hpp"
#include "liner_patch_cells.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

AbradableLiner reference_liner(double hardening) {
  const AbradableCellsGeometry g = abradable_test_geometry();
  LinerGeometry rg;
  rg.radius = g.radius;
  rg.thickness = g.thickness;
  rg.n_theta = g.n_theta;
  rg.n_axial = g.n_axial;
  rg.z_min = g.z_min;
  rg.z_max = g.z_max;
  LinerMaterial rm;
  rm.young = 1000.0;
  rm.yield = 10.0;
  rm.hardening = hardening;
  return AbradableLiner(rg, rm);
}

// A ramp to delta_max and back to 0 by a rigid indenter: the closed form of
// the bar (k = E A / h, F_y = A sigma_y, k_H = H A / h): the permanent
// shortening p = (k delta_max - F_y) / (k + k_H), the peak force
// F_y + k_H p, the plastic work p (F_y + k_H p / 2) (the area under the
// yield line), and zero force once the indenter is back above p.
TEST(AbradableCells, LoadUnloadAgainstClosedForm) {
  for (double hardening : {300.0, 0.0}) {
    AbradableCells cells(abradable_test_geometry(), abradable_test_material(hardening));
    const double a = 250.0 * (2.0 * M_PI / 8.0) * 2.0;
    const double k = 1000.0 * a / 2.0, kh = hardening * a / 2.0, fy = 10.0 * a;
    EXPECT_NEAR(cells.stiffness(), k, 4 * eps * k);
    const double delta_max = 3.0 * fy / k;
    const int n = 600;
    double peak = 0.0;
    for (int i = 1; i <= 2 * n; ++i) {
      // The indenter's depth past the UNWORN surface; the bar sees it past p.
      const double depth = delta_max * (i <= n ? double(i) / n : double(2 * n - i) / n);
      const BarResponse r = cells.bar(cells.state(0), depth - cells.state(0).wear);
      cells.commit(0, r);
      peak = std::max(peak, r.force);
      if (i > n && depth <= cells.state(0).wear) {
        EXPECT_EQ(r.force, 0.0) << "unloaded at " << i;
      }
    }
    const double p = (k * delta_max - fy) / (k + kh);
    // Each step's return mapping is exact (linear hardening): the sums of
    // about n rounded terms, relative n eps.
    EXPECT_NEAR(cells.state(0).wear, p, n * eps * p) << "H " << hardening;
    // The yield force at the peak is F_y plus n rounded increments k_H dp.
    EXPECT_NEAR(peak, fy + kh * p, n * eps * (fy + kh * p));
    const double work = p * (fy + 0.5 * kh * p);
    EXPECT_NEAR(cells.plastic_work(), work, n * eps * work);
  }
}

// The same random path through both kernels: forces, wear and plastic
// work agree to round-off (the two derivations are algebraically equal).
TEST(AbradableCells, MatchesTheReferenceKernel) {
  for (double hardening : {300.0, 0.0}) {
    AbradableCells cells(abradable_test_geometry(), abradable_test_material(hardening));
    AbradableLiner liner = reference_liner(hardening);
    unsigned seed = 7;
    const auto uniform = [&seed]() {
      seed = seed * 1103515245u + 12345u;
      return ((seed >> 8) & 0xffffff) / double(0x1000000);
    };
    const double scale = 4.0 * 10.0 * cells.area() / cells.stiffness();
    // Tolerance (derived): the reference forms F from delta = delta~ - c F
    // and then from the trial stress E delta / h minus the return E dgamma,
    // and delta~ = depth - p is formed from the depth: roundings of terms up
    // to k |depth| (the trial force, and k times the depth's rounding), and
    // of delta~ = delta + c F (times k: c k F), leave F within a few
    // eps (1 + c k) max(F, k |depth|) (about five roundings a side: 16); and
    // each plastic step rounds the two states apart by a few eps (the yield
    // force summed in force here, in stress there), which moves F by up to
    // k times that much wear: 4 eps max(F, k |depth|) per plastic step so far.
    int plastic_steps = 0;
    for (int i = 0; i < 2000; ++i) {
      const double depth = scale * (uniform() * 1.2 - 0.2) + cells.state(3).wear * uniform();
      const double c = uniform() < 0.5 ? 0.0 : uniform() / cells.stiffness();
      const BarResponse mine = cells.compliant(cells.state(3), depth - cells.state(3).wear, c);
      const LinerBarResponse ref =
          liner.compliant_force(liner.state(3), depth - liner.state(3).wear, c);
      const double f = std::max(ref.force, 1e-300);
      const double tolerance = (16.0 * (1.0 + c * cells.stiffness()) + 4.0 * plastic_steps) * eps *
                               std::max(f, cells.stiffness() * std::abs(depth));
      ASSERT_NEAR(mine.force, ref.force, tolerance) << "step " << i;
      // The root: F = bar(delta~ - c F) (its own definition), to the same
      // cancellation in forming delta~ - c F.
      EXPECT_NEAR(mine.force, cells.bar(cells.state(3), depth - cells.state(3).wear - c * mine.force).force,
                  tolerance);
      plastic_steps += ref.plastic;
      cells.commit(3, mine);
      liner.commit(3, ref);
      ASSERT_NEAR(cells.state(3).wear, liner.state(3).wear,
                  4.0 * plastic_steps * eps * std::max(liner.state(3).wear, 1e-300));
    }
    EXPECT_GT(cells.state(3).wear, 0.0);
    EXPECT_NEAR(cells.plastic_work(), liner.plastic_work(), 1e-12 * liner.plastic_work());
  }
}

TEST(AbradableCells, CellMapAndRefusals) {
  AbradableCells cells(abradable_test_geometry(), abradable_test_material());
  EXPECT_EQ(cells.sector(0.0), 0);
  EXPECT_EQ(cells.sector(-1e-18), 7);
  EXPECT_EQ(cells.sector(2.0 * M_PI + 0.1), 0);
  EXPECT_EQ(cells.row(8.0), 3);
  EXPECT_EQ(cells.row(0.0), 0);
  EXPECT_THROW(cells.row(8.5), std::invalid_argument);
  AbradableCellsGeometry g = abradable_test_geometry();
  g.thickness = 300.0;
  EXPECT_THROW(AbradableCells(g, abradable_test_material()), std::invalid_argument);
  AbradableCellsMaterial m = abradable_test_material();
  m.hardening = -1.0;
  EXPECT_THROW(AbradableCells(abradable_test_geometry(), m), std::invalid_argument);
  BarResponse lower;
  lower.state.wear = -1.0;
  EXPECT_THROW(cells.commit(0, lower), std::logic_error);
}

// The selection rule of liner_patch_cells.hpp worked by hand on the 8 x 4
// liner (dtheta = pi/4, r = 250, rows of dz = 2 over [0, 8], centres 1, 3,
// 5, 7). Widths are given as multiples of r dtheta, so a = multiple x dtheta.
TEST(LinerPatchCells, SelectionByHand) {
  AbradableCells cells(abradable_test_geometry(), abradable_test_material());
  const double d = cells.pitch(), r = 250.0;
  using V = std::vector<int>;
  // Inside sector 0: [0.2, 0.4] dtheta holds no centre -> the sector of theta.
  EXPECT_EQ(patch_sectors(cells, 0.3 * d, 0.2 * d), V({0}));
  // Inside sector 3: [3.65, 3.95] dtheta -> sector 3.
  EXPECT_EQ(patch_sectors(cells, 3.8 * d, 0.3 * d), V({3}));
  // Zero width: the one-cell rule.
  EXPECT_EQ(patch_sectors(cells, 5.2 * d, 0.0), V({5}));
  // [1, 4] dtheta (ends on sector edges): centres 1.5, 2.5, 3.5.
  EXPECT_EQ(patch_sectors(cells, 2.5 * d, 3.0 * d), V({1, 2, 3}));
  // The closed window [1.5, 3.5] dtheta ends ON the centres 1.5 and 3.5:
  // both count. The hand case needs a = 2 dtheta and the ends exact in
  // binary (checked, else the case would test rounding, not the rule).
  const double a = (2.0 * d * r) / r;
  ASSERT_EQ(a, 2.0 * d);
  ASSERT_EQ((2.5 * d - 0.5 * a) / d - 0.5, 1.0);
  ASSERT_EQ((2.5 * d + 0.5 * a) / d - 0.5, 3.0);
  EXPECT_EQ(patch_sectors(cells, 2.5 * d, a), V({1, 2, 3}));
  // Across the seam: [-0.9, 1.1] dtheta holds centres -0.5 (sector 7) and 0.5.
  EXPECT_EQ(patch_sectors(cells, 0.1 * d, 2.0 * d), V({0, 7}));
  EXPECT_EQ(patch_sectors(cells, -0.1 * d, 2.0 * d), V({0, 7}));             // [-1.1, 0.9]
  EXPECT_EQ(patch_sectors(cells, 7.9 * d, 2.0 * d), V({0, 7}));              // [6.9, 8.9]
  EXPECT_EQ(patch_sectors(cells, 6.0 * M_PI + 0.1 * d, 2.0 * d), V({0, 7})); // 3 turns on
  // Wider than 2 pi: 9 dtheta -> 9 integers >= 8: every sector once; and
  // exactly 8 centres in [0, 8] dtheta.
  EXPECT_EQ(patch_sectors(cells, 0.3 * d, 9.0 * d), V({0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(patch_sectors(cells, 4.0 * d, 8.0 * d), V({0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(patch_sectors(cells, 1.0, 1e300), V({0, 1, 2, 3, 4, 5, 6, 7}));
  // Rows: [1.75, 6.25] holds centres 3, 5 -> rows 1, 2.
  EXPECT_EQ(patch_rows(cells, 4.0, 4.5), V({1, 2}));
  // [3.4, 4.4] holds no centre -> the row of 3.9.
  EXPECT_EQ(patch_rows(cells, 3.9, 1.0), V({1}));
  // [6.9, 8.1]: centre 7 only (the window passes z_max).
  EXPECT_EQ(patch_rows(cells, 7.5, 1.2), V({3}));
  // [-9.5, 10.5]: every row.
  EXPECT_EQ(patch_rows(cells, 0.5, 20.0), V({0, 1, 2, 3}));
  EXPECT_EQ(patch_rows(cells, 8.0, 0.0), V({3})); // zero width: row(z)
  // Cells: rows {1, 2} x sectors {0, 7}, row n_theta + sector, ascending.
  TipPatch patch;
  patch.circumferential = 2.0 * d * r;
  patch.axial = 4.5;
  EXPECT_EQ(patch_cells(cells, 0.1 * d, 4.0, patch), V({8, 15, 16, 23}));
  EXPECT_FALSE(TipPatch{}.present());
  EXPECT_THROW(patch_sectors(cells, 0.0, -1.0), std::invalid_argument);
  EXPECT_THROW(patch_rows(cells, 9.0, 1.0), std::invalid_argument);
}

// F = sum_i F_bar(state_i, d~ - p_i - c F) by bisection on the common depth
// d (the root of d + c G(d) = d~, G nondecreasing), against patch_compliant
// on five bars: fresh, hardened, worn by different amounts, so that the
// depths sweep them through off, elastic and plastic; c k = 0, 0.1, 1, 1e3.
TEST(LinerPatchCells, JointRootAgainstBisection) {
  AbradableCells cells(abradable_test_geometry(), abradable_test_material());
  const double k = cells.stiffness(), kh = cells.hardening_stiffness();
  const double fy0 = 10.0 * cells.area(), dy = fy0 / k; // the fresh yield force and depth
  std::vector<BarState> from;
  for (double p : {0.0, 0.3, 1.0, 2.5, 6.0}) // wear in yield depths, hardened alike
    from.push_back(BarState{p * dy, fy0 + kh * p * dy});
  const double n = static_cast<double>(from.size()), p_max = 6.0 * dy;
  const auto g_of = [&](double d) {
    double g = 0.0;
    for (const BarState& s : from) g += cells.bar(s, d - s.wear).force;
    return g;
  };
  double worst_root = 0.0, worst_sum = 0.0;
  int off = 0, elastic = 0, plastic = 0;
  for (double ck : {0.0, 0.1, 1.0, 1e3}) {
    const double c = ck / k;
    const int samples = 400;
    for (int s = 0; s <= samples; ++s) {
      // From above the surface to every bar yielding: d~ up to d + c G(d) at d = 9 dy.
      const double d_top = 9.0 * dy + c * g_of(9.0 * dy);
      const double depth = -dy + (d_top + dy) * s / samples;
      std::vector<BarResponse> bars;
      const double f = patch_compliant(cells, from, depth, c, bars);
      // Bisection on [min(d~, p_min), d~] (the root lies there: cG >= 0, and
      // below p_min G = 0 so d = d~).
      double lo = std::min(depth, 0.0), hi = depth;
      for (int it = 0; it < 2000; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (mid + c * g_of(mid) < depth ? lo : hi) = mid;
      }
      // Tolerance (derived): the root's force lies in [G(lo), G(hi)]; the
      // bracket is misplaced by the rounding of d + c G (2 eps (|d~| + p_max)
      // twice in depth), times G's slope <= n k; the closed form rounds
      // (n + 8) roundings of nonnegative terms: 4 (n + 8) eps F.
      const double tolerance = (g_of(hi) - g_of(lo)) +
                               4.0 * n * k * eps * (std::abs(depth) + p_max) +
                               4.0 * (n + 8.0) * eps * std::max(f, g_of(hi));
      const double error = std::abs(f - g_of(0.5 * (lo + hi)));
      worst_root = std::max(worst_root, error / std::max(tolerance, 1e-300));
      ASSERT_LE(error, tolerance) << "c k " << ck << " depth " << depth;
      // The bars' own forces at d~ - p_i - c F sum to F, to the rounding of
      // that difference: 2 eps (|d~ - p_i| + c F) k each, plus eps F a term.
      double sum = 0.0, scale = 0.0;
      for (size_t i = 0; i < from.size(); ++i) {
        sum += bars[i].force;
        scale = std::max(scale, std::abs(depth - from[i].wear) + c * f);
        off += bars[i].force == 0.0;
        plastic += bars[i].plastic_work > 0.0;
        elastic += bars[i].force > 0.0 && bars[i].plastic_work == 0.0;
        EXPECT_GE(bars[i].state.wear, from[i].wear); // wear never decreases
      }
      const double sum_tolerance = 4.0 * n * eps * (k * scale + f);
      worst_sum = std::max(worst_sum, std::abs(sum - f) / std::max(sum_tolerance, 1e-300));
      EXPECT_LE(std::abs(sum - f), sum_tolerance) << "c k " << ck << " depth " << depth;
    }
  }
  std::printf("patch root vs bisection: worst error / tolerance %.3g; bar sum %.3g; bars off %d, "
              "elastic %d, plastic %d\n",
              worst_root, worst_sum, off, elastic, plastic);
  EXPECT_GT(off, 0);
  EXPECT_GT(elastic, 0);
  EXPECT_GT(plastic, 0);
}

// PatchCompliantSolve keeps the breakpoints and the G(b) it evaluated while
// the bars' states stay the same (liner_patch_cells.hpp): called again and
// again, as the Gauss-Seidel sweeps do, with the depth changing and the
// states changing now and then (one bar worn further, a bar more, the first
// states back), it must return patch_compliant's force and bars bit for
// bit. A memory kept across a change of state would put the root on the
// old G's piece. bar_force is bar().force bit for bit (the same operations).
TEST(LinerPatchCells, RepeatedSolveIsTheOneShotSolve) {
  AbradableCells cells(abradable_test_geometry(), abradable_test_material());
  const double k = cells.stiffness(), kh = cells.hardening_stiffness();
  const double fy0 = 10.0 * cells.area(), dy = fy0 / k;
  std::vector<BarState> a;
  for (double p : {0.0, 0.3, 1.0, 2.5, 6.0}) a.push_back(BarState{p * dy, fy0 + kh * p * dy});
  std::vector<BarState> b = a;
  b[1] = BarState{4.0 * dy, fy0 + kh * 4.0 * dy}; // worn further: G changes
  std::vector<BarState> c3 = b;
  c3.push_back(BarState{0.5 * dy, fy0 + kh * 0.5 * dy}); // a bar more
  const std::vector<const std::vector<BarState>*> sequence = {&a, &a, &b, &b, &c3, &a};
  PatchCompliantSolve solve;
  int calls = 0, forces = 0;
  for (const std::vector<BarState>* from : sequence)
    for (double ck : {0.0, 1.0, 1e3})
      for (int s = 0; s <= 40; ++s) {
        const double depth = -dy + 12.0 * dy * s / 40 * (1.0 + ck);
        const double c = ck / k;
        std::vector<BarResponse> once, again;
        const double f1 = patch_compliant(cells, *from, depth, c, once);
        const double f2 = solve(cells, *from, depth, c, again);
        ASSERT_EQ(f1, f2) << "call " << calls;
        ASSERT_EQ(once.size(), again.size());
        for (size_t i = 0; i < once.size(); ++i) {
          EXPECT_EQ(once[i].force, again[i].force);
          EXPECT_EQ(once[i].state.wear, again[i].state.wear);
          EXPECT_EQ(once[i].state.yield_force, again[i].state.yield_force);
          EXPECT_EQ(once[i].plastic_work, again[i].plastic_work);
        }
        ++calls;
        forces += f1 > 0.0;
      }
  EXPECT_GT(forces, calls / 2); // most depths press the patch
  for (const BarState& st : c3)
    for (int s = -10; s <= 100; ++s) {
      const double delta = 0.1 * s * dy;
      EXPECT_EQ(cells.bar_force(st, delta), cells.bar(st, delta).force) << delta;
    }
}

// One bar: patch_compliant's closed forms are AbradableCells::compliant's
// term for term (liner_patch_cells.hpp), so the force is the same bit for
// bit where both put the root on the same piece; near the yield breakpoint
// they may classify apart, and the two pieces then agree at the root to the
// classification's rounding: 8 eps (F + k (|delta~| + F_Y / k) / (1 + c k)).
TEST(LinerPatchCells, OneBarIsTheCompliantBar) {
  for (double hardening : {300.0, 0.0}) {
    AbradableCells cells(abradable_test_geometry(), abradable_test_material(hardening));
    const double k = cells.stiffness(), fy0 = 10.0 * cells.area();
    unsigned seed = 17;
    const auto uniform = [&seed]() {
      seed = seed * 1103515245u + 12345u;
      return ((seed >> 8) & 0xffffff) / double(0x1000000);
    };
    int same = 0, total = 0;
    double worst = 0.0;
    for (int i = 0; i < 5000; ++i) {
      const double p = uniform() < 0.3 ? 0.0 : 3.0 * uniform() * fy0 / k;
      const BarState s{p, fy0 + cells.hardening_stiffness() * p};
      const double ck = std::pow(10.0, -2.0 + 5.0 * uniform()) * (uniform() < 0.1 ? 0.0 : 1.0);
      const double c = ck / k;
      // The last 1000 within a few ulps of the yield threshold
      // k delta~ = F_Y (1 + c k), where the two may classify apart.
      const double depth = i < 4000
                               ? p + (4.0 * uniform() - 0.5) * (1.0 + ck) * s.yield_force / k
                               : p + (1.0 + ck) * s.yield_force / k * (1.0 + (i % 9 - 4) * eps);
      std::vector<BarResponse> bars;
      const double f = patch_compliant(cells, {s}, depth, c, bars);
      const BarResponse r = cells.compliant(s, depth - p, c);
      const double tolerance =
          8.0 * eps * (r.force + k * (std::abs(depth - p) + s.yield_force / k) / (1.0 + ck));
      worst = std::max(worst, std::abs(f - r.force) / tolerance);
      EXPECT_LE(std::abs(f - r.force), tolerance) << i;
      same += f == r.force;
      ++total;
      // The wear: the bar law at delta~ - c F against compliant's flow from
      // delta~: they differ by the rounding of delta~ - c F, 2 eps
      // (|delta~| + c F), scaled by k / (k + k_H) <= 1.
      EXPECT_NEAR(bars[0].state.wear, r.state.wear,
                  2.0 * eps * (std::abs(depth - p) + c * f) + 4.0 * eps * r.state.wear)
          << i;
    }
    std::printf("one bar, H %g: %d of %d forces bit for bit, worst |difference| / tolerance %.3g\n",
                hardening, same, total, worst);
  }
}

} // namespace
} // namespace rsi

// The reduced solver's own abradable bar (reduced/abradable_cells) against
// the closed form of a linear-hardening bar loaded and unloaded by a moving
// rigid indenter, and against the reference's independent kernel
// (reference/contact/abradable_liner) on the same paths: the two
// derivations (force variables here, stress and return mapping there) must
// give the same forces, wear and plastic work to round-off.

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "abradable_cells.hpp"
#include "abradable_liner.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

AbradableCellsGeometry geometry() {
  AbradableCellsGeometry g;
  g.radius = 250.0;
  g.thickness = 2.0;
  g.n_theta = 8;
  g.n_axial = 4;
  g.z_min = 0.0;
  g.z_max = 8.0;
  return g;
}

AbradableCellsMaterial material(double hardening = 300.0) {
  AbradableCellsMaterial m;
  m.young = 1000.0;
  m.yield = 10.0;
  m.hardening = hardening;
  return m;
}

AbradableLiner reference_liner(double hardening) {
  const AbradableCellsGeometry g = geometry();
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
    AbradableCells cells(geometry(), material(hardening));
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
    AbradableCells cells(geometry(), material(hardening));
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
  AbradableCells cells(geometry(), material());
  EXPECT_EQ(cells.sector(0.0), 0);
  EXPECT_EQ(cells.sector(-1e-18), 7);
  EXPECT_EQ(cells.sector(2.0 * M_PI + 0.1), 0);
  EXPECT_EQ(cells.row(8.0), 3);
  EXPECT_EQ(cells.row(0.0), 0);
  EXPECT_THROW(cells.row(8.5), std::invalid_argument);
  AbradableCellsGeometry g = geometry();
  g.thickness = 300.0;
  EXPECT_THROW(AbradableCells(g, material()), std::invalid_argument);
  AbradableCellsMaterial m = material();
  m.hardening = -1.0;
  EXPECT_THROW(AbradableCells(geometry(), m), std::invalid_argument);
  BarResponse lower;
  lower.state.wear = -1.0;
  EXPECT_THROW(cells.commit(0, lower), std::logic_error);
}

} // namespace
} // namespace rsi

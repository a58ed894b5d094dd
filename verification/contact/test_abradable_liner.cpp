// The abradable liner's cell law (SPEC §9; reference/contact/abradable_liner):
// one elasto-plastic bar with linear hardening loaded and unloaded by a rigid
// indenter against its closed form (force at every step, permanent
// shortening, plastic work = the hysteresis loop's area), reloading below
// and beyond the previous maximum, the compliant per-step solve against its
// defining identity and an independent bisection, the cell map, a huge
// yield stress, and the refusal of bad parameters.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "abradable_liner.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// Rotor-37-sized liner [mm, MPa]: r 250, h 2, 8 sectors, 4 rows over
/// [0, 8] (dz = 2 and the sector edges at multiples of pi/4 exact in binary).
LinerGeometry geometry() {
  LinerGeometry g;
  g.radius = 250.0;
  g.thickness = 2.0;
  g.n_theta = 8;
  g.n_axial = 4;
  g.z_min = 0.0;
  g.z_max = 8.0;
  return g;
}

/// An abradable's order of magnitude: E 1 GPa, sigma_y 10 MPa, H 300 MPa.
LinerMaterial material(double yield = 10.0, double hardening = 300.0) {
  LinerMaterial m;
  m.young = 1000.0;
  m.yield = yield;
  m.hardening = hardening;
  return m;
}

/// The closed form of a virgin bar (elastic-linear-hardening, 1D):
/// k = E A / h, F_y = A sigma_y, d_y = F_y / k, k_t = k H / (E + H),
/// k_H = A H / h (F = F_y + k_H p on yield, p the plastic shortening).
struct ClosedForm {
  double k, k_t, k_H, F_y, d_y;
  ClosedForm(const LinerGeometry& g, const LinerMaterial& m) {
    const double A = g.radius * (2.0 * M_PI / g.n_theta) * ((g.z_max - g.z_min) / g.n_axial);
    k = m.young * A / g.thickness;
    k_t = k * m.hardening / (m.young + m.hardening);
    k_H = A * m.hardening / g.thickness;
    F_y = A * m.yield;
    d_y = F_y / k;
  }
  /// Monotone loading to depth d (past the unworn surface): k d, then F_y + k_t (d - d_y).
  double loading(double d) const { return d <= d_y ? k * d : F_y + k_t * (d - d_y); }
  /// Permanent shortening after loading to d_max > d_y: d_max - F_max / k.
  double permanent(double d_max) const { return d_max - loading(d_max) / k; }
  /// Plastic work to a plastic shortening p: the integral of (F_y + k_H p) dp.
  double plastic_work(double p) const { return F_y * p + 0.5 * k_H * p * p; }
  /// The hysteresis loop's area to d_max: the work in on loading (elastic
  /// triangle, then the hardening trapezoid) less the work out on unloading.
  double loop_area(double d_max) const {
    const double F_max = loading(d_max);
    return 0.5 * F_y * d_y + 0.5 * (F_y + F_max) * (d_max - d_y) - 0.5 * F_max * F_max / k;
  }
};

/// Moves a rigid indenter over cell `cell` through the depths `path`
/// (past the unworn surface), committing every step; returns the forces.
std::vector<double> indent(AbradableLiner& liner, int cell, const std::vector<double>& path) {
  std::vector<double> forces;
  for (double d : path) {
    const LinerBarResponse r = liner.bar_force(liner.state(cell), liner.indentation(cell, d));
    liner.commit(cell, r);
    forces.push_back(r.force);
  }
  return forces;
}

/// n equal steps from a to b (b included, a not).
std::vector<double> ramp(double a, double b, int n) {
  std::vector<double> d;
  for (int s = 1; s <= n; ++s)
    d.push_back(a + (b - a) * s / n);
  return d;
}

/// One cycle 0 -> d_max -> 0 with hardening modulus H, against the closed form.
void load_unload(double H) {
  AbradableLiner liner(geometry(), material(10.0, H));
  const ClosedForm cf(geometry(), material(10.0, H));
  const double d_max = 0.1; // 5 d_y
  const int n = 100;
  const int cell = liner.cell(1.0, 3.0);
  std::vector<double> path = ramp(0.0, d_max, n);
  const std::vector<double> down = ramp(d_max, 0.0, n);
  path.insert(path.end(), down.begin(), down.end());
  const std::vector<double> forces = indent(liner, cell, path);

  const double F_max = cf.loading(d_max);
  const double p = cf.permanent(d_max);
  double worst = 0.0;
  for (std::size_t s = 0; s < path.size(); ++s) {
    // Closed form: loading k d / F_y + k_t (d - d_y); unloading max(0, k (d - p)).
    const double expected =
        s < static_cast<std::size_t>(n) ? cf.loading(path[s]) : std::max(0.0, cf.k * (path[s] - p));
    worst = std::max(worst, std::abs(forces[s] - expected));
  }
  // Each step rounds the trial (d - p_n, E delta / h) and the return (f,
  // dgamma, sigma, p, alpha) within a few eps; the wear's rounding carries
  // over to later steps at most 2 eps p per step (the return mapping
  // corrects p to first order: p = (F - F_y) / k_H), and a wear error moves
  // the force by k times it; with k d_max >= F_max: (8 + 2 steps) eps k d_max.
  const double tol_force = (8.0 + 2.0 * path.size()) * eps * cf.k * d_max;
  const double p_error = std::abs(liner.wear(cell) - p);
  const double tol_p = tol_force / cf.k;
  // W_p summed over the steps telescopes to A h (sigma_y alpha + H alpha^2 / 2)
  // at the final alpha; rounding: a few eps a step on terms <= F_max d_max.
  const double W_closed = cf.plastic_work(p);
  const double W_loop = cf.loop_area(d_max);
  const double tol_W = (8.0 + 2.0 * path.size()) * eps * F_max * d_max;
  std::printf("k %.6e N/mm, k_t %.6e, F_y %.6e N, F_max %.6e N: worst force error %.3e N "
              "(tol %.3e)\n",
              cf.k, cf.k_t, cf.F_y, F_max, worst, tol_force);
  std::printf("permanent shortening %.17g mm, closed form d_max - F_max/k %.17g: error %.3e "
              "(tol %.3e)\n",
              liner.wear(cell), p, p_error, tol_p);
  std::printf("plastic work %.17g N mm; F_y p + k_H p^2/2 %.17g, loop area %.17g: errors "
              "%.3e, %.3e (tol %.3e)\n",
              liner.plastic_work(), W_closed, W_loop, std::abs(liner.plastic_work() - W_closed),
              std::abs(liner.plastic_work() - W_loop), tol_W);
  EXPECT_LE(worst, tol_force);
  EXPECT_LE(p_error, tol_p);
  EXPECT_GT(p, 0.0); // the test reaches the plastic branch
  EXPECT_LE(std::abs(liner.plastic_work() - W_closed), tol_W);
  EXPECT_LE(std::abs(liner.plastic_work() - W_loop), tol_W);
  // The last step is off the surface (d = 0 < p): no force.
  EXPECT_EQ(forces.back(), 0.0);
  // alpha = p / h on a compression-only bar: two roundings a plastic step.
  EXPECT_NEAR(liner.state(cell).hardening, p / geometry().thickness, tol_p / geometry().thickness);
  // Other cells untouched.
  for (int c = 0; c < liner.n_cells(); ++c)
    if (c != cell) {
      EXPECT_EQ(liner.wear(c), 0.0);
    }
}

TEST(AbradableLiner, LoadUnloadAgainstClosedForm) {
  load_unload(300.0);
}

// H = 0: k_t = 0, the force stays at F_y while the bar flows.
TEST(AbradableLiner, LoadUnloadPerfectlyPlastic) {
  load_unload(0.0);
}

TEST(AbradableLiner, ReloadingBelowStaysElasticBeyondHardens) {
  AbradableLiner liner(geometry(), material());
  const ClosedForm cf(geometry(), material());
  const int cell = 5;
  const double d1 = 0.06, d2 = 0.05, d3 = 0.1;
  const int n = 60;
  indent(liner, cell, ramp(0.0, d1, n));
  indent(liner, cell, ramp(d1, 0.0, n));
  const LinerCellState after_first = liner.state(cell);
  const double p1 = cf.permanent(d1);
  // As in LoadUnloadAgainstClosedForm over the 6 n steps of this test.
  const double tol = (8.0 + 2.0 * 6 * n) * eps * cf.k * d3;

  // Reloading to d2 < d1: the bar stays on the elastic line k (d - p1).
  double worst_below = 0.0;
  for (double d : ramp(0.0, d2, n)) {
    const LinerBarResponse r = liner.bar_force(liner.state(cell), liner.indentation(cell, d));
    EXPECT_FALSE(r.plastic) << "d " << d;
    EXPECT_EQ(r.plastic_work, 0.0);
    liner.commit(cell, r);
    worst_below = std::max(worst_below, std::abs(r.force - std::max(0.0, cf.k * (d - p1))));
  }
  // No new wear: exactly the state left by the first cycle.
  EXPECT_EQ(liner.state(cell).wear, after_first.wear);
  EXPECT_EQ(liner.state(cell).hardening, after_first.hardening);
  indent(liner, cell, ramp(d2, 0.0, n));

  // Reloading beyond d1: elastic up to d1 (F = k (d - p1) reaches F(d1)),
  // then the hardened branch F(d1) + k_t (d - d1), the virgin line continued.
  double worst_beyond = 0.0;
  for (double d : ramp(0.0, d3, 2 * n)) {
    const LinerBarResponse r = liner.bar_force(liner.state(cell), liner.indentation(cell, d));
    liner.commit(cell, r);
    const double expected =
        d <= d1 ? std::max(0.0, cf.k * (d - p1)) : cf.loading(d1) + cf.k_t * (d - d1);
    worst_beyond = std::max(worst_beyond, std::abs(r.force - expected));
    // The same line as a virgin bar loaded monotonically (closed form).
    if (d > d1) {
      EXPECT_NEAR(r.force, cf.loading(d), tol) << "d " << d;
    }
  }
  const double p3 = cf.permanent(d3);
  std::printf("reload below d1: worst force error %.3e N; beyond: %.3e N (tol %.3e); wear %.17g, "
              "closed form %.17g; plastic work %.17g, closed form %.17g\n",
              worst_below, worst_beyond, tol, liner.wear(cell), p3, liner.plastic_work(),
              cf.plastic_work(p3));
  EXPECT_LE(worst_below, tol);
  EXPECT_LE(worst_beyond, tol);
  EXPECT_NEAR(liner.wear(cell), p3, tol / cf.k);
  // The plastic work depends only on the final p (closed form), whatever the path.
  EXPECT_NEAR(liner.plastic_work(), cf.plastic_work(p3),
              (8.0 + 2.0 * 6 * n) * eps * cf.loading(d3) * d3);
}

/// Independent root of phi(F) = F - bar_force(state, delta_pred - c F).F
/// (phi increasing, slope >= 1) by bisection on [0, k max(delta_pred, 0)].
double bisection_root(const AbradableLiner& liner, const LinerCellState& state, double delta_pred,
                      double c) {
  double lo = 0.0, hi = liner.stiffness() * std::max(delta_pred, 0.0);
  for (int it = 0; it < 2000 && lo < hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const double phi = mid - liner.bar_force(state, delta_pred - c * mid).force;
    (phi > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(AbradableLiner, CompliantSolveOnEveryBranch) {
  const AbradableLiner liner(geometry(), material());
  const double k = liner.stiffness();
  const double h = geometry().thickness;
  LinerCellState hardened;
  hardened.hardening = 0.01;
  hardened.wear = 0.01 * h;
  int checked = 0;
  double worst = 0.0, worst_bisection = 0.0;
  for (const LinerCellState& state : {LinerCellState{}, hardened}) {
    const double F_Y = liner.yield_force(state);
    const double delta_Y = F_Y / k;
    for (double ck : {0.0, 0.1, 1.0, 1e3}) {
      const double c = ck / k;
      const double edge = delta_Y * (1.0 + ck); // delta_pred where the bar starts yielding
      // (delta_pred, expected branch: 0 off, 1 elastic, 2 plastic, -1 either)
      const std::vector<std::pair<double, int>> cases = {
          {-0.01, 0}, {0.0, 0}, {0.5 * edge, 1}, {edge, -1}, {1.5 * edge, 2}, {10.0 * edge, 2}};
      for (const auto& [delta_pred, branch] : cases) {
        const LinerBarResponse r = liner.compliant_force(state, delta_pred, c);
        // The defining identity F = bar_force(delta_pred - c F).
        const LinerBarResponse again = liner.bar_force(state, delta_pred - c * r.force);
        const double residual = std::abs(r.force - again.force);
        // The forward error: delta = delta_pred - c F rounds within
        // eps (|delta_pred| + c F) plus c times F's 4 eps (closed form), the
        // k-Lipschitz law turns that into force and adds a few eps of F:
        // 8 eps (F + k (|delta_pred| + c F)).
        const double tol = 8.0 * eps * (r.force + k * (std::abs(delta_pred) + c * r.force));
        // The identity's residual phi(F) = F - law(delta_pred - c F) has
        // slope 1 + c k_g <= 1 + c k in F: the forward error times (1 + c k)
        // (c k = 1e3 is ill-conditioned in this form, not in the solve).
        const double tol_residual = (1.0 + ck) * tol;
        // The pair (delta, F) the solve returns, F the law's at delta, lies on
        // the line delta + c F = delta_pred within the rounding of delta (8 eps
        // (|delta_pred| + c F), as above) plus c times the law's change over
        // it (k times that): (1 + c k) 8 eps (|delta_pred| + c F).
        const double line = std::abs(r.indentation + c * r.force - delta_pred);
        const double tol_line = (1.0 + ck) * 8.0 * eps * (std::abs(delta_pred) + c * r.force);
        // Independent: phi' >= 1, so a bisection on phi (to adjacent doubles,
        // phi evaluated within the same rounding) is within tol of the root.
        const double F_bis = bisection_root(liner, state, delta_pred, c);
        const double bis_error = std::abs(r.force - F_bis);
        std::printf("alpha %.2f c k %-6g delta_pred %-12.6g: F %.17g, |F - law(dp - cF)| %.2e "
                    "(tol %.2e), |delta + c F - dp| %.2e (tol %.2e), |F - bisection| %.2e "
                    "(tol %.2e), plastic %d\n",
                    state.hardening, ck, delta_pred, r.force, residual, tol_residual, line,
                    tol_line, bis_error, tol, r.plastic ? 1 : 0);
        EXPECT_LE(residual, tol_residual);
        EXPECT_LE(line, tol_line);
        EXPECT_LE(bis_error, 2.0 * tol);
        EXPECT_GE(r.force, 0.0);
        if (branch == 0) {
          EXPECT_EQ(r.force, 0.0);
          EXPECT_EQ(r.state.wear, state.wear);
        }
        // Elastic root k delta_pred / (1 + c k), plastic root
        // (F_Y + k_t (delta_pred - delta_Y)) / (1 + c k_t): the header's closed forms.
        if (branch == 1) {
          EXPECT_FALSE(r.plastic);
          EXPECT_NEAR(r.force, k * delta_pred / (1.0 + ck), tol);
        }
        if (branch == 2) {
          EXPECT_TRUE(r.plastic);
          const double kt = liner.tangent_stiffness();
          EXPECT_NEAR(r.force, (F_Y + kt * (delta_pred - delta_Y)) / (1.0 + c * kt), tol);
        }
        // State and work are the law's at the solved indentation, bit for
        // bit; the force is the root itself (within tol of the law's there,
        // |F - law(dp - cF)| above).
        const LinerBarResponse at = liner.bar_force(state, r.indentation);
        EXPECT_EQ(r.state.wear, at.state.wear);
        EXPECT_EQ(r.state.hardening, at.state.hardening);
        EXPECT_EQ(r.plastic_work, at.plastic_work);
        if (c == 0.0) { // c = 0 is the bar law itself, bit for bit
          const LinerBarResponse law = liner.bar_force(state, delta_pred);
          EXPECT_EQ(r.force, law.force);
          EXPECT_EQ(r.state.wear, law.state.wear);
          EXPECT_EQ(r.state.hardening, law.state.hardening);
          EXPECT_EQ(r.plastic_work, law.plastic_work);
        }
        worst = std::max(worst, residual / std::max(tol_residual, 1e-300));
        worst_bisection = std::max(worst_bisection, bis_error);
        ++checked;
      }
    }
  }
  std::printf("%d solves: worst residual / tol %.3f, worst |F - bisection| %.3e N\n", checked,
              worst, worst_bisection);
  EXPECT_EQ(checked, 48);
}

TEST(AbradableLiner, CellMap) {
  const AbradableLiner liner(geometry(), material());
  const double pitch = 2.0 * M_PI / 8;
  // Wrap: a sector's centre, a turn either way and many turns away, is the same
  // sector (theta + 2 pi k rounds within 64 k eps, far below pitch / 2).
  for (int i = 0; i < 8; ++i) {
    const double centre = (i + 0.5) * pitch;
    for (int turns : {-1000, -1, 0, 1, 2, 1000})
      EXPECT_EQ(liner.angular_cell(centre + 2.0 * M_PI * turns), i) << i << " " << turns;
  }
  // Exact edges (pitch = pi/4: 2 pitch and 4 pitch are pi/2 and pi in binary)
  // belong to the sector above them; 0 and 2 pi to sector 0; angles just
  // below 0 (or 2 pi) to the last sector.
  EXPECT_EQ(liner.angular_cell(0.0), 0);
  EXPECT_EQ(liner.angular_cell(-0.0), 0);
  EXPECT_EQ(liner.angular_cell(M_PI / 2), 2);
  EXPECT_EQ(liner.angular_cell(M_PI), 4);
  EXPECT_EQ(liner.angular_cell(2.0 * M_PI), 0);
  EXPECT_EQ(liner.angular_cell(std::nextafter(2.0 * M_PI, 0.0)), 7);
  EXPECT_EQ(liner.angular_cell(-1e-300), 7);
  EXPECT_EQ(liner.angular_cell(-std::numeric_limits<double>::denorm_min()), 7);
  // Every edge: a point 1e-12 rad each side (far above the 1e-15 rad of
  // rounding) lands in the sector on its side.
  for (int i = 0; i < 8; ++i) {
    const double edge = i * pitch;
    EXPECT_EQ(liner.angular_cell(edge + 1e-12), i) << "edge " << i;
    EXPECT_EQ(liner.angular_cell(edge - 1e-12), (i + 7) % 8) << "edge " << i;
  }
  // No gaps and no overlaps: walking the circle the sector rises by 0 or 1 and
  // visits every sector.
  int previous = liner.angular_cell(0.0), visited = 1;
  for (int s = 1; s < 100000; ++s) {
    const int now = liner.angular_cell(2.0 * M_PI * s / 100000);
    ASSERT_TRUE(now == previous || now == previous + 1) << s;
    visited += now != previous;
    previous = now;
  }
  EXPECT_EQ(visited, 8);
  // Rows of [0, 8], dz = 2: edges exact, z_max closes the last row.
  EXPECT_EQ(liner.axial_row(0.0), 0);
  EXPECT_EQ(liner.axial_row(2.0), 1);
  EXPECT_EQ(liner.axial_row(std::nextafter(2.0, 0.0)), 0);
  EXPECT_EQ(liner.axial_row(6.0), 3);
  EXPECT_EQ(liner.axial_row(8.0), 3);
  EXPECT_EQ(liner.cell(M_PI + 0.1, 5.0), 2 * 8 + 4);
  // Outside [z_min, z_max] the point is not over the liner: refused.
  for (double z : {-1e-12, 8.0 + 1e-12, -1.0, 100.0, std::nan("")}) {
    try {
      liner.axial_row(z);
      ADD_FAILURE() << "z = " << z << " accepted";
    } catch (const std::invalid_argument& e) {
      std::printf("z = %g: %s\n", z, e.what());
      EXPECT_NE(std::string(e.what()).find("axial coordinate"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("[z_min, z_max] = [0, 8]"), std::string::npos);
    }
  }
  EXPECT_THROW(liner.angular_cell(std::nan("")), std::invalid_argument);
  EXPECT_THROW(liner.angular_cell(std::numeric_limits<double>::infinity()), std::invalid_argument);
}

TEST(AbradableLiner, HugeYieldStressLeavesNoWear) {
  // sigma_y = 1e300 MPa: the trial stress of the same path (<= 50 MPa) never yields.
  AbradableLiner liner(geometry(), material(1e300));
  const ClosedForm cf(geometry(), material(1e300));
  std::vector<double> path = ramp(0.0, 0.1, 100);
  const std::vector<double> down = ramp(0.1, -0.05, 150);
  path.insert(path.end(), down.begin(), down.end());
  double worst = 0.0;
  for (int cell = 0; cell < liner.n_cells(); ++cell) {
    const std::vector<double> forces = indent(liner, cell, path);
    for (std::size_t s = 0; s < path.size(); ++s)
      worst = std::max(worst, std::abs(forces[s] - std::max(0.0, cf.k * path[s])));
    EXPECT_EQ(liner.wear(cell), 0.0);
    EXPECT_EQ(liner.state(cell).hardening, 0.0);
    // The compliant solve as well, far past where sigma_y = 10 MPa would yield.
    const LinerBarResponse r = liner.compliant_force(liner.state(cell), 1.0, 1.0 / cf.k);
    EXPECT_FALSE(r.plastic);
    EXPECT_EQ(r.state.wear, 0.0);
  }
  // The elastic line k d: the trial and A sigma, a few eps of k d_max.
  const double tol = 8.0 * eps * cf.k * 0.1;
  std::printf("sigma_y 1e300: wear 0 in all %d cells, plastic work %g, worst |F - k d| %.3e "
              "(tol %.3e)\n",
              liner.n_cells(), liner.plastic_work(), worst, tol);
  EXPECT_EQ(liner.plastic_work(), 0.0);
  EXPECT_LE(worst, tol);
}

TEST(AbradableLiner, CommitRefusesAStaleResponse) {
  AbradableLiner liner(geometry(), material());
  const LinerCellState virgin = liner.state(0);
  liner.commit(0, liner.bar_force(virgin, 0.1));
  ASSERT_GT(liner.wear(0), 0.0);
  const double work = liner.plastic_work();
  // A response computed from the virgin state at a shallower depth would
  // lower the wear: refused, and nothing changes.
  EXPECT_THROW(liner.commit(0, liner.bar_force(virgin, 0.05)), std::invalid_argument);
  EXPECT_EQ(liner.plastic_work(), work);
  EXPECT_THROW(liner.state(-1), std::invalid_argument);
  EXPECT_THROW(liner.state(liner.n_cells()), std::invalid_argument);
  EXPECT_THROW(liner.bar_force(LinerCellState{-1e-9, 0.0}, 0.1), std::invalid_argument);
  EXPECT_THROW(liner.bar_force(virgin, std::nan("")), std::invalid_argument);
  EXPECT_THROW(liner.compliant_force(virgin, 0.1, -1.0), std::invalid_argument);
}

TEST(AbradableLiner, RefusesBadParameters) {
  struct Bad {
    std::function<void(LinerGeometry&, LinerMaterial&)> spoil;
    std::string says;
  };
  const std::vector<Bad> bad = {
      {[](LinerGeometry& g, LinerMaterial&) { g.thickness = 0.0; }, "thickness h = 0 must be"},
      {[](LinerGeometry& g, LinerMaterial&) { g.thickness = -1.0; }, "thickness h = -1 must be"},
      {[](LinerGeometry& g, LinerMaterial&) { g.thickness = 300.0; }, "must be < radius r"},
      {[](LinerGeometry& g, LinerMaterial&) {
         g.radius = std::numeric_limits<double>::quiet_NaN();
       },
       "radius r = nan must be"},
      {[](LinerGeometry& g, LinerMaterial&) { g.n_theta = 0; }, "n_theta = 0 must be >= 1"},
      {[](LinerGeometry& g, LinerMaterial&) { g.n_axial = -2; }, "n_axial = -2 must be >= 1"},
      {[](LinerGeometry& g, LinerMaterial&) { g.z_max = g.z_min; }, "z_min < z_max"},
      {[](LinerGeometry& g, LinerMaterial&) {
         g.n_theta = 1 << 20;
         g.n_axial = 1 << 12;
       },
       "must be <= 2147483647"},
      {[](LinerGeometry&, LinerMaterial& m) { m.young = 0.0; }, "Young's modulus E = 0 must be"},
      {[](LinerGeometry&, LinerMaterial& m) { m.yield = -5.0; }, "yield stress sigma_y = -5"},
      {[](LinerGeometry&, LinerMaterial& m) { m.yield = 0.0; }, "yield stress sigma_y = 0"},
      {[](LinerGeometry&, LinerMaterial& m) { m.hardening = -1.0; },
       "hardening modulus H = -1 must be finite and >= 0"},
      {[](LinerGeometry&, LinerMaterial& m) { m.hardening = HUGE_VAL; },
       "hardening modulus H = inf"},
  };
  for (const Bad& b : bad) {
    LinerGeometry g = geometry();
    LinerMaterial m = material();
    b.spoil(g, m);
    try {
      const AbradableLiner liner(g, m);
      (void)liner;
      ADD_FAILURE() << "accepted; expected: " << b.says;
    } catch (const std::invalid_argument& e) {
      std::printf("%s\n", e.what());
      EXPECT_NE(std::string(e.what()).find(b.says), std::string::npos) << e.what();
    }
  }
  // H = 0 (perfect plasticity) is in range.
  EXPECT_NO_THROW({
    const AbradableLiner perfectly_plastic(geometry(), material(10.0, 0.0));
    (void)perfectly_plastic;
  });
}

} // namespace
} // namespace rsi

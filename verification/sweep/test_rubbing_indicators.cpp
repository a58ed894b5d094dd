// The indicators of a component sweep's run (sweep/rubbing_indicators.hpp)
// on rows whose answers are known: the transient cut, the contact nodes'
// radial displacement u_r = g0(t) - g (constant gap, and the oval casing at
// its deepest point), the contact fraction as a share of rows (not of
// (node, row) pairs), the energy ratio and its undefined case; against a
// flexible casing (no imposed gap) the largest |u| of the response dof and
// the rest as before.

#include <cmath>

#include <gtest/gtest.h>

#include "rubbing_indicators.hpp"

namespace rsi {
namespace {

/// Two contact nodes on the x and y axes at radius 100 (dofs 0-2, 3-5).
std::vector<RigidSurfaceNode> two_nodes() {
  RigidSurfaceNode a, b;
  a.dofs = {{0, 1, 2}};
  a.position = Eigen::Vector3d(100.0, 0.0, 0.0);
  b.dofs = {{3, 4, 5}};
  b.position = Eigen::Vector3d(0.0, 100.0, 0.0);
  return {a, b};
}

TEST(RubbingIndicators, KnownRowsGiveKnownIndicators) {
  const double g0 = 0.1;
  const RigidSurfaceContact casing(two_nodes(), ImposedGap::constant(g0), 1000.0, 0.1);
  // Rows every 1 ms, transient 2 ms: rows at t = 0, 1 (skipped), 2 .. 5 ms read.
  RubbingIndicatorAccumulator acc(casing, 2e-3, 1e-3);
  for (int i = 0; i < 6; ++i) {
    Eigen::VectorXd gap(2), lambda(2);
    // u_r = g0 - g: node 1 moves out by 0.01 i, node 2 in by 0.02 i; 9 before the transient.
    gap << (i < 2 ? -9.0 : g0 - 0.01 * i), (i < 2 ? -9.0 : g0 + 0.02 * i);
    lambda << (i == 3 ? 50.0 : 0.0), (i >= 3 ? 20.0 * i : 0.0);
    const HistoryRow row{i * 1e-3, gap, lambda, 1.0 + i, 0.0, 0.0, 0.0};
    acc.add(row, 0.5 * i);
  }
  const RubbingIndicators s = acc.finish();
  std::printf("rows %d, max |u_r| %.17g, force %.17g, fraction %.17g, energy ratio %.17g\n", s.rows,
              s.max_tip_radial, s.max_contact_force, s.contact_fraction, s.energy_ratio);
  EXPECT_EQ(s.rows, 4);
  // |g0 - g| of node 2 at 5 ms, 0.02 x 5, to the round-off of g0 + 0.1 - g0 (1 ulp of 0.2).
  EXPECT_NEAR(s.max_tip_radial, 0.1, 1e-16);
  EXPECT_DOUBLE_EQ(s.max_contact_force, 100.0); // node 2 at 5 ms
  EXPECT_DOUBLE_EQ(s.contact_fraction, 3.0 / 4.0); // rows 3, 4, 5 ms of 4 (pairs would be 4/8)
  EXPECT_DOUBLE_EQ(s.energy_ratio, 6.0 / 3.0);  // E(5 ms) / E(2 ms)
  EXPECT_EQ(s.peaks.size(), 1u);                // 4 samples of a ramp: one local maximum
}

TEST(RubbingIndicators, OvalGapIsReadAtTheRowsTime) {
  // Omega t = pi/2 at t = 1 ms: node 1 (phi = 0) at the oval's deepest
  // point, g0 = -g_m (rigid_surface_contact.hpp); g = 0 there, so u_r = -g_m.
  const double g_m = 0.356, omega = 0.5 * M_PI / 1e-3;
  const RigidSurfaceContact casing(two_nodes(), ImposedGap::oval(g_m, 0.15), omega, 0.0);
  RubbingIndicatorAccumulator acc(casing, 1e-3, 1e-3);
  const Eigen::VectorXd gap = Eigen::VectorXd::Zero(2), lambda = Eigen::VectorXd::Zero(2);
  const HistoryRow row{1e-3, gap, lambda, 0.0, 0.0, 0.0, 0.0};
  acc.add(row, 0.0);
  const RubbingIndicators s = acc.finish();
  std::printf("max |u_r| %.17g, expected g_m = %.17g\n", s.max_tip_radial, g_m);
  // exp(-(d/w)^2) with d of order 1e-16 (pi/2 rounded): 1 to 1e-30; g_m to 1 ulp.
  EXPECT_NEAR(s.max_tip_radial, g_m, 1e-15);
  EXPECT_TRUE(std::isnan(s.energy_ratio)); // E = 0 from the first row: undefined
  EXPECT_EQ(s.contact_fraction, 0.0);
}

TEST(RubbingIndicators, FlexibleCasingReadsTheResponseNotTheGap) {
  // The rows of KnownRowsGiveKnownIndicators without a casing law: the gap
  // is the two bodies' and is not read; the response 0.5 i, its largest
  // |u| after the transient 0.5 x 5 at 5 ms (exact in binary); a response
  // of -3 before the transient is skipped.
  RubbingIndicatorAccumulator acc(2e-3, 1e-3);
  for (int i = 0; i < 6; ++i) {
    Eigen::VectorXd gap(3), lambda(3); // any number of contacts: no law to match
    gap << -9.0, 1.0, 2.0;
    lambda << (i == 3 ? 50.0 : 0.0), (i >= 3 ? 20.0 * i : 0.0), 0.0;
    const HistoryRow row{i * 1e-3, gap, lambda, 1.0 + i, 0.0, 0.0, 0.0};
    acc.add(row, i < 2 ? -3.0 : 0.5 * i);
  }
  const RubbingIndicators s = acc.finish();
  std::printf("rows %d, max |u| %.17g, max |u_r| %.17g, force %.17g, fraction %.17g, energy "
              "ratio %.17g\n",
              s.rows, s.max_abs_response, s.max_tip_radial, s.max_contact_force,
              s.contact_fraction, s.energy_ratio);
  EXPECT_EQ(s.rows, 4);
  EXPECT_EQ(s.max_abs_response, 2.5);
  EXPECT_EQ(s.max_tip_radial, 0.0); // not read: no imposed gap
  EXPECT_EQ(s.max_contact_force, 100.0);
  EXPECT_EQ(s.contact_fraction, 3.0 / 4.0);
  EXPECT_EQ(s.energy_ratio, 6.0 / 3.0);
}

TEST(RubbingIndicators, RigidCasingRefusesAnotherContactCount) {
  const RigidSurfaceContact casing(two_nodes(), ImposedGap::constant(0.1), 1000.0, 0.1);
  RubbingIndicatorAccumulator acc(casing, 0.0, 1e-3);
  const Eigen::VectorXd three = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(acc.add(HistoryRow{0.0, three, three, 0.0, 0.0, 0.0, 0.0}, 0.0),
               std::invalid_argument);
}

} // namespace
} // namespace rsi

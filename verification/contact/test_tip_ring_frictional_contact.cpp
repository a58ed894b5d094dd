// The 2D tip/ring law as a FrictionalContactLaw (SPEC §2-3, issue 12 items
// 1-2): its gap and rows against TipCasingContact, its slip increment at
// rest and its linearisation, on the default case.

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "case_file.hpp"
#include "casing.hpp"
#include "tip_casing_contact.hpp"
#include "tip_ring_frictional_contact.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

struct Parts {
  Case c;
  BladedDisk bd;
  Casing casing;
  int n = 0;
};

Parts parts() {
  Parts p;
  p.c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
  p.bd = assemble_bladed_disk(p.c);
  p.casing = assemble_casing(p.c);
  p.n = p.bd.n_dofs() + static_cast<int>(p.casing.dofs.size());
  return p;
}

/// A random state of 1e-4 m (tips and casing) on the dofs the law reads.
Eigen::VectorXd random_state(const FrictionalContactLaw& law, int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1e-4, 1e-4);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (int dof : law.dofs_read(n))
    x(dof) = u(rng);
  return x;
}

Eigen::VectorXd dense(const SparseRow& row, int n) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  for (const auto& [dof, value] : row)
    r(dof) += value;
  return r;
}

TEST(TipRingFrictionalContact, SameGeometryAsTipCasingContact) {
  const Parts p = parts();
  const TipRingFrictionalContact law(p.bd, p.casing, p.c);
  const TipCasingContact old_law(p.bd, p.casing, p.c);
  ASSERT_EQ(law.n_contacts(), old_law.n_constraints());
  EXPECT_EQ(law.friction_coefficient(), old_law.friction_coefficient());
  std::mt19937 rng(22);
  const double dt = 5e-7;
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd xn = random_state(law, p.n, rng);
    const Eigen::VectorXd xp = random_state(law, p.n, rng);
    const double t = 1.3e-3 * (trial + 1);
    FrictionalContactGeometry geo;
    law.evaluate(xn, xp, t, dt, geo);
    ContactState s;
    old_law.evaluate(xp, (xp - xn) / dt, t, s);
    double worst_gap = 0.0, worst_row = 0.0;
    for (int k = 0; k < law.n_contacts(); ++k) {
      // Same formula for the gap (R_c + u_c - (R_t + u)): equal within the
      // rounding of a 4-term sum of terms below R_c: 4 eps R_c.
      worst_gap = std::max(worst_gap, std::abs(geo.normal_gap(k) - s.gap(k)));
      EXPECT_LE(std::abs(geo.normal_gap(k) - s.gap(k)), 4 * eps * p.casing.radius);
      // G: the same row, same values (same Hermite values at the same alpha).
      EXPECT_EQ(dense(geo.rows[2 * k], p.n), dense(s.gradient[k], p.n));
      // D = mu s T_old + G, T_old = -T: T = -(D - G)/(mu s); the sign s is
      // +1 here (tip speed Omega R_t = 155 m/s): mu s T_old is one rounding
      // of T_old, the division one more, the subtraction of G (disjoint dofs)
      // exact: 2 eps relative to the largest entry (1).
      ASSERT_NE(s.friction_sign(k), 0.0);
      const Eigen::VectorXd t_old = (dense(s.direction[k], p.n) - dense(s.gradient[k], p.n)) /
                                    (old_law.friction_coefficient() * s.friction_sign(k));
      const double row_error = (dense(geo.rows[2 * k + 1], p.n) + t_old).cwiseAbs().maxCoeff();
      worst_row = std::max(worst_row, row_error);
      EXPECT_LE(row_error, 2 * eps);
      // The old law's sliding velocity at v = (u~ - u_n)/dt, times dt, is the
      // slip increment (same alpha, same Hermite values): equal up to the
      // rounding of (u~ - u_n)/dt * dt and of 6-term sums of terms below
      // 3e-4 m (increments 2e-4, Omega R_t dt 7.8e-5): 16 eps 3e-4 m.
      EXPECT_LE(std::abs(geo.slip(k) - s.sliding_velocity(k) * dt), 16 * eps * 3e-4);
    }
    std::printf("trial %d: |g - g_old| <= %.2e m, |T + T_old| <= %.2e\n", trial, worst_gap,
                worst_row);
  }
}

TEST(TipRingFrictionalContact, AtRestAndLinearisation) {
  Parts p = parts();
  const double dt = 5e-7;
  const double omega = p.c.operating_point.rotation_speed;
  const double rt = p.c.bladed_disk.tip_radius;
  const TipRingFrictionalContact law(p.bd, p.casing, p.c);
  FrictionalContactGeometry geo;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.n);
  law.evaluate(zero, zero, 2e-3, dt, geo);
  for (int k = 0; k < law.n_contacts(); ++k) {
    // At rest: g~ = R_c - R_t, exact (Sterbenz: R_c / R_t within a factor 2),
    // and s~ = Omega R_t dt, two roundings: 2 eps relative.
    EXPECT_EQ(geo.normal_gap(k), p.casing.radius - rt);
    EXPECT_LE(std::abs(geo.slip(k) - omega * rt * dt), 2 * eps * omega * rt * dt);
  }
  std::printf("at rest: g~ = %.6e m, s~ = %.17g m (Omega R_t dt = %.17g m)\n", geo.normal_gap(0),
              geo.slip(0), omega * rt * dt);

  // Casing v, v_s moved by dv (tips at rest, so alpha~ unchanged): s = s~ + T dv
  // exactly up to rounding of the 4-term Hermite sum (terms <= 1e-4 m): 8 eps 1e-4.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1e-4, 1e-4);
  Eigen::VectorXd dv = Eigen::VectorXd::Zero(p.n);
  for (int first : p.casing.node_first_dof)
    if (first >= 0)
      for (int d = 2; d < 4; ++d)
        dv(p.bd.n_dofs() + first + d) = u(rng);
  FrictionalContactGeometry moved;
  law.evaluate(zero, dv, 2e-3, dt, moved);
  for (int k = 0; k < law.n_contacts(); ++k)
    EXPECT_LE(std::abs(moved.slip(k) - (geo.slip(k) + dot(geo.rows[2 * k + 1], dv))),
              8 * eps * 1e-4 + 2 * eps * omega * rt * dt);
  // Tip u and v moved: s = s~ + T du + Omega du_u dt, the term T leaves out
  // (tip_ring_frictional_contact.hpp); 4 roundings of terms <= 2e-4 m.
  Eigen::VectorXd du = Eigen::VectorXd::Zero(p.n);
  for (int k = 0; k < law.n_contacts(); ++k) {
    du(p.bd.tip_radial[k]) = u(rng);
    du(p.bd.tip_tangential[k]) = u(rng);
  }
  law.evaluate(zero, du, 2e-3, dt, moved);
  for (int k = 0; k < law.n_contacts(); ++k) {
    const double omitted = omega * du(p.bd.tip_radial[k]) * dt;
    EXPECT_LE(std::abs(moved.slip(k) - (geo.slip(k) + dot(geo.rows[2 * k + 1], du) + omitted)),
              4 * eps * 2e-4);
    // The gap: G du exactly (casing at rest: the tip's own -du_u).
    EXPECT_LE(std::abs(moved.normal_gap(k) - (geo.normal_gap(k) + dot(geo.rows[2 * k], du))),
              4 * eps * p.casing.radius);
  }

  // At Omega = 0 a state at rest does not slide: s~ = 0 exactly.
  p.c.operating_point.rotation_speed = 0.0;
  const TipRingFrictionalContact still(p.bd, p.casing, p.c);
  still.evaluate(zero, zero, 2e-3, dt, geo);
  EXPECT_EQ(geo.slip.cwiseAbs().maxCoeff(), 0.0);
}

TEST(TipRingFrictionalContact, RejectsBadArguments) {
  const Parts p = parts();
  const TipRingFrictionalContact law(p.bd, p.casing, p.c);
  FrictionalContactGeometry geo;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.n);
  EXPECT_THROW(law.evaluate(zero, zero, 0.0, 0.0, geo), std::invalid_argument);
  EXPECT_THROW(law.evaluate(zero, Eigen::VectorXd::Zero(p.n - 1), 0.0, 1e-6, geo),
               std::invalid_argument);
  EXPECT_THROW(law.evaluate(zero, zero, NAN, 1e-6, geo), std::invalid_argument);
  EXPECT_THROW(law.dofs_read(p.n - 1), std::invalid_argument);
}

} // namespace
} // namespace rsi

// Reduced models at any speed from one subspace (speed_subspace.hpp) on the
// gmsh blade's rotation fit (200 .. 2000 rad/s, test_rotation_fit's), the
// subspace spanned by the method's bases at 0, 1000 and 2000 rad/s.
//
// 1. At a basis speed (1000 rad/s) the subspace holds the direct basis, so
//    every Rayleigh-Ritz solution inside it is the direct one: CB's
//    fixed-interface modes and constraint modes, MacNeal's free modes and
//    the static response K^-1 B (its residual attachment modes plus the
//    free modes' part). Checked on two invariants of the reduced model that
//    do not depend on its coordinates: the boundary's static stiffness
//    (the Schur complement of K^ on the boundary, = B^T K^-1 B inverted,
//    exact when K^-1 B is in the span) and the lowest natural frequencies
//    with the boundary free (the pencil's, or MacNeal's kept modes). Both
//    to rounding: the subspace's orthonormalisation and two projections,
//    ~ r_g eps cond(K): 1e-7 relative asserted (cond(K) ~ 1e8 for this
//    blade, r_g eps ~ 1e-13; the Schur complement loses cond(K^_ii)).
// 2. Between basis speeds (600 rad/s) the subspace model is a Ritz model of
//    the full K(Omega): its CB pencil's eigenvalues are upper bounds of the
//    full model's (Rayleigh-Ritz), as are the direct CB's; both printed
//    with their distance to the full model's.
// 3. The bases built on two threads give the same subspace, bit for bit
//    (each basis is one reduce() on its own K(Omega); only who builds it
//    changes): the sweep's rows must not depend on --jobs.
//
// Skipped (GTEST_SKIP, reason printed) when ccx or gmsh is not on PATH.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include "case_file.hpp"
#include "child_process.hpp"
#include "component_case.hpp"
#include "gmsh_blade_fit.hpp"
#include "modal_analysis.hpp"
#include "reduction.hpp"
#include "rotation_fit.hpp"
#include "speed_subspace.hpp"

namespace {

class SpeedSubspaceBlade : public rsi::testing::GmshBladeFit {};

/// The boundary's static stiffness: K^_bb - K^_bi K^_ii^-1 K^_ib.
Eigen::MatrixXd boundary_stiffness(const rsi::ReducedBasis& b) {
  const int r = b.n_reduced(), nb = static_cast<int>(b.boundary_position.size());
  std::vector<int> interior;
  std::vector<bool> on(static_cast<size_t>(r), false);
  for (int p : b.boundary_position) on[static_cast<size_t>(p)] = true;
  for (int i = 0; i < r; ++i)
    if (!on[static_cast<size_t>(i)]) interior.push_back(i);
  const int ni = static_cast<int>(interior.size());
  Eigen::MatrixXd kbb(nb, nb), kbi(nb, ni), kii(ni, ni);
  for (int a = 0; a < nb; ++a) {
    for (int c = 0; c < nb; ++c) kbb(a, c) = b.stiffness(b.boundary_position[a], b.boundary_position[c]);
    for (int c = 0; c < ni; ++c) kbi(a, c) = b.stiffness(b.boundary_position[a], interior[c]);
  }
  for (int a = 0; a < ni; ++a)
    for (int c = 0; c < ni; ++c) kii(a, c) = b.stiffness(interior[a], interior[c]);
  return kbb - kbi * kii.ldlt().solve(kbi.transpose());
}

/// The lowest natural frequencies of the reduced model, boundary free [rad^2/s^2].
Eigen::VectorXd reduced_eigenvalues(const rsi::ReducedBasis& b, int count) {
  if (b.massless_boundary) return b.mode_omega.head(count).cwiseAbs2();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> e(b.stiffness, b.mass,
                                                                     Eigen::EigenvaluesOnly);
  return e.eigenvalues().head(count);
}

void compare_at_basis_speed(const rsi::RotationFit& fit, const std::string& method, int modes) {
  const rsi::SpeedSubspace s = rsi::speed_subspace(fit, method, modes, {0.0, 1000.0, 2000.0});
  const rsi::RotatingComponent at = rsi::rotating_component_at(fit, 1000.0);
  const rsi::ReducedBasis direct =
      rsi::reduce(at.component.stiffness, at.component.mass, at.component.boundary, method, modes);
  const rsi::ReducedBasis sub = rsi::reduce_at_speed(s, fit, 1000.0);
  const Eigen::MatrixXd sd = boundary_stiffness(direct), ss = boundary_stiffness(sub);
  const double k_error = (ss - sd).cwiseAbs().maxCoeff() / sd.cwiseAbs().maxCoeff();
  const int count = 5;
  const Eigen::VectorXd ld = reduced_eigenvalues(direct, count), ls = reduced_eigenvalues(sub, count);
  const double lambda_error = (ls.array() / ld.array() - 1.0).abs().maxCoeff();
  std::printf("%s-%d at 1000 rad/s (a basis speed): subspace %d coordinates (built in %.2f s), "
              "reduced %d; boundary stiffness %.2e, %d lowest eigenvalues %.2e relative to the "
              "direct basis's; reduced at this speed in %.3f s (direct %.3f s)\n",
              method.c_str(), modes, s.n_subspace(), s.build_seconds, sub.n_reduced(), k_error,
              count, lambda_error, sub.build_seconds, direct.build_seconds);
  EXPECT_EQ(sub.n_reduced(), direct.n_reduced());
  EXPECT_LT(k_error, 1e-7);
  EXPECT_LT(lambda_error, 1e-7);
}

TEST_F(SpeedSubspaceBlade, CraigBamptonAtABasisSpeedIsTheDirectBasis) {
  compare_at_basis_speed(fit, "cb", 10);
}

TEST_F(SpeedSubspaceBlade, MacNealAtABasisSpeedIsTheDirectBasis) {
  compare_at_basis_speed(fit, "macneal", 10);
}

TEST_F(SpeedSubspaceBlade, BetweenBasisSpeedsARitzModel) {
  const rsi::SpeedSubspace s = rsi::speed_subspace(fit, "cb", 10, {0.0, 1000.0, 2000.0});
  const double speed = 600.0;
  const rsi::RotatingComponent at = rsi::rotating_component_at(fit, speed);
  const int count = 5;
  const rsi::Modes full = rsi::lowest_modes(at.component.stiffness, at.component.mass, count);
  const Eigen::VectorXd ld = reduced_eigenvalues(
      rsi::reduce(at.component.stiffness, at.component.mass, at.component.boundary, "cb", 10), count);
  const Eigen::VectorXd ls = reduced_eigenvalues(rsi::reduce_at_speed(s, fit, speed), count);
  for (int i = 0; i < count; ++i) {
    const double exact = full.omega_squared(i);
    std::printf("600 rad/s mode %d: full %.6e, direct CB-10 %+.2e, subspace CB-10 %+.2e (relative)\n",
                i + 1, exact, ld(i) / exact - 1.0, ls(i) / exact - 1.0);
    // Rayleigh-Ritz: no reduced eigenvalue below the full model's (to the
    // eigensolvers' rounding, 1e-10 relative).
    EXPECT_GT(ls(i), exact * (1.0 - 1e-10));
    EXPECT_GT(ld(i), exact * (1.0 - 1e-10));
  }
}

TEST_F(SpeedSubspaceBlade, TwoThreadsBuildTheSameSubspace) {
  const std::vector<double> speeds = {0.0, 1000.0, 2000.0};
  const rsi::SpeedSubspace one = rsi::speed_subspace(fit, "macneal", 10, speeds, 1);
  const rsi::SpeedSubspace two = rsi::speed_subspace(fit, "macneal", 10, speeds, 2);
  std::printf("MacNeal-10 subspace, 3 basis speeds: %.2f s on one thread, %.2f s on two\n",
              one.build_seconds, two.build_seconds);
  ASSERT_EQ(one.n_subspace(), two.n_subspace());
  EXPECT_TRUE((one.transformation.array() == two.transformation.array()).all());
  EXPECT_TRUE((one.rest_stiffness.array() == two.rest_stiffness.array()).all());
  EXPECT_TRUE((one.mass.array() == two.mass.array()).all());
  ASSERT_EQ(one.terms.size(), two.terms.size());
  for (size_t q = 0; q < one.terms.size(); ++q)
    EXPECT_TRUE((one.terms[q].array() == two.terms[q].array()).all()) << "term " << q;
}

} // namespace

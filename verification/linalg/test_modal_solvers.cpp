// V2/V3: the sparse modal path (Spectra shift-invert Lanczos, for refined
// models) against the dense path (LAPACKE dsygvd) on the default models.

#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "modal_analysis.hpp"

namespace rsi {
namespace {

Case default_case() {
  return load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
}

void compare(const std::string& name, const Eigen::SparseMatrix<double>& k,
             const Eigen::SparseMatrix<double>& m, int count) {
  const Modes dense = lowest_modes(k, m, count, ModalSolver::dense);
  const Modes sparse = lowest_modes(k, m, count, ModalSolver::sparse);
  const int n = static_cast<int>(k.rows());
  const double eps = std::numeric_limits<double>::epsilon();
  const double k_norm = Eigen::MatrixXd(k).cwiseAbs().rowwise().sum().maxCoeff();
  // Scaled differences: |d lambda_i| / (n eps lambda_max) and
  // |K phi - lambda M phi| / (||K|| |phi|), the units of the two solvers' error bounds.
  double value_error = 0.0;
  double residual = 0.0;
  for (int i = 0; i < count; ++i) {
    value_error = std::max(value_error, std::abs(sparse.omega_squared(i) - dense.omega_squared(i)));
    const Eigen::VectorXd phi = sparse.shapes.col(i);
    residual = std::max(residual, (k * phi - sparse.omega_squared(i) * (m * phi)).norm() /
                                      (k_norm * phi.norm()));
  }
  const double lambda_max = dense.omega_max * dense.omega_max;
  const double scaled_value_error = value_error / (n * eps * lambda_max);
  const double max_error = std::abs(sparse.omega_max - dense.omega_max) / dense.omega_max;
  // Mass-normalised and M-orthogonal, whatever the solver.
  const Eigen::MatrixXd gram = sparse.shapes.transpose() * m * sparse.shapes;
  const double gram_error = (gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff();
  std::printf(
      "%s, lowest %d: max|d omega^2| = %.3e = %.3f n eps lambda_max; omega_max rel. diff. %.3e; "
      "max|Phi^T M Phi - I| %.3e; max |K phi - w2 M phi|/(|K| |phi|) %.3e\n",
      name.c_str(), count, value_error, scaled_value_error, max_error, gram_error, residual);
  // dsygvd is backward stable: |d lambda| <= p(n) eps lambda_max (Weyl), p(n) = n;
  // Lanczos converged to 1e-12 adds much less.
  EXPECT_LE(scaled_value_error, 1.0);
  // Both solvers find omega_max to near machine precision (dense: exact
  // backward error on the largest; Lanczos tolerance 1e-12).
  EXPECT_LE(max_error, 1e-11);
  // Lanczos B-orthonormalises its basis: round-off n eps.
  EXPECT_LE(gram_error, n * eps);
  // Spectra's stopping test |K^-1 M phi - theta phi| <= 1e-12 |theta| maps to
  // |K phi - lambda M phi| <= 1e-12 ||K|| |phi|; a factor 10 for the norms.
  EXPECT_LE(residual, 1e-11);
}

TEST(ModalSolvers, SparseMatchesDenseOnTheBladedDisk) {
  const BladedDisk bd = assemble_bladed_disk(default_case());
  compare("bladed disk", bd.stiffness, bd.mass, 60);
}

TEST(ModalSolvers, SparseMatchesDenseOnTheCasing) {
  const Casing casing = assemble_casing(default_case());
  compare("casing", casing.stiffness, casing.mass, 30);
}

TEST(ModalSolvers, SingularStiffnessGivesItsRigidMode) {
  // A free hub leaves the rigid rotation: K singular, shift-invert about 0
  // impossible; the sparse path solves about a shift below the spectrum and
  // reports the rotation as a zero mode (it refused the model before).
  const BladedDisk bd = assemble_bladed_disk(default_case(), HubSupport::free);
  const Modes modes = lowest_modes(bd.stiffness, bd.mass, 10, ModalSolver::sparse);
  std::printf("free hub: lambda_1 %.3e within its uncertainty %.3e (zero), lambda_2 %.6e, shift %g\n",
              modes.omega_squared(0), modes.accuracy.uncertainty(0), modes.omega_squared(1),
              modes.accuracy.shift);
  EXPECT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
  EXPECT_EQ(modes.accuracy.n_zero, 1); // the one rigid rotation
  EXPECT_TRUE(modes.is_zero(0));
}

} // namespace
} // namespace rsi

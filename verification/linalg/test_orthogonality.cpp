// V3: the computed modes of both parts are M- and K-orthogonal:
// Phi^T M Phi = I and Phi^T K Phi = diag(omega^2).

#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "modal_analysis.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

Case default_case() {
  return load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
}

/// Infinity norm: an upper bound of the 2-norm of a symmetric matrix.
double norm_inf(const Eigen::SparseMatrix<double>& a) {
  return Eigen::MatrixXd(a).cwiseAbs().rowwise().sum().maxCoeff();
}

void check_orthogonality(const std::string& name, const Eigen::SparseMatrix<double>& k,
                         const Eigen::SparseMatrix<double>& m, int count) {
  const Modes modes = lowest_modes(k, m, static_cast<int>(k.rows()));
  const Eigen::MatrixXd phi = modes.shapes.leftCols(count);
  const int n = static_cast<int>(k.rows());
  const Eigen::MatrixXd mass_error =
      phi.transpose() * m * phi - Eigen::MatrixXd::Identity(count, count);
  const Eigen::MatrixXd stiffness_error =
      phi.transpose() * k * phi - Eigen::MatrixXd(modes.omega_squared.head(count).asDiagonal());
  const double phi_norm2 = phi.colwise().squaredNorm().maxCoeff();
  // Backward stability of dsygvd plus the products: errors <= n eps ||A|| max|phi|^2.
  const double mass_bound = n * eps * norm_inf(m) * phi_norm2;
  const double stiffness_bound = n * eps * norm_inf(k) * phi_norm2;
  std::printf("%s: max|Phi^T M Phi - I| = %.3e (bound %.3e), max|Phi^T K Phi - Omega^2| = %.3e "
              "(bound %.3e, "
              "omega^2_max of the set %.3e)\n",
              name.c_str(), mass_error.cwiseAbs().maxCoeff(), mass_bound,
              stiffness_error.cwiseAbs().maxCoeff(), stiffness_bound,
              modes.omega_squared(count - 1));
  EXPECT_LE(mass_error.cwiseAbs().maxCoeff(), mass_bound);
  EXPECT_LE(stiffness_error.cwiseAbs().maxCoeff(), stiffness_bound);
}

TEST(Orthogonality, BladedDiskModes) {
  const BladedDisk bd = assemble_bladed_disk(default_case());
  check_orthogonality("bladed disk, all modes", bd.stiffness, bd.mass, bd.n_dofs());
  check_orthogonality("bladed disk, lowest 110", bd.stiffness, bd.mass, 110);
}

TEST(Orthogonality, CasingModes) {
  const Casing casing = assemble_casing(default_case());
  check_orthogonality("casing, all modes", casing.stiffness, casing.mass, casing.n_dofs());
}

} // namespace
} // namespace rsi

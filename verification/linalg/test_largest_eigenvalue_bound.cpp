// The cheap lower bound of lambda_max of (K, M) that the stability check
// uses before any eigensolver (reference/linalg/largest_eigenvalue_bound,
// issue 13, class 9). Checked against the dense generalized eigensolver
// (LAPACK through Eigen, independent of the power method) on the default
// parts and a 400-element casing: the bound never exceeds lambda_max (the
// defining property: a Rayleigh quotient lowered by its rounding bound), and
// it improves on the one-dof quotient K_ii / M_ii the check used before
// (3 to 6 times under lambda_max on these parts).

#include <cstdio>
#include <string>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "case_file.hpp"
#include "casing.hpp"
#include "largest_eigenvalue_bound.hpp"

namespace rsi {
namespace {

const Case& default_case() {
  static const Case c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
  return c;
}

void check_bound(const char* part, const Eigen::SparseMatrix<double>& k,
                 const Eigen::SparseMatrix<double>& m) {
  const LargestEigenvalueBound bound = largest_eigenvalue_lower_bound(k, m);
  const double exact = Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(
                           Eigen::MatrixXd(k), Eigen::MatrixXd(m), Eigen::EigenvaluesOnly)
                           .eigenvalues()
                           .maxCoeff();
  std::printf("%s (%ld dofs): lambda_max %.10g, bound %.10g (%.3g under), one dof %.4g (%.3g "
              "under), %d power steps\n",
              part, static_cast<long>(k.rows()), exact, bound.value, 1.0 - bound.value / exact,
              bound.one_dof, 1.0 - bound.one_dof / exact, bound.iterations);
  // Source: the dense solver's eigenvalues carry a backward error of
  // n eps |(K, M)| (LAPACK Users' Guide 4.7), here n eps lambda_max.
  const double dense_error = static_cast<double>(k.rows()) * 2.2e-16 * exact;
  EXPECT_LE(bound.value, exact + dense_error) << part;
  EXPECT_GT(bound.value, bound.one_dof) << part;
  EXPECT_EQ(bound.iterations, 100) << part;
}

TEST(LargestEigenvalueBound, DefaultBladedDisk) {
  const BladedDisk bd = assemble_bladed_disk(default_case());
  check_bound("bladed disk", bd.stiffness, bd.mass);
}

TEST(LargestEigenvalueBound, DefaultCasing) {
  const Casing casing = assemble_casing(default_case());
  check_bound("casing, 40 elements", casing.stiffness, casing.mass);
}

TEST(LargestEigenvalueBound, RefinedCasing) {
  Case c = default_case();
  c.casing.n_elements = 200;
  const Casing casing = assemble_casing(c);
  check_bound("casing, 200 elements", casing.stiffness, casing.mass);
}

TEST(LargestEigenvalueBound, OneDofWhenTheMassCannotBeFactorized) {
  // M indefinite: the power method needs M^-1; the bound falls back to the
  // unit vectors' quotients (here K_00 / M_00 = 2), lowered by 1 ulp.
  Eigen::SparseMatrix<double> k(2, 2), m(2, 2);
  k.insert(0, 0) = 2.0;
  k.insert(1, 1) = 1.0;
  m.insert(0, 0) = 1.0;
  m.insert(0, 1) = 2.0;
  m.insert(1, 0) = 2.0;
  m.insert(1, 1) = 1.0;
  const LargestEigenvalueBound bound = largest_eigenvalue_lower_bound(k, m);
  std::printf("bound %.17g, one dof %.17g, %d power steps\n", bound.value, bound.one_dof,
              bound.iterations);
  EXPECT_EQ(bound.iterations, 0);
  EXPECT_EQ(bound.one_dof, 2.0);
  EXPECT_LT(bound.value, 2.0);
}

} // namespace
} // namespace rsi

// The modal solvers' answers checked, and the cases they used to get wrong
// or refuse (reference/solver/modal_check, modal_analysis):
//  - a positive semi-definite mass (massless dofs), dense and sparse paths,
//    against the static condensation of the massless dofs solved densely;
//  - a free part (K singular): its rigid-body mode at zero frequency within
//    the stated uncertainty, its elastic modes against the closed form;
//  - a model in N, mm, t, s (eigenvalues 1e10 to 1e14) on Spectra's
//    Lanczos, which restarted at random below its absolute thresholds;
//  - the check catching a perturbed eigenvector, a skipped mode and a mode
//    returned twice, and the Sturm count against closed-form counts;
//  - CalculiX's tied C3D10/C3D20 test deck against ccx's own frequencies.
//
// The model: the Q1 finite-element Laplacian on the unit cube (a 3D
// Kronecker sum of 1D linear elements), whose eigenvalues are sums
// kappa_a + kappa_b + kappa_c of the 1D pencil's,
//   kappa_j = (6 / h^2) (1 - cos t_j) / (2 + cos t_j)
// with t_j = j pi h, j = 1..N (N interior nodes, clamped ends, h = 1/(N+1))
// or t_j = j pi / (N - 1), j = 0..N-1 (N nodes, free ends, h = 1/(N-1); the
// end rows of the ends' half elements hold for u_i = cos(i t) exactly).

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <lapacke.h>
#include <nlohmann/json.hpp>
#include <unsupported/Eigen/KroneckerProduct>

#include "bladed_disk.hpp"
#include "case_file.hpp"
#include "calculix_deck.hpp"
#include "calculix_run.hpp"
#include "component_case.hpp"
#include "modal_analysis.hpp"
#include "modal_check.hpp"
#include "symmetric_inertia.hpp"

namespace rsi {
namespace {

using SpMat = Eigen::SparseMatrix<double>;
constexpr double eps = std::numeric_limits<double>::epsilon();

struct Cube {
  SpMat k;
  SpMat m;
  std::vector<double> kappa; ///< the 1D pencil's eigenvalues
};

/// The Q1 Laplacian of the unit cube (file comment), K and M scaled by
/// k_scale and m_scale (the eigenvalues by k_scale / m_scale).
Cube laplacian_cube(int nodes, bool free, double k_scale = 1.0, double m_scale = 1.0) {
  const double h = free ? 1.0 / (nodes - 1) : 1.0 / (nodes + 1);
  SpMat k1(nodes, nodes), m1(nodes, nodes);
  std::vector<Eigen::Triplet<double>> tk, tm;
  for (int i = 0; i < nodes; ++i) {
    const bool end = free && (i == 0 || i == nodes - 1);
    tk.emplace_back(i, i, (end ? 1.0 : 2.0) / h);
    tm.emplace_back(i, i, (end ? 2.0 : 4.0) * h / 6.0);
    if (i + 1 < nodes) {
      tk.emplace_back(i, i + 1, -1.0 / h);
      tk.emplace_back(i + 1, i, -1.0 / h);
      tm.emplace_back(i, i + 1, h / 6.0);
      tm.emplace_back(i + 1, i, h / 6.0);
    }
  }
  k1.setFromTriplets(tk.begin(), tk.end());
  m1.setFromTriplets(tm.begin(), tm.end());
  Cube c;
  const SpMat mm = Eigen::kroneckerProduct(m1, m1);
  c.m = m_scale * SpMat(Eigen::kroneckerProduct(m1, mm));
  const SpMat km = Eigen::kroneckerProduct(k1, m1);
  const SpMat mk = Eigen::kroneckerProduct(m1, k1);
  c.k = k_scale * (SpMat(Eigen::kroneckerProduct(km, m1)) + SpMat(Eigen::kroneckerProduct(mk, m1)) +
                   SpMat(Eigen::kroneckerProduct(mm, k1)));
  c.k.makeCompressed();
  c.m.makeCompressed();
  for (int j = free ? 0 : 1; j <= (free ? nodes - 1 : nodes); ++j) {
    const double t = free ? j * M_PI / (nodes - 1) : j * M_PI * h;
    c.kappa.push_back(k_scale / m_scale * 6.0 / (h * h) * (1.0 - std::cos(t)) / (2.0 + std::cos(t)));
  }
  return c;
}

/// Every sum kappa_a + kappa_b + kappa_c, ascending.
std::vector<double> cube_eigenvalues(const std::vector<double>& kappa) {
  std::vector<double> sums;
  for (double a : kappa)
    for (double b : kappa)
      for (double c : kappa)
        sums.push_back(a + b + c);
  std::sort(sums.begin(), sums.end());
  return sums;
}

Eigen::MatrixXd take(const Eigen::MatrixXd& a, const std::vector<int>& rows,
                     const std::vector<int>& cols) {
  Eigen::MatrixXd b(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j)
      b(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = a(rows[i], cols[j]);
  return b;
}

/// A model with massless dofs: every 5th dof's row and column of M zeroed
/// (a principal submatrix of a positive definite M, bordered by zeros:
/// positive semi-definite), and its exact finite eigenvalues: those of the
/// statically condensed pencil (K_ff - K_fz K_zz^-1 K_zf, M_ff) (massless
/// rows of K phi = lambda M phi are K_zf phi_f + K_zz phi_z = 0), solved by
/// LAPACKE dsygvd on the condensed pair, backward stable: each to within
/// n_f eps lambda_max of the condensed pencil.
struct Massless {
  SpMat k;
  SpMat m;
  Eigen::VectorXd exact;  ///< ascending
  double exact_error = 0; ///< n_f eps lambda_max
  int n_massless = 0;
};

Massless massless_model(const Cube& c) {
  const int n = static_cast<int>(c.k.rows());
  std::vector<int> massless, massive;
  for (int i = 0; i < n; ++i)
    (i % 5 == 2 ? massless : massive).push_back(i);
  Eigen::MatrixXd m = Eigen::MatrixXd(c.m);
  for (int i : massless) {
    m.row(i).setZero();
    m.col(i).setZero();
  }
  Massless out;
  out.k = c.k;
  out.m = m.sparseView();
  out.m.makeCompressed();
  out.n_massless = static_cast<int>(massless.size());
  const Eigen::MatrixXd kd = Eigen::MatrixXd(c.k);
  const Eigen::MatrixXd k_fz = take(kd, massive, massless);
  Eigen::MatrixXd a =
      take(kd, massive, massive) - k_fz * take(kd, massless, massless).llt().solve(k_fz.transpose());
  a = 0.5 * (a + a.transpose()).eval();
  Eigen::MatrixXd b = take(m, massive, massive);
  const int nf = static_cast<int>(massive.size());
  Eigen::VectorXd w(nf);
  const lapack_int info =
      LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'N', 'L', nf, a.data(), nf, b.data(), nf, w.data());
  EXPECT_EQ(info, 0);
  out.exact = w;
  out.exact_error = nf * eps * w(nf - 1);
  return out;
}

/// Each |lambda_i - exact_i| against the uncertainty lowest_modes states
/// plus the reference's own error; prints the worst ratio.
void expect_within_uncertainty(const std::string& name, const Modes& modes,
                               const Eigen::VectorXd& exact, double exact_error) {
  double worst = 0.0;
  double worst_relative = 0.0;
  for (int i = 0; i < modes.n_modes(); ++i) {
    const double error = std::abs(modes.omega_squared(i) - exact(i));
    const double bound = modes.accuracy.uncertainty(i) + exact_error;
    worst = std::max(worst, error / bound);
    worst_relative = std::max(worst_relative, error / std::abs(exact(i)));
    EXPECT_LE(error, bound) << name << " mode " << i + 1;
  }
  std::printf("%s: %d modes by %s; max |d lambda| / (stated uncertainty + reference error) = "
              "%.3f, max relative error %.3e; residual <= %.2e, max|Phi^T M Phi - I| %.2e, Sturm "
              "%d below %.6e\n",
              name.c_str(), modes.n_modes(), modes.accuracy.solver.c_str(), worst, worst_relative,
              modes.accuracy.residual.maxCoeff(), modes.accuracy.orthonormality,
              modes.accuracy.sturm_count, modes.accuracy.sturm_shift);
  if (!modes.accuracy.replaced.empty())
    std::printf("  (in place of %s)\n", modes.accuracy.replaced.c_str());
}

TEST(ModalChecks, MasslessDofsOnTheDensePath) {
  // 729 dofs (the dense path), 146 massless: dsygvd on (K, M) refused M.
  const Massless model = massless_model(laplacian_cube(9, false));
  const int count = 20;
  const Modes automatic = lowest_modes(model.k, model.m, count);
  const Modes dense = lowest_modes(model.k, model.m, count, ModalSolver::dense);
  ASSERT_TRUE(automatic.accuracy.passed) << automatic.accuracy.failure;
  ASSERT_TRUE(dense.accuracy.passed) << dense.accuracy.failure;
  // Exact: the condensed pencil (massless_model).
  expect_within_uncertainty("massless, dense path (automatic)", automatic, model.exact.head(count),
                            model.exact_error);
  expect_within_uncertainty("massless, dense path (dense)", dense, model.exact.head(count),
                            model.exact_error);
  EXPECT_EQ(automatic.accuracy.n_zero, 0);
  EXPECT_TRUE(std::isinf(automatic.omega_max)); // M singular: infinite eigenvalues
  // The finite eigenvalues number the massive dofs: asking all n is refused
  // (exit 2 in the CLI), not answered with a massless direction.
  const int n = static_cast<int>(model.k.rows());
  EXPECT_THROW(lowest_modes(model.k, model.m, n, ModalSolver::dense), ModalResolutionError);
  const Modes all_finite = lowest_modes(model.k, model.m, n - model.n_massless, ModalSolver::dense);
  EXPECT_TRUE(all_finite.accuracy.passed) << all_finite.accuracy.failure;
}

TEST(ModalChecks, SharedNullDirectionWhoseCholeskySucceeds) {
  // K = diag(1e-16, 1, 2, 3) / 3, M = diag(-1e-17, 1, 1, 1) / 3 (entries of
  // 16-17 digits, as assembled: stored_digits): the first direction
  // carries neither stiffness nor mass beyond rounding (a C3D20R zero-energy
  // mode as ccx writes it: CalculiX's inistrain test deck), yet K - sigma M
  // factors, and its mu = -1e-17 / 1e-16 looked like an indefinite M (exit 3
  // "the mass matrix is not positive definite, nor semi-definite"). Exact: the
  // pencil on the other directions, lambda = 1, 2, 3 (to the rounding of the
  // quotients of the stored thirds: a few eps).
  Eigen::SparseMatrix<double> k(4, 4);
  Eigen::SparseMatrix<double> m(4, 4);
  const double stiffness[] = {1e-16 / 3.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
  const double mass[] = {-1e-17 / 3.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  for (int i = 0; i < 4; ++i) {
    k.insert(i, i) = stiffness[i];
    m.insert(i, i) = mass[i];
  }
  const Modes modes = lowest_modes(k, m, 3);
  ASSERT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
  for (int i = 0; i < 3; ++i) {
    // Exact eigenvalue i + 1; the dense solvers' bound n eps lambda_max (4 eps 3), doubled.
    std::printf("shared null direction: lambda_%d = %.17g (exact %d)\n", i + 1,
                modes.omega_squared(i), i + 1);
    EXPECT_NEAR(modes.omega_squared(i), i + 1.0, 2.0 * 4.0 * 3.0 * 2.22e-16);
  }
  EXPECT_EQ(modes.accuracy.null_directions.cols(), 1);
}

TEST(ModalChecks, AllModesAboveTheDenseLimit) {
  // 2,197 dofs, above dense_limit: all of them asked threw "the sparse
  // solver needs count < 2197" (exit 1 in the CLI, whose --count allows n),
  // and a count near n ran minutes of Lanczos; more than n/4 modes now go
  // to the dense solver up to dense_many_modes_limit.
  const Cube cube = laplacian_cube(13, false);
  const int n = static_cast<int>(cube.k.rows());
  ASSERT_GT(n, dense_limit);
  const Modes modes = lowest_modes(cube.k, cube.m, n);
  ASSERT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
  const std::vector<double> exact = cube_eigenvalues(cube.kappa);
  // The dense solver is backward stable: each eigenvalue within n eps lambda_max
  // (LAPACK Users' Guide, 3rd ed., 4.10), doubled for the closed form's own rounding.
  const double bound = 2.0 * n * std::numeric_limits<double>::epsilon() * exact.back();
  double worst = 0.0;
  for (int i = 0; i < n; ++i)
    worst = std::max(worst, std::abs(modes.omega_squared(i) - exact[static_cast<size_t>(i)]));
  std::printf("all %d modes: max |lambda - exact| = %.3g, bound %.3g\n", n, worst, bound);
  EXPECT_LE(worst, bound);
  // Above dense_many_modes_limit all n modes are refused before any solve.
  const Cube big = laplacian_cube(21, false);
  const int n_big = static_cast<int>(big.k.rows());
  ASSERT_GT(n_big, dense_many_modes_limit);
  EXPECT_THROW(lowest_modes(big.k, big.m, n_big), ModalResolutionError);
}

TEST(ModalChecks, MasslessDofsOnTheSparsePathInMillimetres) {
  // 2,744 dofs (the sparse path: Spectra's Lanczos on SparseLU), 549
  // massless, in the units of a CalculiX model (N, mm, t, s: steel's E =
  // 2.1e5 N/mm^2, rho = 7.8e-9 t/mm^3), eigenvalues 1e15 times the unit
  // cube's: Spectra's Lanczos, unscaled, took residual norms of 1e-14 for
  // breakdowns and returned modes with residuals of order one.
  const Massless model = massless_model(laplacian_cube(14, false, 2.1e5, 7.8e-9));
  const int count = 12;
  const Modes modes = lowest_modes(model.k, model.m, count, ModalSolver::sparse);
  ASSERT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
  EXPECT_TRUE(modes.accuracy.replaced.empty()) << modes.accuracy.replaced; // no fallback
  expect_within_uncertainty("massless, sparse path, N mm t s", modes, model.exact.head(count),
                            model.exact_error);
  // The stated uncertainty is a bound, not a guess: at least 1e-13 relative
  // (the input's rounding, 2^-53, times the energy's condition number).
  EXPECT_GT(modes.accuracy.uncertainty(0), 1e-13 * modes.omega_squared(0));
}

TEST(ModalChecks, FreeCubeHasOneRigidBodyMode) {
  // Free (Neumann) Q1 cube: the constant is a rigid-body motion, K singular.
  // Dense path (729 dofs), the automatic choice (which takes the sparse
  // path, the dense solver not resolving lambda_1 = 0) and the sparse path.
  const Cube c = laplacian_cube(9, true);
  const std::vector<double> exact_all = cube_eigenvalues(c.kappa);
  const int count = 15; // 1 zero, then clusters of 3 (15 = 1 + 3 + 3 + 6 + 2 cut a cluster)
  const Eigen::VectorXd exact = Eigen::Map<const Eigen::VectorXd>(exact_all.data(), count);
  const double exact_error = 10.0 * eps * exact.maxCoeff(); // the closed form in double
  for (ModalSolver solver : {ModalSolver::automatic, ModalSolver::dense, ModalSolver::sparse}) {
    const Modes modes = lowest_modes(c.k, c.m, count, solver);
    ASSERT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
    EXPECT_EQ(modes.accuracy.n_zero, 1);
    EXPECT_TRUE(modes.is_zero(0));
    EXPECT_EQ(modes.claimed_frequency_hz(0), 0.0);
    // The zero mode's stated tolerance: sqrt(|lambda| + u) / 2 pi, below the
    // first elastic frequency by far (kappa_1 = 3 pi^2 / (1 + ...) here).
    std::printf("  zero mode: lambda %.3e, uncertainty %.3e, frequency 0 +- %.3e Hz (first "
                "elastic %.4f Hz)\n",
                modes.omega_squared(0), modes.accuracy.uncertainty(0), modes.uncertainty_hz(0),
                modes.frequency_hz(1));
    EXPECT_LT(modes.uncertainty_hz(0), 1e-3 * modes.frequency_hz(1));
    // Elastic ones: closed form (file comment); the zero mode's lambda within its uncertainty.
    expect_within_uncertainty(solver == ModalSolver::dense    ? "free cube, dense"
                              : solver == ModalSolver::sparse ? "free cube, sparse"
                                                              : "free cube, automatic",
                              modes, exact, exact_error);
  }
}

TEST(ModalChecks, FreeHubBladedDiskHasTheRigidRotation) {
  // The paper's bladed disk with a free hub (HubSupport::free): one rigid
  // rotation, K singular; the sparse path refused it with a ModalError. Its
  // elastic modes against the dense solver on (K, M) (M positive definite,
  // each eigenvalue to within n eps lambda_max, LAPACK Users' Guide §4.10).
  const BladedDisk bd = assemble_bladed_disk(
      load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json"), HubSupport::free);
  const int count = 25;
  const Modes sparse = lowest_modes(bd.stiffness, bd.mass, count, ModalSolver::sparse);
  const Modes reference = lowest_modes(bd.stiffness, bd.mass, count, ModalSolver::dense);
  ASSERT_TRUE(sparse.accuracy.passed) << sparse.accuracy.failure;
  EXPECT_EQ(sparse.accuracy.n_zero, 1);
  EXPECT_TRUE(sparse.is_zero(0));
  const double dense_error = dense_resolution(reference);
  Eigen::VectorXd exact = reference.omega_squared;
  exact(0) = 0.0; // the rigid rotation, exactly
  expect_within_uncertainty("free-hub bladed disk, sparse", sparse, exact, dense_error);
}

TEST(ModalChecks, FreeCubeOnTheBlockMethod) {
  // 10,648 dofs: the block Krylov-Schur method about a shift below the
  // spectrum (it took only shift 0, and lowest_modes refused the free cube).
  const Cube c = laplacian_cube(22, true);
  const std::vector<double> exact_all = cube_eigenvalues(c.kappa);
  const int count = 10;
  const Eigen::VectorXd exact = Eigen::Map<const Eigen::VectorXd>(exact_all.data(), count);
  const Modes modes = lowest_modes(c.k, c.m, count, ModalSolver::sparse);
  ASSERT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
  EXPECT_EQ(modes.accuracy.n_zero, 1);
  EXPECT_LT(modes.accuracy.shift, 0.0);
  expect_within_uncertainty("free cube, block method", modes, exact, 10.0 * eps * exact.maxCoeff());
}

/// The 11 lowest modes of the clamped cube (8^3 = 512 dofs; kappa sums: 1,
/// 3, 3, 3, 6 ... equal ones), as lowest_modes gives them (checked).
const Modes& clamped_modes() {
  static const Modes modes = [] {
    const Cube c = laplacian_cube(8, false);
    return lowest_modes(c.k, c.m, 11, ModalSolver::dense);
  }();
  return modes;
}

Modes subset(const Modes& modes, const std::vector<int>& kept) {
  Modes out;
  out.omega_squared.resize(static_cast<Eigen::Index>(kept.size()));
  out.shapes.resize(modes.shapes.rows(), static_cast<Eigen::Index>(kept.size()));
  for (size_t i = 0; i < kept.size(); ++i) {
    out.omega_squared(static_cast<Eigen::Index>(i)) = modes.omega_squared(kept[i]);
    out.shapes.col(static_cast<Eigen::Index>(i)) = modes.shapes.col(kept[i]);
  }
  out.omega_max = modes.omega_max;
  return out;
}

TEST(ModalChecks, CheckCatchesAPerturbedVector) {
  const Cube c = laplacian_cube(8, false);
  Modes modes = clamped_modes();
  ASSERT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
  const double clean = modes.accuracy.residual(4);
  // Mode 5 plus 1e-6 of mode 11 (M-orthogonal to it, a higher eigenvalue),
  // M-normalised again: its residual is about 1e-6 (lambda_11 - lambda_5) /
  // (2 lambda_5), far above the bound tau_r = 1e-8.
  Eigen::VectorXd phi = modes.shapes.col(4) + 1e-6 * modes.shapes.col(10);
  phi /= std::sqrt(phi.dot(c.m * phi));
  modes.shapes.col(4) = phi;
  EXPECT_FALSE(check_modes(c.k, c.m, 0.0, modes));
  std::printf("perturbed mode 5: residual %.3e (bound %.3e; %.3e unperturbed): %s\n",
              modes.accuracy.residual(4), modes.accuracy.residual_bound(4), clean,
              modes.accuracy.failure.c_str());
  EXPECT_NE(modes.accuracy.failure.find("relative residual"), std::string::npos);
  EXPECT_NE(modes.accuracy.failure.find("of mode 5"), std::string::npos);
  EXPECT_THROW(require_passed(modes, "test"), ModalCheckError);
  // A wrong eigenvalue with the right vector: 1e-6 relative off.
  Modes shifted = clamped_modes();
  shifted.omega_squared(2) *= 1.0 + 1e-6;
  EXPECT_FALSE(check_modes(c.k, c.m, 0.0, shifted));
  std::printf("eigenvalue 3 off by 1e-6: %s\n", shifted.accuracy.failure.c_str());
}

TEST(ModalChecks, SturmCountCatchesASkippedMode) {
  const Cube c = laplacian_cube(8, false);
  const Modes& all = clamped_modes();
  ASSERT_TRUE(all.accuracy.passed);
  // Mode 1 is simple (kappa_1 three times), 2-4 equal, 5-7 equal: skipping
  // mode 1 leaves true eigenpairs, M-orthonormal, residuals as small as ever.
  Modes skipped = subset(all, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  EXPECT_FALSE(check_modes(c.k, c.m, 0.0, skipped));
  std::printf("mode 1 skipped: residual max %.2e, orthonormality %.2e, Sturm %d below %.6e, "
              "%d below %.6e (%d returned there): %s\n",
              skipped.accuracy.residual.maxCoeff(), skipped.accuracy.orthonormality,
              skipped.accuracy.sturm_count, skipped.accuracy.sturm_shift,
              skipped.accuracy.sturm_count_below, skipped.accuracy.sturm_shift_below,
              skipped.accuracy.returned_below, skipped.accuracy.failure.c_str());
  EXPECT_NE(skipped.accuracy.failure.find("a mode was missed"), std::string::npos);
  EXPECT_LE(skipped.accuracy.residual.maxCoeff(), 1e-8); // the other checks pass
  // A mode returned twice (a Lanczos ghost): the Gram matrix has a 1 off the diagonal.
  Modes twice = subset(all, {0, 1, 1, 2, 3});
  EXPECT_FALSE(check_modes(c.k, c.m, 0.0, twice));
  std::printf("mode 2 twice: %s\n", twice.accuracy.failure.c_str());
  EXPECT_NE(twice.accuracy.failure.find("M-orthonormality"), std::string::npos);
  // Cutting a cluster of equal eigenvalues is no miss: modes 1-3 of the
  // cluster 2-4 (the count above exceeds them, the count below matches).
  Modes cut = subset(all, {0, 1, 2});
  EXPECT_TRUE(check_modes(c.k, c.m, 0.0, cut)) << cut.accuracy.failure;
  EXPECT_EQ(cut.accuracy.sturm_count, 4);
  EXPECT_EQ(cut.accuracy.sturm_count_below, 1);
}

TEST(ModalChecks, InertiaCountsTheClosedFormEigenvalues) {
  // Sylvester: negative pivots of K - tau M = eigenvalues below tau (the
  // closed form), by UMFPACK's LU, CHOLMOD's L D L^T and LAPACK's Bunch-Kaufman.
  const Cube c = laplacian_cube(10, false);
  const std::vector<double> exact = cube_eigenvalues(c.kappa);
  const Eigen::MatrixXd kd = Eigen::MatrixXd(c.k);
  const Eigen::MatrixXd md = Eigen::MatrixXd(c.m);
  for (double fraction : {0.01, 0.1, 0.37, 0.9}) {
    // tau halfway between two consecutive distinct eigenvalues.
    const size_t index = static_cast<size_t>(fraction * static_cast<double>(exact.size()));
    size_t next = index + 1;
    while (next < exact.size() && exact[next] - exact[index] < 1e-9 * exact[index])
      ++next;
    const double tau = 0.5 * (exact[index] + exact[next]);
    const int expected = static_cast<int>(next);
    SpMat lower = SpMat(c.k.triangularView<Eigen::Lower>()) -
                  tau * SpMat(c.m.triangularView<Eigen::Lower>());
    lower.makeCompressed();
    const Inertia sparse = sparse_inertia(lower);
    const Inertia simplicial = simplicial_inertia(lower);
    const Inertia dense = dense_inertia(kd - tau * md);
    std::printf("tau %.6e: %d eigenvalues below (closed form), %s %d negative, %s %d, %s %d\n",
                tau, expected, sparse.method.c_str(), sparse.negative, simplicial.method.c_str(),
                simplicial.negative, dense.method.c_str(), dense.negative);
    ASSERT_TRUE(sparse.factorized) << sparse.why;
    ASSERT_TRUE(simplicial.factorized) << simplicial.why;
    ASSERT_TRUE(dense.factorized) << dense.why;
    EXPECT_EQ(sparse.method, "UMFPACK LU, diagonal pivots");
    EXPECT_EQ(sparse.negative, expected);
    EXPECT_EQ(simplicial.negative, expected);
    EXPECT_EQ(dense.negative, expected);
    EXPECT_EQ(sparse.negative + sparse.positive, static_cast<int>(exact.size()));
  }
}

TEST(ModalChecks, InertiaOfTinyAndZeroPivots) {
  // Blocks [d 1; 1 d] (eigenvalues d - 1 < 0 < d + 1) between diagonal
  // entries 1..n_spd: with d = 1e-6 UMFPACK keeps to the diagonal (its
  // threshold is 0, as an L D L^T without pivoting: pivots d > 0 and
  // d - 1/d < 0 a block) and counts one negative eigenvalue a block. With
  // d = 0 it must pivot off the diagonal, its U says nothing of the
  // inertia, and CHOLMOD's L D L^T meets a zero pivot first: no count, and
  // the failure says which factorization made it (the caller moves tau).
  const int n_blocks = 40, n_spd = 30;
  const int n = 2 * n_blocks + n_spd;
  auto blocks = [&](double d) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int b = 0; b < n_blocks; ++b) {
      entries.emplace_back(2 * b, 2 * b, d);
      entries.emplace_back(2 * b + 1, 2 * b, 1.0);
      entries.emplace_back(2 * b + 1, 2 * b + 1, d);
    }
    for (int k = 0; k < n_spd; ++k)
      entries.emplace_back(2 * n_blocks + k, 2 * n_blocks + k, 1.0 + k);
    SpMat lower(n, n);
    lower.setFromTriplets(entries.begin(), entries.end());
    lower.makeCompressed();
    return lower;
  };
  const SpMat tiny = blocks(1e-6);
  const Inertia sparse = sparse_inertia(tiny);
  const Inertia dense = dense_inertia(Eigen::MatrixXd(SpMat(tiny.selfadjointView<Eigen::Lower>())));
  std::printf("d = 1e-6: %s %d negative, %s %d\n", sparse.method.c_str(), sparse.negative,
              dense.method.c_str(), dense.negative);
  ASSERT_TRUE(sparse.factorized) << sparse.why;
  EXPECT_EQ(sparse.method, "UMFPACK LU, diagonal pivots");
  EXPECT_EQ(sparse.negative, n_blocks);
  EXPECT_EQ(sparse.positive, n_blocks + n_spd);
  EXPECT_EQ(dense.negative, n_blocks);
  const Inertia zero = sparse_inertia(blocks(0.0));
  std::printf("d = 0: %s: %s\n", zero.method.c_str(), zero.why.c_str());
  EXPECT_FALSE(zero.factorized);
  EXPECT_EQ(zero.method, "CHOLMOD simplicial L D L^T");
  EXPECT_NE(zero.why.find("pivot"), std::string::npos);
}

TEST(ModalChecks, TiedC3d10AndC3d20DeckMatchesCalculix) {
  // CalculiX's test deck cubef2f3 (Debian calculix-ccx-test): a C3D10 and a
  // C3D20 part joined by *TIE, 8,505 dofs, in N, mm, t, s. Its 10 lowest
  // frequencies came out up to 17 % off (modes 4 to 10), with residuals of
  // order one. ccx's own eigensolver prints 7 significant digits.
  const std::string deck_gz = "/usr/share/doc/calculix-ccx-test/examples/test/cubef2f3.inp.gz";
  if (!std::filesystem::exists(deck_gz)) GTEST_SKIP() << deck_gz << " absent (calculix-ccx-test)";
  try {
    find_ccx();
  } catch (const ImportError& e) {
    GTEST_SKIP() << e.what();
  }
  const std::string dir = std::string(RSI_BINARY_DIR) + "/modal-checks";
  std::filesystem::create_directories(dir);
  const std::string deck_path = dir + "/cubef2f3.inp";
  ASSERT_EQ(std::system(("gzip -dc " + deck_gz + " > " + deck_path).c_str()), 0);
  const std::string case_path = dir + "/cubef2f3.json";
  {
    std::FILE* f = std::fopen(case_path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("{\"component\": {\"name\": \"cubef2f3\", \"source\": {\"calculix_deck\": "
               "\"cubef2f3.inp\"}, \"boundary\": {\"nodes\": [748]}, \"units\": \"N, mm, t, s\", "
               "\"rotation_axis\": [0, 0, 1]}}\n",
               f);
    std::fclose(f);
  }
  const ComponentCase cc = parse_component_case(read_case_document(case_path), case_path);
  ComponentLoadOptions load;
  load.ccx_cache = dir + "/ccx-cache";
  const Component part = load_component(cc, load);
  const int count = 10;
  const Modes modes = lowest_modes(part.stiffness, part.mass, count);
  ASSERT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
  const std::vector<double> ccx =
      calculix_eigenvalues(read_calculix_deck(cc.source_path), count, load.ccx_cache);
  ASSERT_EQ(static_cast<int>(ccx.size()), count);
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    // ccx's .dat: 7 significant digits, so 5e-7 relative, plus the stated uncertainty.
    const double error = std::abs(modes.omega_squared(i) - ccx[i]) / ccx[i];
    const double bound = 5e-7 + modes.accuracy.uncertainty(i) / modes.omega_squared(i);
    std::printf("  mode %2d: rsi %.10e, ccx %.7e rad^2/s^2, relative difference %.2e (bound %.2e), "
                "%d digits claimed\n",
                i + 1, modes.omega_squared(i), ccx[i], error, bound, modes.digits(i));
    worst = std::max(worst, error);
    EXPECT_LE(error, bound) << "mode " << i + 1;
  }
  std::printf("cubef2f3: %d dofs, %s: max relative difference to ccx %.2e\n", part.n_dofs(),
              modes.accuracy.solver.c_str(), worst);
}

} // namespace
} // namespace rsi

// V2/V3 for the large-model modal solvers: the block Krylov-Schur method
// (reference/solver/block_shift_invert) and Spectra's Lanczos on the CHOLMOD
// shift-invert operator (reference/solver/cholmod_shift_invert), against
// the dense LAPACKE solve (the paper's bladed disk, 838 dofs) and against
// the closed-form eigenvalues of a 3D finite-element Laplacian (Q1 on a
// cube, 10,648 dofs, above the size where lowest_modes takes the block
// method).
//
// Error bounds used below (symmetric definite pencil K - lambda M):
//  - residual bound: for M-orthonormal Phi (p columns) and the residual
//    R = K Phi - M Phi Lambda, p eigenvalues lie within
//    ||R||_{M^-1} <= ||R||_F / sqrt(mu_min(M)) of the p Ritz values (Kahan;
//    Parlett, The Symmetric Eigenvalue Problem, th. 11.5.2, with the
//    M^-1 norm for the pencil), so sorted lists match within that;
//  - dsygvd is backward stable: |d lambda| <= n eps lambda_max (Weyl).

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <unsupported/Eigen/KroneckerProduct>

#include "bladed_disk.hpp"
#include "block_shift_invert.hpp"
#include "cholmod_shift_invert.hpp"
#include "modal_analysis.hpp"

namespace rsi {
namespace {

using SpMat = Eigen::SparseMatrix<double>;
constexpr double eps = std::numeric_limits<double>::epsilon();

/// The residual bound ||K Phi - M Phi Lambda||_F / sqrt(mu_min(M)).
double residual_bound(const SpMat& k, const SpMat& m, const Eigen::VectorXd& lambda,
                      const Eigen::MatrixXd& phi, double mu_min) {
  const Eigen::MatrixXd r = k * phi - m * phi * lambda.asDiagonal();
  return r.norm() / std::sqrt(mu_min);
}

/// max_i |K phi_i - lambda_i M phi_i| / |K phi_i|.
double largest_relative_residual(const SpMat& k, const SpMat& m, const Eigen::VectorXd& lambda,
                                 const Eigen::MatrixXd& phi) {
  const Eigen::MatrixXd k_phi = k * phi;
  const Eigen::MatrixXd m_phi = m * phi;
  double largest = 0.0;
  for (Eigen::Index i = 0; i < phi.cols(); ++i)
    largest =
        std::max(largest, (k_phi.col(i) - lambda(i) * m_phi.col(i)).norm() / k_phi.col(i).norm());
  return largest;
}

double gram_error(const SpMat& m, const Eigen::MatrixXd& phi) {
  const Eigen::MatrixXd gram = phi.transpose() * (m * phi);
  return (gram - Eigen::MatrixXd::Identity(phi.cols(), phi.cols())).cwiseAbs().maxCoeff();
}

/// Spectra's shift-invert Lanczos on the CHOLMOD factor (tolerance 1e-12), sorted ascending.
Modes spectra_on_cholmod(const SpMat& k, const SpMat& m, int count, int ncv) {
  CholmodShiftInvert op(k, m);
  op.set_shift(0.0);
  EXPECT_TRUE(op.factorized()) << op.message();
  Spectra::SparseSymMatProd<double> bop(m);
  Spectra::SymGEigsShiftSolver<CholmodShiftInvert, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      solver(op, bop, count, ncv, 0.0);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
  EXPECT_EQ(solver.info(), Spectra::CompInfo::Successful);
  const Eigen::VectorXd values = solver.eigenvalues();
  const Eigen::MatrixXd vectors = solver.eigenvectors();
  std::vector<int> order(count);
  for (int i = 0; i < count; ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values(a) < values(b); });
  Modes modes;
  modes.omega_squared.resize(count);
  modes.shapes.resize(k.rows(), count);
  for (int i = 0; i < count; ++i) {
    modes.omega_squared(i) = values(order[i]);
    modes.shapes.col(i) = vectors.col(order[i]);
  }
  return modes;
}

struct BladedDiskFixture : ::testing::Test {
  static void SetUpTestSuite() {
    bd = new BladedDisk(assemble_bladed_disk(
        load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json")));
    dense = new Modes(lowest_modes(bd->stiffness, bd->mass, 60, ModalSolver::dense));
    mu_min = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(bd->mass),
                                                            Eigen::EigenvaluesOnly)
                 .eigenvalues()(0);
  }
  static void TearDownTestSuite() {
    delete dense;
    delete bd;
  }
  static BladedDisk* bd;
  static Modes* dense;
  static double mu_min;
};
BladedDisk* BladedDiskFixture::bd = nullptr;
Modes* BladedDiskFixture::dense = nullptr;
double BladedDiskFixture::mu_min = 0.0;

TEST_F(BladedDiskFixture, CholmodSolveMatchesDenseCholesky) {
  // Habit 9: CHOLMOD against a dense LLT of the same K, on 5 right-hand sides.
  const SpMat& k = bd->stiffness;
  CholmodShiftInvert op(k, bd->mass);
  op.set_shift(0.0);
  ASSERT_TRUE(op.factorized()) << op.message();
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(k.rows(), 5);
  Eigen::MatrixXd x(k.rows(), 5);
  ASSERT_TRUE(op.solve(b, x));
  const Eigen::LLT<Eigen::MatrixXd> dense_llt{Eigen::MatrixXd(k)};
  const Eigen::MatrixXd y = dense_llt.solve(b);
  const Eigen::VectorXd ev =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(k), Eigen::EigenvaluesOnly)
          .eigenvalues();
  const double cond = ev(ev.size() - 1) / ev(0);
  const double difference = (x - y).norm() / y.norm();
  std::printf("CHOLMOD vs dense LLT: |x - y| / |y| = %.3e, cond(K) = %.3e, n eps cond = %.3e\n",
              difference, cond, k.rows() * eps * cond);
  // Both backward stable: forward errors <= n eps cond(K) each (Higham, th. 10.4 and 7.2).
  EXPECT_LE(difference, 2.0 * k.rows() * eps * cond);
}

TEST_F(BladedDiskFixture, BlockMethodMatchesDenseAndSpectra) {
  const SpMat& k = bd->stiffness;
  const SpMat& m = bd->mass;
  const int n = static_cast<int>(k.rows());
  const int count = 60;
  BlockShiftInvertOptions options;
  options.block_size = 16;
  options.n_kept = count + 8;
  options.max_basis = options.n_kept + 6 * options.block_size;
  const BlockShiftInvertResult block = block_shift_invert(k, m, count, options);
  ASSERT_EQ(block.status, BlockShiftInvertResult::Status::successful) << block.message;
  const Modes spectra = spectra_on_cholmod(k, m, count, 2 * count + 1);

  const double lambda_max = dense->omega_max * dense->omega_max;
  const double dense_bound = n * eps * lambda_max;
  const double block_bound =
      residual_bound(k, m, block.eigenvalues, block.eigenvectors, mu_min) + dense_bound;
  const double spectra_bound =
      residual_bound(k, m, spectra.omega_squared, spectra.shapes, mu_min) + dense_bound;
  const double block_error = (block.eigenvalues - dense->omega_squared).cwiseAbs().maxCoeff();
  const double spectra_error = (spectra.omega_squared - dense->omega_squared).cwiseAbs().maxCoeff();
  const double block_spectra = (block.eigenvalues - spectra.omega_squared).cwiseAbs().maxCoeff();
  const double residual = largest_relative_residual(k, m, block.eigenvalues, block.eigenvectors);
  const double floor = block.residual_floors.maxCoeff();
  const double gram = gram_error(m, block.eigenvectors);
  std::printf("bladed disk, lowest %d: block %ld solves (%d blocks, %d restarts); max|d lambda| "
              "block-dense %.3e (bound %.3e), Spectra-dense %.3e (bound %.3e), block-Spectra "
              "%.3e (lambda_60 %.3e)\n",
              count, block.n_solves, block.n_block_solves, block.n_restarts, block_error,
              block_bound, spectra_error, spectra_bound, block_spectra,
              dense->omega_squared(count - 1));
  std::printf("  block: max |K phi - lambda M phi| / |K phi| = %.3e (tolerance %.1e + rounding "
              "floor up to %.3e); max |Phi^T M Phi - I| = %.3e (n eps = %.3e)\n",
              residual, options.tolerance, floor, gram, n * eps);
  const double relative = (block.eigenvalues - dense->omega_squared)
                              .cwiseQuotient(dense->omega_squared)
                              .cwiseAbs()
                              .maxCoeff();
  std::printf("  block-dense: max |d lambda| / lambda = %.3e\n", relative);
  // The residual bound (file comment) plus dsygvd's own error.
  EXPECT_LE(block_error, block_bound);
  // The goal of the block method (its header): far below 1e-8 relative.
  EXPECT_LE(relative, 1e-8);
  EXPECT_LE(spectra_error, spectra_bound);
  // The block method stops at tolerance + floor; recomputed here with
  // Eigen's products, whose rounding differs by up to another floor.
  EXPECT_LE(residual, options.tolerance + 2.0 * floor);
  // SVQB twice and Gram-Schmidt twice orthonormalize to round-off: n eps.
  EXPECT_LE(gram, n * eps);
}

/// The 3D finite-element Laplacian on the unit cube, trilinear (Q1) elements
/// on a uniform grid, u = 0 on the boundary (or free: singular K), N nodes a
/// direction inside: K = K1 x M1 x M1 + M1 x K1 x M1 + M1 x M1 x K1,
/// M = M1 x M1 x M1 (Kronecker products of the 1D matrices).
struct Laplacian3d {
  SpMat k;
  SpMat m;
  std::vector<double> kappa; ///< eigenvalues of the 1D pencil (K1, M1), Dirichlet
  double mu_min = 0.0;       ///< smallest eigenvalue of M
  double lambda_max = 0.0;
};

Laplacian3d laplacian_3d(int nodes, bool free) {
  const double h = 1.0 / (free ? nodes - 1 : nodes + 1);
  SpMat k1(nodes, nodes), m1(nodes, nodes);
  std::vector<Eigen::Triplet<double>> tk, tm;
  for (int i = 0; i < nodes; ++i) {
    const bool end = free && (i == 0 || i == nodes - 1); // half an element's worth
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
  Laplacian3d l;
  const SpMat mm = Eigen::kroneckerProduct(m1, m1);
  l.m = Eigen::kroneckerProduct(m1, mm);
  const SpMat km = Eigen::kroneckerProduct(k1, m1);
  const SpMat mk = Eigen::kroneckerProduct(m1, k1);
  l.k = SpMat(Eigen::kroneckerProduct(km, m1)) + SpMat(Eigen::kroneckerProduct(mk, m1)) +
        SpMat(Eigen::kroneckerProduct(mm, k1));
  l.k.makeCompressed();
  l.m.makeCompressed();
  // Dirichlet: sin(k pi x) modes, kappa_k = (6 / h^2) (1 - cos t) / (2 + cos t), t = k pi h;
  // M1's eigenvalues (h / 6) (4 + 2 cos t).
  double m1_min = 1.0;
  for (int j = 1; j <= nodes; ++j) {
    const double t = j * M_PI * h;
    l.kappa.push_back(6.0 / (h * h) * (1.0 - std::cos(t)) / (2.0 + std::cos(t)));
    m1_min = std::min(m1_min, h / 6.0 * (4.0 + 2.0 * std::cos(t)));
  }
  l.mu_min = m1_min * m1_min * m1_min;
  l.lambda_max = 3.0 * l.kappa.back();
  return l;
}

/// The `count` lowest sums kappa_i + kappa_j + kappa_k, ascending.
Eigen::VectorXd lowest_sums(const std::vector<double>& kappa, int count) {
  std::vector<double> sums;
  for (double a : kappa)
    for (double b : kappa)
      for (double c : kappa)
        sums.push_back(a + b + c);
  std::partial_sort(sums.begin(), sums.begin() + count, sums.end());
  return Eigen::Map<const Eigen::VectorXd>(sums.data(), count);
}

TEST(BlockShiftInvert, LaplacianCubeMatchesClosedForm) {
  const Laplacian3d l = laplacian_3d(22, false);
  const int n = static_cast<int>(l.k.rows());
  const int count = 50;
  const Eigen::VectorXd exact = lowest_sums(l.kappa, count);
  // lowest_modes takes the block method above 10,000 dofs (modal_analysis.cpp).
  const Modes modes = lowest_modes(l.k, l.m, count, ModalSolver::sparse);
  const Modes spectra = spectra_on_cholmod(l.k, l.m, count, 2 * count + 1);
  // The closed form is evaluated in double: a few eps relative.
  const double exact_error = 10.0 * eps * exact.cwiseAbs().maxCoeff();
  const double block_bound =
      residual_bound(l.k, l.m, modes.omega_squared, modes.shapes, l.mu_min) + exact_error;
  const double spectra_bound =
      residual_bound(l.k, l.m, spectra.omega_squared, spectra.shapes, l.mu_min) + exact_error;
  const double block_error = (modes.omega_squared - exact).cwiseAbs().maxCoeff();
  const double spectra_error = (spectra.omega_squared - exact).cwiseAbs().maxCoeff();
  const double relative = (modes.omega_squared - exact).cwiseQuotient(exact).cwiseAbs().maxCoeff();
  const double residual = largest_relative_residual(l.k, l.m, modes.omega_squared, modes.shapes);
  const double gram = gram_error(l.m, modes.shapes);
  const double max_error =
      std::abs(modes.omega_max * modes.omega_max - l.lambda_max) / l.lambda_max;
  std::printf("Q1 Laplacian, %d dofs, lowest %d (clusters of 3 and 6 equal): max|d lambda| block "
              "%.3e (bound %.3e, relative %.3e), Spectra %.3e (bound %.3e); max |K phi - lambda M "
              "phi| / |K phi| %.3e; max |Phi^T M Phi - I| %.3e; omega_max^2 rel. error %.3e\n",
              n, count, block_error, block_bound, relative, spectra_error, spectra_bound, residual,
              gram, max_error);
  EXPECT_LE(block_error, block_bound);     // residual bound (file comment)
  EXPECT_LE(spectra_error, spectra_bound); // the same for Spectra's pairs
  EXPECT_LE(relative, 1e-8);               // the goal of the block method (header)
  EXPECT_LE(gram, n * eps);                // SVQB and Gram-Schmidt twice
  // Lanczos on L^-1 K L^-T to 1e-12 relative (Spectra's tolerance), a factor 10 for the norms.
  EXPECT_LE(max_error, 1e-11);
}

TEST(BlockShiftInvert, SingularMassLeavesTheFiniteEigenvalues) {
  // Massless dofs (M singular, positive semi-definite, as CalculiX's C3D10
  // mass of Rotor 37): the finite eigenvalues are those of the condensed
  // pencil (K_ff - K_fz K_zz^-1 K_zf, M_ff), solved densely here.
  const Laplacian3d l = laplacian_3d(9, false);
  const int n = static_cast<int>(l.k.rows());
  std::vector<int> massless, massive;
  for (int i = 0; i < n; ++i)
    (i % 7 == 3 ? massless : massive).push_back(i);
  Eigen::MatrixXd m = Eigen::MatrixXd(l.m);
  for (int i : massless) {
    m.row(i).setZero();
    m.col(i).setZero();
  }
  const SpMat m_singular = m.sparseView();
  const Eigen::MatrixXd kd = Eigen::MatrixXd(l.k);
  auto take = [](const Eigen::MatrixXd& a, const std::vector<int>& r, const std::vector<int>& c) {
    Eigen::MatrixXd b(r.size(), c.size());
    for (size_t i = 0; i < r.size(); ++i)
      for (size_t j = 0; j < c.size(); ++j)
        b(i, j) = a(r[i], c[j]);
    return b;
  };
  const Eigen::MatrixXd k_fz = take(kd, massive, massless);
  const Eigen::MatrixXd condensed =
      take(kd, massive, massive) -
      k_fz * take(kd, massless, massless).llt().solve(k_fz.transpose());
  const Eigen::MatrixXd m_ff = take(m, massive, massive);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(condensed, m_ff);
  ASSERT_EQ(dense.info(), Eigen::Success);
  const int count = 30;
  const Eigen::VectorXd exact = dense.eigenvalues().head(count);
  const double lambda_max = dense.eigenvalues()(dense.eigenvalues().size() - 1);
  const double mu_min = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m_ff).eigenvalues()(0);

  BlockShiftInvertOptions options;
  options.block_size = 8;
  options.n_kept = count + 4;
  options.max_basis = options.n_kept + 8 * options.block_size;
  const BlockShiftInvertResult block = block_shift_invert(l.k, m_singular, count, options);
  ASSERT_EQ(block.status, BlockShiftInvertResult::Status::successful) << block.message;
  // phi_f and its residual on the massive dofs: the massless rows of K phi
  // vanish for an eigenvector (K_zf phi_f + K_zz phi_z = 0).
  auto condensed_bound = [&](const Eigen::VectorXd& lambda, const Eigen::MatrixXd& phi) {
    Eigen::MatrixXd phi_f(massive.size(), count);
    for (size_t i = 0; i < massive.size(); ++i)
      phi_f.row(static_cast<Eigen::Index>(i)) = phi.row(massive[i]);
    const Eigen::MatrixXd r = condensed * phi_f - m_ff * phi_f * lambda.asDiagonal();
    return r.norm() / std::sqrt(mu_min) + static_cast<double>(massive.size()) * eps * lambda_max;
  };
  const double error = (block.eigenvalues - exact).cwiseAbs().maxCoeff();
  const double bound = condensed_bound(block.eigenvalues, block.eigenvectors);
  const double gram = gram_error(m_singular, block.eigenvectors);
  const double residual =
      largest_relative_residual(l.k, m_singular, block.eigenvalues, block.eigenvectors);
  std::printf("singular M (%zu of %d dofs massless), lowest %d: max|d lambda| %.3e (bound %.3e); "
              "max |K phi - lambda M phi| / |K phi| %.3e; max |Phi^T M Phi - I| %.3e\n",
              massless.size(), n, count, error, bound, residual, gram);
  EXPECT_LE(error, bound); // residual bound, condensed pencil
  EXPECT_LE(residual, options.tolerance + 2.0 * block.residual_floors.maxCoeff()); // its stop
  EXPECT_LE(gram, n * eps); // orthonormal to round-off
  // lowest_modes (Spectra on SparseLU at this size) needs M only positive
  // semi-definite too, and reports omega_max = +inf; max_angular_frequency
  // has no finite value to give.
  const Modes modes = lowest_modes(l.k, m_singular, count, ModalSolver::sparse);
  const double lanczos_error = (modes.omega_squared - exact).cwiseAbs().maxCoeff();
  const double lanczos_bound = condensed_bound(modes.omega_squared, modes.shapes);
  std::printf("  lowest_modes: max|d lambda| %.3e (bound %.3e), omega_max %g\n", lanczos_error,
              lanczos_bound, modes.omega_max);
  EXPECT_LE(lanczos_error, lanczos_bound); // residual bound, condensed pencil
  EXPECT_TRUE(std::isinf(modes.omega_max));
  EXPECT_THROW(max_angular_frequency(l.k, m_singular), ModalError);
}

TEST(BlockShiftInvert, SingularStiffnessIsAStatus) {
  // Free cube: the constant is a rigid motion, K singular.
  const Laplacian3d l = laplacian_3d(22, true);
  BlockShiftInvertResult result = block_shift_invert(l.k, l.m, 10);
  std::printf("free cube: status %d, %s, lowest %.3e\n", static_cast<int>(result.status),
              result.message.c_str(),
              result.eigenvalues.size() ? result.eigenvalues(0) : std::nan(""));
  // CHOLMOD meets a pivot <= 0 or rcond < n eps, or factorizes the round-off
  // and the rigid motion comes out at the round-off level n eps lambda_max,
  // lambda_max < 3 x 12 / h^2 (the 1D pencil's kappa < 12 / h^2, h = 1/21).
  const double floor = l.k.rows() * eps * 36.0 / std::pow(1.0 / 21.0, 2);
  EXPECT_TRUE(result.status == BlockShiftInvertResult::Status::stiffness_not_positive_definite ||
              (result.status == BlockShiftInvertResult::Status::successful &&
               result.eigenvalues(0) < floor));
  // lowest_modes solves it either way (block method above 10,000 dofs,
  // about a shift below the spectrum), the constant a zero mode.
  const Modes modes = lowest_modes(l.k, l.m, 10, ModalSolver::sparse);
  EXPECT_TRUE(modes.accuracy.passed) << modes.accuracy.failure;
  EXPECT_EQ(modes.accuracy.n_zero, 1);
}

TEST(BlockShiftInvert, RejectsABasisLargerThanTheSpace) {
  const Laplacian3d l = laplacian_3d(4, false); // 64 dofs
  BlockShiftInvertOptions options;
  options.block_size = 16;
  EXPECT_THROW(block_shift_invert(l.k, l.m, 10, options), std::invalid_argument);
  EXPECT_THROW(block_shift_invert(l.k, l.m, 0), std::invalid_argument);
}

} // namespace
} // namespace rsi

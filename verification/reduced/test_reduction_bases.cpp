// V3 / V4: the reduction bases of the bladed disk (SPEC §3, §4; paper
// eqs. 3-20), and the Craig-Chang-Martinez boundary extended to the tip
// rotations (paper §5.3; Bladh, Pierre, Castanier, AIAA J. 41, 2003).
//
// V3: fixed-interface and free modes are M-orthonormal and K-orthogonal,
//     the Craig-Bampton stiffness is block diagonal.
//     The characteristic constraint modes (Castanier et al. 2001) are
//     M^_BB-orthonormal and diagonalise K^_BB.
// V4: CB(eta = 0) stiffness = Schur complement; CB(0) = CCM(0) = Guyan;
//     static tip loads reproduced exactly at every eta, psi; CB with every
//     fixed-interface mode reproduces the full eigenvalues; the reduced
//     eigenvalues are Rayleigh-Ritz upper bounds decreasing as modes are added;
//     CC with every boundary mode has CB's eigenvalues, with fewer it bounds
//     them from above, decreasing as boundary modes are added.
//
// Every reference quantity is computed here independently of reduced/:
// dense LAPACKE dsygvd eigenproblems and dense Eigen Cholesky factorizations
// (reduced/ uses CHOLMOD and Spectra's Lanczos). The tolerances are
// first-order round-off bounds, n eps times the relevant norm or condition
// number (the convention of test_orthogonality): they are worst-case, so the
// measured errors are printed with their ratio to the bound.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <lapacke.h>

#include "bladed_disk.hpp"
#include "characteristic_constraint.hpp"
#include "craig_chang_martinez.hpp"
#include "modal_analysis.hpp"
#include "partition.hpp"
#include "reduction.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// Infinity norm: an upper bound of the 2-norm of a symmetric matrix.
double norm_inf(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  return a.cwiseAbs().rowwise().sum().maxCoeff();
}

/// Extreme eigenvalues (min, max) of a symmetric matrix (Eigen, values only).
std::pair<double, double> extreme_eigenvalues(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  const Eigen::VectorXd w =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, Eigen::EigenvaluesOnly).eigenvalues();
  return {w(0), w(w.size() - 1)};
}

/// Spectral norm of any matrix: sqrt(lambda_max(A^T A)).
double norm2(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  const Eigen::MatrixXd ata = a.cols() <= a.rows() ? Eigen::MatrixXd(a.transpose() * a)
                                                   : Eigen::MatrixXd(a * a.transpose());
  return std::sqrt(std::max(extreme_eigenvalues(ata).second, 0.0));
}

/// The block A(rows, cols) of a dense matrix.
Eigen::MatrixXd block(const Eigen::Ref<const Eigen::MatrixXd>& a, const std::vector<int>& rows,
                      const std::vector<int>& cols) {
  return take_rows(Eigen::MatrixXd(take_rows(a, rows).transpose()), cols).transpose();
}

/// All eigenpairs of A x = lambda B x (A, B symmetric, B positive definite),
/// by LAPACKE dsygvd; eigenvectors B-normalised, eigenvalues ascending.
struct DenseEigen {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};

DenseEigen dense_eigen(const Eigen::Ref<const Eigen::MatrixXd>& a,
                       const Eigen::Ref<const Eigen::MatrixXd>& b) {
  const int n = static_cast<int>(a.rows());
  Eigen::MatrixXd aa = a;
  Eigen::MatrixXd bb = b;
  DenseEigen out;
  out.values.resize(n);
  const lapack_int info = LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'V', 'L', n, aa.data(), n, bb.data(),
                                         n, out.values.data());
  if (info != 0) throw std::runtime_error("dense_eigen: dsygvd info " + std::to_string(info));
  out.vectors = aa;
  return out;
}

/// Backward-error bound of each eigenvalue of a dense solve (dsygvd is
/// backward stable: perturbations n eps ||A||, n eps ||B||):
/// |d lambda_i| <= n eps (||A|| + |lambda_i| ||B||) ||x_i||^2, x_i B-normalised.
Eigen::VectorXd solve_bounds(const DenseEigen& e, double a_norm, double b_norm) {
  const int n = static_cast<int>(e.values.size());
  Eigen::VectorXd bound(n);
  for (int i = 0; i < n; ++i)
    bound(i) = n * eps * (a_norm + std::abs(e.values(i)) * b_norm) * e.vectors.col(i).squaredNorm();
  return bound;
}

struct Model {
  BladedDisk bd;
  Partition p;
  Eigen::MatrixXd k, m;                     ///< dense K, M
  Eigen::SparseMatrix<double> k_abs, m_abs; ///< |K|, |M|
  double k_norm = 0.0, m_norm = 0.0;
  Eigen::LLT<Eigen::MatrixXd> k_llt; ///< dense Cholesky of K (static reference)

  int n() const { return bd.n_dofs(); }
};

/// Eigenpairs of a reduced basis and the bound of each eigenvalue: the
/// rounding of K^ = T^T K T, M^ = T^T M T, |x^T dK^ x| <= n eps (|T||x|)^T |K| (|T||x|)
/// (and M), plus the backward error of the dense reduced solve.
struct ReducedEigen {
  DenseEigen eig;
  Eigen::VectorXd bound;
};

class ReductionBases : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    auto model = std::make_unique<Model>();
    model->bd = assemble_bladed_disk(
        load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json"));
    model->p = make_partition(model->bd.n_dofs(), model->bd.boundary);
    model->k = Eigen::MatrixXd(model->bd.stiffness);
    model->m = Eigen::MatrixXd(model->bd.mass);
    model->k_abs = model->bd.stiffness.cwiseAbs();
    model->m_abs = model->bd.mass.cwiseAbs();
    model->k_norm = norm_inf(model->k);
    model->m_norm = norm_inf(model->m);
    model->k_llt.compute(model->k);
    ASSERT_EQ(model->k_llt.info(), Eigen::Success) << "dense Cholesky of K";
    std::printf("bladed disk: n = %d, n_B = %d, ||K||_inf = %.3e, ||M||_inf = %.3e\n", model->n(),
                model->p.n_boundary(), model->k_norm, model->m_norm);
    s_model = std::move(model);
    s_bases = std::make_unique<std::map<std::pair<std::string, int>, ReducedBasis>>();
  }
  static void TearDownTestSuite() {
    s_bases.reset();
    s_full.reset();
    s_model.reset();
  }

  static const Model& model() { return *s_model; }

  /// Every mode of the bladed disk (dsygvd), computed on first use (~0.7 s).
  static const DenseEigen& full() {
    if (!s_full) {
      const Model& md = model();
      s_full = std::make_unique<DenseEigen>(dense_eigen(md.k, md.m));
      s_full_bound = solve_bounds(*s_full, md.k_norm, md.m_norm);
      std::printf("full model: omega_1^2 = %.6e, omega_max^2 = %.6e rad^2/s^2\n", s_full->values(0),
                  s_full->values(md.n() - 1));
    }
    return *s_full;
  }
  /// solve_bounds of full().
  static const Eigen::VectorXd& full_bound() {
    full();
    return s_full_bound;
  }

  /// reduce_bladed_disk, built once per (method, modes) for the whole suite.
  static const ReducedBasis& basis(const std::string& method, int modes) {
    const std::pair<std::string, int> key{method, modes};
    auto it = s_bases->find(key);
    if (it == s_bases->end())
      it = s_bases->emplace(key, reduce_bladed_disk(model().bd, method, modes)).first;
    return it->second;
  }

  static ReducedEigen reduced_eigen(const ReducedBasis& b) {
    const Model& md = model();
    ReducedEigen out;
    out.eig = dense_eigen(b.stiffness, b.mass);
    out.bound = solve_bounds(out.eig, norm_inf(b.stiffness), norm_inf(b.mass));
    const Eigen::MatrixXd shapes = b.transformation.cwiseAbs() * out.eig.vectors.cwiseAbs();
    const Eigen::MatrixXd k_shapes = md.k_abs * shapes;
    const Eigen::MatrixXd m_shapes = md.m_abs * shapes;
    for (int i = 0; i < out.eig.values.size(); ++i)
      out.bound(i) += md.n() * eps *
                      (shapes.col(i).dot(k_shapes.col(i)) +
                       std::abs(out.eig.values(i)) * shapes.col(i).dot(m_shapes.col(i)));
    return out;
  }

  static std::unique_ptr<Model> s_model;
  static std::unique_ptr<DenseEigen> s_full;
  static Eigen::VectorXd s_full_bound;
  static std::unique_ptr<std::map<std::pair<std::string, int>, ReducedBasis>> s_bases;
};
std::unique_ptr<Model> ReductionBases::s_model;
std::unique_ptr<DenseEigen> ReductionBases::s_full;
Eigen::VectorXd ReductionBases::s_full_bound;
std::unique_ptr<std::map<std::pair<std::string, int>, ReducedBasis>> ReductionBases::s_bases;

// ---------------------------------------------------------------- V3

// V3, Craig-Bampton (paper eqs. 3-7): the first eta columns of T, restricted
// to I, are the fixed-interface modes, zero on B. Checked on K^, M^ as
// stored in the basis: M^(modal, modal) = Phi^T M_II Phi = I,
// K^(modal, modal) = diag(omega_i^2) with omega_i^2 the eigenvalues of
// (K_II, M_II) solved here by dsygvd, and K^(modal, B) = Phi^T (K_II Psi + K_IB) = 0.
TEST_F(ReductionBases, CraigBamptonFixedInterfaceModesAndBlockDiagonalStiffness) {
  const Model& md = model();
  const int n = md.n();
  const int nb = md.p.n_boundary();
  const int n_i = md.p.n_interior();
  const Eigen::MatrixXd k_ii = block(md.k, md.p.interior, md.p.interior);
  const Eigen::MatrixXd m_ii = block(md.m, md.p.interior, md.p.interior);
  const DenseEigen fixed = dense_eigen(k_ii, m_ii);
  const Eigen::VectorXd fixed_bound = solve_bounds(fixed, norm_inf(k_ii), norm_inf(m_ii));
  // Spectra's Lanczos (reduced/ uses it when 4 eta < n_I) stops at a relative residual
  // tol = 1e-12 of the shift-inverted operator: eigenvalues within tol relative, and
  // Ritz vectors K-orthogonal up to tol^2 lambda_max (second order in the residual).
  const double lanczos_tol = 1e-12;
  for (int eta : {88, n_i}) {
    const ReducedBasis& b = basis("cb", eta);
    const double on_boundary =
        take_rows(b.transformation, md.p.boundary).leftCols(eta).cwiseAbs().maxCoeff();
    // The modes are placed on I only: their rows on B are exact zeros.
    std::printf("CB eta = %d: max|T(B, modal)| = %.3e (exact 0)\n", eta, on_boundary);
    EXPECT_EQ(on_boundary, 0.0);

    const Eigen::VectorXd t_col = b.transformation.colwise().norm();
    const double k_hat_norm = norm_inf(b.stiffness);
    double m_err = 0.0, m_ratio = 0.0, off_err = 0.0, off_ratio = 0.0, diag_err = 0.0,
           diag_ratio = 0.0, mb_err = 0.0, mb_ratio = 0.0;
    for (int j = 0; j < eta; ++j)
      for (int i = 0; i < eta; ++i) {
        const double cross = t_col(i) * t_col(j);
        // Product rounding and solver orthogonality: n eps ||M|| |phi_i| |phi_j|.
        const double dm = std::abs(b.mass(i, j) - (i == j ? 1.0 : 0.0));
        m_err = std::max(m_err, dm);
        m_ratio = std::max(m_ratio, dm / (n * eps * md.m_norm * cross));
        if (i != j) {
          // n eps ||K|| |phi_i| |phi_j| + tol^2 omega_max^2 (Lanczos).
          const double bound =
              n * eps * md.k_norm * cross + lanczos_tol * lanczos_tol * fixed.values(n_i - 1);
          off_err = std::max(off_err, std::abs(b.stiffness(i, j)));
          off_ratio = std::max(off_ratio, std::abs(b.stiffness(i, j)) / bound);
        } else {
          // Both eigen solves (dsygvd backward error), the product, Lanczos tol.
          const double w2 = fixed.values(i);
          const double bound =
              fixed_bound(i) + n * eps * (md.k_norm + w2 * md.m_norm) * cross + lanczos_tol * w2;
          const double err = std::abs(b.stiffness(i, i) - w2);
          diag_err = std::max(diag_err, err / w2);
          diag_ratio = std::max(diag_ratio, err / bound);
        }
      }
    for (int j = 0; j < nb; ++j)
      for (int i = 0; i < eta; ++i) {
        // K^(modal, B) = Phi^T (K_II Psi + K_IB): the Cholesky residual of Psi and the
        // rounding of T^T K T, each <= n eps ||K|| |t_i| |t_b|.
        const double bound = 2.0 * n * eps * md.k_norm * t_col(i) * t_col(eta + j);
        const double v = std::abs(b.stiffness(i, eta + j));
        mb_err = std::max(mb_err, v);
        mb_ratio = std::max(mb_ratio, v / bound);
      }
    std::printf("  M^(modal, modal) - I: max %.3e (%.2e of bound)\n", m_err, m_ratio);
    std::printf("  K^(modal, modal) off-diagonal: max %.3e = %.3e ||K^|| (%.2e of bound)\n",
                off_err, off_err / k_hat_norm, off_ratio);
    std::printf("  K^(i, i) vs omega_i^2 of (K_II, M_II): max relative %.3e (%.2e of bound)\n",
                diag_err, diag_ratio);
    std::printf("  K^(modal, B): max %.3e = %.3e ||K^|| (%.2e of bound)\n", mb_err,
                mb_err / k_hat_norm, mb_ratio);
    EXPECT_LE(m_ratio, 1.0);
    EXPECT_LE(off_ratio, 1.0);
    EXPECT_LE(diag_ratio, 1.0);
    EXPECT_LE(mb_ratio, 1.0);
  }
}

// V3, Craig-Chang-Martinez (paper eqs. 8-20): the free modes Phi_1 that
// craig_chang_martinez uses (lowest_modes with its solver choice, which is
// deterministic) satisfy Phi_1^T M Phi_1 = I and Phi_1^T K Phi_1 = diag(omega^2)
// of the full dense solve, and the modal columns of T are eq. 20,
// Phi_1 - T_attachment Phi_1B (exact zeros on B).
TEST_F(ReductionBases, CraigChangMartinezFreeModesOrthonormal) {
  const Model& md = model();
  const int n = md.n();
  const int nb = md.p.n_boundary();
  const double lanczos_tol = 1e-12; // as above
  for (int psi : {44, 200}) {
    const ReducedBasis& b = basis("ccm", psi);
    const Modes free = lowest_modes(md.bd.stiffness, md.bd.mass, psi, few_modes(psi, n));
    const Eigen::MatrixXd& phi = free.shapes;
    const Eigen::VectorXd norm2_col = phi.colwise().squaredNorm();
    const Eigen::MatrixXd mm = phi.transpose() * md.m * phi;
    const Eigen::MatrixXd kk = phi.transpose() * md.k * phi;
    double m_err = 0.0, m_ratio = 0.0, off_ratio = 0.0, diag_err = 0.0, diag_ratio = 0.0;
    for (int j = 0; j < psi; ++j)
      for (int i = 0; i < psi; ++i) {
        const double cross = std::sqrt(norm2_col(i) * norm2_col(j));
        // n eps ||M|| |phi_i| |phi_j|, as for the fixed-interface modes.
        const double dm = std::abs(mm(i, j) - (i == j ? 1.0 : 0.0));
        m_err = std::max(m_err, dm);
        m_ratio = std::max(m_ratio, dm / (n * eps * md.m_norm * cross));
        if (i != j) {
          const double bound =
              n * eps * md.k_norm * cross + lanczos_tol * lanczos_tol * full().values(n - 1);
          off_ratio = std::max(off_ratio, std::abs(kk(i, j)) / bound);
        } else {
          const double w2 = full().values(i);
          const double bound =
              full_bound()(i) + n * eps * (md.k_norm + w2 * md.m_norm) * cross + lanczos_tol * w2;
          diag_err = std::max(diag_err, std::abs(kk(i, i) - w2) / w2);
          diag_ratio = std::max(diag_ratio, std::abs(kk(i, i) - w2) / bound);
        }
      }
    // Eq. 20 recomputed from T's own attachment columns: the products differ by
    // rounding only, componentwise <= (n_B + 1) eps (|Phi_1| + |A| |Phi_1B|).
    const Eigen::MatrixXd a = b.transformation.leftCols(nb);
    const Eigen::MatrixXd phi_b = take_rows(phi, md.p.boundary);
    const Eigen::MatrixXd expected = phi - a * phi_b;
    const Eigen::MatrixXd bound20 =
        (nb + 1) * eps * (phi.cwiseAbs() + a.cwiseAbs() * phi_b.cwiseAbs());
    const Eigen::MatrixXd diff20 = (b.transformation.rightCols(psi) - expected).cwiseAbs();
    const double eq20_ratio =
        diff20
            .cwiseQuotient(bound20 +
                           Eigen::MatrixXd::Constant(n, psi, std::numeric_limits<double>::min()))
            .maxCoeff();
    // Not asserted: in exact arithmetic the attachment modes R(:,B) R_B^-1 are
    // M-orthogonal to Phi_1; round-off in R = K^-1 - Phi_1 Omega_1^-1 Phi_1^T leaves
    // components along Phi_1, harmless (they do not change span T).
    const double am = (a.transpose() * md.m * phi).cwiseAbs().maxCoeff();
    std::printf("CCM psi = %d free modes: max|Phi^T M Phi - I| = %.3e (%.2e of bound), "
                "Phi^T K Phi: off-diagonal %.2e of bound, diagonal vs full omega^2 max relative "
                "%.3e (%.2e of bound)\n",
                psi, m_err, m_ratio, off_ratio, diag_err, diag_ratio);
    std::printf("  T(:, modal) vs Phi_1 - T(:, attachment) Phi_1B (eq. 20): max %.3e (%.2e of "
                "bound); info: max|A^T M Phi_1| = %.3e\n",
                diff20.maxCoeff(), eq20_ratio, am);
    EXPECT_LE(m_ratio, 1.0);
    EXPECT_LE(off_ratio, 1.0);
    EXPECT_LE(diag_ratio, 1.0);
    EXPECT_LE(eq20_ratio, 1.0);
  }
}

// ---------------------------------------------------------------- V4

// V4: CB(eta = 0) stiffness = K_BB - K_BI K_II^-1 K_IB, the Schur complement
// computed here by a dense Eigen Cholesky K_II = L L^T: S = K_BB - W^T W,
// W = L^-1 K_IB. Componentwise round-off (Higham, Accuracy and Stability,
// §3.5 and Thm 10.3), X = K_II^-1 K_IB = -Psi:
// - S: the Cholesky backward error |dK_II| <= n eps |L||L^T| moves S by
//   |X|^T |dK_II| |X|, the products by n eps (|K_BB| + |W|^T |W|);
// - K^ = T^T K T: the rounding n eps |T|^T |K| |T|; the error of Psi enters
//   at second order only, since (K T)_I = K_II Psi + K_IB = 0.
TEST_F(ReductionBases, CraigBamptonZeroIsSchurComplement) {
  const Model& md = model();
  const int n = md.n();
  const Eigen::MatrixXd k_ii = block(md.k, md.p.interior, md.p.interior);
  const Eigen::MatrixXd k_ib = block(md.k, md.p.interior, md.p.boundary);
  const Eigen::MatrixXd k_bb = block(md.k, md.p.boundary, md.p.boundary);
  const Eigen::LLT<Eigen::MatrixXd> llt(k_ii);
  ASSERT_EQ(llt.info(), Eigen::Success) << "dense Cholesky of K_II";
  const Eigen::MatrixXd l = llt.matrixL();
  const Eigen::MatrixXd w = llt.matrixL().solve(k_ib);
  const Eigen::MatrixXd schur = k_bb - w.transpose() * w;
  const ReducedBasis& b = basis("cb", 0);
  const Eigen::MatrixXd t_abs = b.transformation.cwiseAbs();
  const Eigen::MatrixXd lx = l.transpose().cwiseAbs() * take_rows(t_abs, md.p.interior);
  const Eigen::MatrixXd bound = n * eps *
                                (t_abs.transpose() * (md.k_abs * t_abs) + k_bb.cwiseAbs() +
                                 w.cwiseAbs().transpose() * w.cwiseAbs() + lx.transpose() * lx);
  const Eigen::MatrixXd err = (b.stiffness - schur).cwiseAbs();
  const double ratio = err.cwiseQuotient(bound).maxCoeff();
  std::printf("CB(0) K^ vs Schur complement: max|K^ - S| = %.3e, ||K^ - S||_2 / ||S||_2 = %.3e, "
              "max|K^ - S| / componentwise bound = %.2e\n",
              err.maxCoeff(), norm2(b.stiffness - schur) / norm2(schur), ratio);
  EXPECT_LE(ratio, 1.0);
}

// V4: CB(0), CCM(0) and Guyan are the same basis in the same coordinates q_B
// (SPEC §3): T, K^, M^ equal to round-off.
// - T: Guyan/CB take Psi from a CHOLMOD factor of K_II, CCM from K^-1 E_B
//   (CHOLMOD of K) times R_B^-1. Each is the exact constraint-mode matrix of a
//   K within n eps ||K||: ||d Psi|| <= n eps ||K|| ||K_II^-1|| (1 + ||Psi||) per
//   method; the R_B^-1 solve adds n_B eps cond(R_B) (1 + ||Psi||).
// - K^ is stationary in d Psi ((K T)_I = 0): 2 n eps ||K|| ||T||^2 (products)
//   + 2 ||dT|| n eps ||K|| (1 + ||Psi||) (residual of Psi) + ||K|| ||dT||^2.
// - M^ is not: 2 n eps ||M|| ||T||^2 + 2 ||M|| ||T|| ||dT|| + ||M|| ||dT||^2.
TEST_F(ReductionBases, ZeroModeLimitsCoincideWithGuyan) {
  const Model& md = model();
  const int n = md.n();
  const int nb = md.p.n_boundary();
  const ReducedBasis& g = basis("guyan", 0);
  const ReducedBasis& cb = basis("cb", 0);
  const ReducedBasis& ccm = basis("ccm", 0);
  ASSERT_EQ(cb.n_reduced(), nb);
  ASSERT_EQ(ccm.n_reduced(), nb);
  const double lambda_min_ii = extreme_eigenvalues(block(md.k, md.p.interior, md.p.interior)).first;
  const double psi_norm = norm2(take_rows(g.transformation, md.p.interior));
  const double t_norm = norm2(g.transformation);
  const double dpsi = n * eps * md.k_norm / lambda_min_ii * (1.0 + psi_norm);
  for (const ReducedBasis* other : {&cb, &ccm}) {
    const double dt = 2.0 * dpsi + nb * eps * other->cond_rb * (1.0 + psi_norm);
    const double k_bound = 2.0 * n * eps * md.k_norm * t_norm * t_norm +
                           2.0 * dt * n * eps * md.k_norm * (1.0 + psi_norm) + md.k_norm * dt * dt;
    const double m_bound = 2.0 * n * eps * md.m_norm * t_norm * t_norm +
                           2.0 * md.m_norm * t_norm * dt + md.m_norm * dt * dt;
    const double e_t = norm2(other->transformation - g.transformation);
    const double e_k = norm2(other->stiffness - g.stiffness);
    const double e_m = norm2(other->mass - g.mass);
    std::printf("%s(0) vs Guyan: ||dT||_2 = %.3e (bound %.3e, ||T||_2 = %.3e), ||dK^||_2 = %.3e = "
                "%.3e ||K^|| (bound %.3e), ||dM^||_2 = %.3e = %.3e ||M^|| (bound %.3e)\n",
                other->method.c_str(), e_t, dt, t_norm, e_k, e_k / norm2(g.stiffness), k_bound, e_m,
                e_m / norm2(g.mass), m_bound);
    EXPECT_LE(e_t, dt);
    EXPECT_LE(e_k, k_bound);
    EXPECT_LE(e_m, m_bound);
  }
}

// V4: a static load on the tips (random 44-vector, fixed seed) is reproduced
// exactly by CB and CCM at any eta, psi, since span T contains K^-1 E_B: the
// constraint modes (CB), the residual attachment modes plus Phi_1 (CCM).
// u_red = T K^-1 T^T f against u = K^-1 f (dense Cholesky). Both are
// backward-stable solutions of K u = f (static condensation is block
// Cholesky): n eps cond(K) each; CCM adds n_B eps cond(R_B) (R_B^-1 and the
// exact identity imposed on the boundary rows).
TEST_F(ReductionBases, StaticTipLoadsExact) {
  const Model& md = model();
  const int n = md.n();
  const int nb = md.p.n_boundary();
  std::mt19937 generator(2007);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd f_b(nb);
  for (int i = 0; i < nb; ++i)
    f_b(i) = 1000.0 * uniform(generator); // [N]
  const Eigen::VectorXd f = place_rows(n, md.p.boundary, f_b);
  const Eigen::VectorXd u = md.k_llt.solve(f);
  const std::pair<double, double> ek = extreme_eigenvalues(md.k);
  const double cond_k = ek.second / ek.first;
  std::printf("cond_2(K) = %.3e\n", cond_k);
  for (const char* method : {"cb", "ccm"})
    for (int modes : {0, 10, 44, 88}) {
      const ReducedBasis& b = basis(method, modes);
      const Eigen::LLT<Eigen::MatrixXd> llt(b.stiffness);
      ASSERT_EQ(llt.info(), Eigen::Success)
          << method << " " << modes << ": K^ not positive definite";
      const Eigen::VectorXd q = llt.solve(b.transformation.transpose() * f);
      const Eigen::VectorXd u_red = b.transformation * q;
      const double err = (u_red - u).norm() / u.norm();
      const double bound = 2.0 * n * eps * cond_k + nb * eps * b.cond_rb;
      std::printf("static tip load, %s %d: ||T q - K^-1 f|| / ||K^-1 f|| = %.3e (bound %.3e); "
                  "tip dofs alone %.3e\n",
                  method, modes, err, bound,
                  (take_rows(u_red, md.p.boundary) - take_rows(u, md.p.boundary)).norm() /
                      take_rows(u, md.p.boundary).norm());
      EXPECT_LE(err, bound);
    }
}

// V4: CB with all n_I = 638 fixed-interface modes spans the whole space: its
// eigenvalues are the full ones (lowest 50 compared), to the bounds of both
// dense solves (and of forming K^, M^).
TEST_F(ReductionBases, AllFixedInterfaceModesReproduceFullEigenvalues) {
  const Model& md = model();
  const int n_i = md.p.n_interior();
  const ReducedBasis& b = basis("cb", n_i);
  ASSERT_EQ(b.n_reduced(), md.n());
  const ReducedEigen red = reduced_eigen(b);
  double worst = 0.0, worst_ratio = 0.0;
  for (int i = 0; i < 50; ++i) {
    const double err = std::abs(red.eig.values(i) - full().values(i));
    worst = std::max(worst, err / full().values(i));
    worst_ratio = std::max(worst_ratio, err / (red.bound(i) + full_bound()(i)));
  }
  std::printf("CB(%d), lowest 50 eigenvalues vs full: max relative error %.3e (%.2e of bound; "
              "bound for omega_1^2 relative %.3e)\n",
              n_i, worst, worst_ratio, (red.bound(0) + full_bound()(0)) / full().values(0));
  EXPECT_LE(worst_ratio, 1.0);
}

// V4: Rayleigh-Ritz. For any basis, lambda_i(reduced) >= lambda_i(full) for
// i < r, and lambda_max(reduced) <= lambda_max(full) (Courant-Fischer, both
// ends); the bases are nested as eta (psi) grows (the same constraint
// modes / K^-1 E_B plus more modes), so each lambda_i decreases. Tolerance:
// the eigenvalue bounds of the two problems compared.
TEST_F(ReductionBases, ReducedEigenvaluesBoundFullAndDecrease) {
  const Model& md = model();
  const int n = md.n();
  const int lowest = 20;
  const std::vector<int> counts{0, 4, 8, 16, 32, 64, 88};
  for (const char* method : {"cb", "ccm"}) {
    Eigen::VectorXd previous, previous_bound;
    for (int modes : counts) {
      const ReducedBasis& b = basis(method, modes);
      const ReducedEigen red = reduced_eigen(b);
      const int r = b.n_reduced();
      double below = 0.0, below_ratio = 0.0;
      for (int i = 0; i < r; ++i) {
        const double shortfall = full().values(i) - red.eig.values(i);
        below = std::max(below, shortfall / full().values(i));
        below_ratio = std::max(below_ratio, shortfall / (red.bound(i) + full_bound()(i)));
      }
      double rel_err = 0.0;
      for (int i = 0; i < lowest; ++i)
        rel_err =
            std::max(rel_err, std::abs(red.eig.values(i) - full().values(i)) / full().values(i));
      const double top_excess = red.eig.values(r - 1) - full().values(n - 1);
      const double top_ratio = top_excess / (red.bound(r - 1) + full_bound()(n - 1));
      double rise = -std::numeric_limits<double>::infinity();
      double rise_ratio = rise;
      if (previous.size() > 0) {
        for (int i = 0; i < lowest; ++i) {
          const double d = red.eig.values(i) - previous(i);
          rise = std::max(rise, d / previous(i));
          rise_ratio = std::max(rise_ratio, d / (red.bound(i) + previous_bound(i)));
        }
      }
      std::printf("%s %2d (r = %3d): lowest %d max relative error %.3e; max (full - reduced) / "
                  "full %.3e (%.2e of bound); omega_max = %.6e vs full %.6e rad/s; rise vs "
                  "previous %.3e (%.2e of bound)\n",
                  method, modes, r, lowest, rel_err, below, below_ratio,
                  std::sqrt(red.eig.values(r - 1)), std::sqrt(full().values(n - 1)),
                  previous.size() > 0 ? rise : 0.0, previous.size() > 0 ? rise_ratio : 0.0);
      EXPECT_LE(below_ratio, 1.0) << method << " " << modes << ": below the full eigenvalues";
      EXPECT_LE(top_ratio, 1.0) << method << " " << modes << ": omega_max above the full one";
      if (previous.size() > 0) {
        EXPECT_LE(rise_ratio, 1.0) << method << " " << modes << ": not decreasing";
      }
      previous = red.eig.values.head(lowest);
      previous_bound = red.bound.head(lowest);
    }
  }
}

// ------------------------------------------------ paper §5.3, Bladh et al.

/// R_B(psi) = sum_{i >= psi} phi_iB phi_iB^T / omega_i^2 from every mode of
/// the dense solve: the residual flexibility (eq. 14) summed over the
/// discarded modes, terms all positive semi-definite, no cancellation.
Eigen::MatrixXd residual_flexibility_tail(const DenseEigen& all, const std::vector<int>& boundary,
                                          int psi) {
  const int n = static_cast<int>(all.values.size());
  const Eigen::MatrixXd phi_b = take_rows(all.vectors, boundary).rightCols(n - psi);
  return phi_b * all.values.tail(n - psi).cwiseInverse().asDiagonal() * phi_b.transpose();
}

/// E = K^-1_BB - Phi_B Omega^-2 Phi_B^T over every mode: zero in exact
/// arithmetic. CCM's R = K^-1 - Phi_1 Omega_1^-1 Phi_1^T (eq. 14) differs
/// from the tail sum by exactly E at every psi, so ||E||_2 (dense Cholesky
/// and dsygvd) is the round-off floor of R_B evaluated by subtraction.
double subtraction_floor(const Model& md, const DenseEigen& all, const std::vector<int>& boundary) {
  const int nb = static_cast<int>(boundary.size());
  const Eigen::MatrixXd k_inv_b = take_rows(
      md.k_llt.solve(place_rows(md.n(), boundary, Eigen::MatrixXd::Identity(nb, nb))), boundary);
  return norm2(k_inv_b - residual_flexibility_tail(all, boundary, 0));
}

/// Relative change of cond(R_B) when every eigenvalue moves by at most delta
/// (Weyl): delta (1/lambda_min + 1/lambda_max) / (1 - delta/lambda_min).
double cond_tolerance(double lambda_min, double lambda_max, double delta) {
  return delta * (1.0 / lambda_min + 1.0 / lambda_max) / (1.0 - delta / lambda_min);
}

// SPEC §3: cond(R_B) is reported for the default (tip u, v) boundary, finite,
// and equal to the exact one (tail sum) up to the round-off floor of R_B:
// 2 ||E|| (the tail sum and CCM's own evaluation, each within the floor).
TEST_F(ReductionBases, DefaultBoundaryCondRbReported) {
  const Model& md = model();
  const double floor = subtraction_floor(md, full(), md.p.boundary);
  std::printf("tip u, v boundary: round-off floor of R_B ||E||_2 = %.3e\n", floor);
  for (int psi : {0, 10, 44, 88}) {
    const ReducedBasis& b = basis("ccm", psi);
    const std::pair<double, double> e =
        extreme_eigenvalues(residual_flexibility_tail(full(), md.p.boundary, psi));
    const double exact = e.second / e.first;
    const double tol = cond_tolerance(e.first, e.second, 2.0 * floor);
    const double rel = std::abs(b.cond_rb - exact) / exact;
    std::printf("  CCM psi = %2d: cond_rb = %.6e, exact (tail sum) %.6e, relative difference %.3e "
                "(tolerance %.3e); lambda(R_B) in [%.3e, %.3e]\n",
                psi, b.cond_rb, exact, rel, tol, e.first, e.second);
    EXPECT_TRUE(std::isfinite(b.cond_rb));
    EXPECT_GE(b.cond_rb, 1.0);
    EXPECT_LE(rel, tol);
  }
  for (const char* method : {"cb", "guyan"}) {
    // Not a CCM basis: cond(R_B) is not defined and stays 0.
    EXPECT_EQ(basis(method, 0).cond_rb, 0.0) << method;
  }
}

// Paper §5.3 (Bladh et al. 2003): attachment modes on the tip rotations too
// (boundary u, v, theta of every tip: theta is tip_radial + 2). The u, v
// residual flexibility is a principal submatrix of the u, v, theta one, so
// by Cauchy interlacing cond(R_B) with theta >= cond(R_B) without, at every
// psi (tolerance: the eigenvalue round-off 66 eps lambda_max on lambda_min,
// relative 66 eps cond). What craig_chang_martinez does:
// - where R_B is resolvable (lambda_min(R_B) > 2 ||E||, the round-off floor)
//   and cond(R_B) < 1/(n eps), it accepts and reports cond(R_B) to the
//   tolerance above;
// - where even the exact cond(R_B) >= 1/(n eps) it must refuse (SPEC §3);
// - in between (lambda_min below the floor, exact cond below the limit) the
//   computed R_B is dominated by round-off of either sign, so accepting or
//   refusing is decided by round-off: either way it must be sound, i.e. an
//   accepted basis still bounds the eigenvalues from above (Rayleigh-Ritz),
//   a refusal names cond(R_B).
TEST_F(ReductionBases, RotationBoundaryConditioning) {
  const Model& md = model();
  const BladedDisk& bd = md.bd;
  const int n = md.n();
  std::vector<int> with_theta;
  for (int k = 0; k < bd.n_sectors; ++k) {
    ASSERT_EQ(bd.dofs[bd.tip_radial[k] + 2].kind, "theta");
    with_theta.push_back(bd.tip_radial[k]);
    with_theta.push_back(bd.tip_tangential[k]);
    with_theta.push_back(bd.tip_radial[k] + 2);
  }
  const Partition p_theta = make_partition(n, with_theta);
  const int nb = p_theta.n_boundary();
  const double limit = 1.0 / (n * eps);
  const double floor_uv = subtraction_floor(md, full(), md.p.boundary);
  const double floor_theta = subtraction_floor(md, full(), with_theta);
  std::printf("round-off floor of R_B ||E||_2: u, v %.3e, u, v, theta %.3e; refusal limit "
              "1/(n eps) = %.3e\n",
              floor_uv, floor_theta, limit);
  std::printf("  psi | cond(R_B) u,v | cond(R_B) u,v,theta | ratio | lambda_min(R_B) u,v,theta\n");
  std::map<int, std::pair<double, double>> theta_eig;
  std::map<int, double> cond_uv_exact;
  for (int psi : {0, 22, 44, 88, 200, 300, 400, 450, 480, 500, 520, 550, 600}) {
    const std::pair<double, double> uv =
        extreme_eigenvalues(residual_flexibility_tail(full(), md.p.boundary, psi));
    const std::pair<double, double> th =
        extreme_eigenvalues(residual_flexibility_tail(full(), with_theta, psi));
    theta_eig[psi] = th;
    const double cond_uv = uv.second / uv.first;
    cond_uv_exact[psi] = cond_uv;
    const double cond_th = th.second / th.first;
    std::printf("  %3d | %.3e | %.3e | %.3e | %.3e\n", psi, cond_uv, cond_th, cond_th / cond_uv,
                th.first);
    // Interlacing, when both are resolved in double precision (cond below 1/eps).
    if (std::abs(cond_th) < 1.0 / eps) {
      EXPECT_GE(cond_th * (1.0 + nb * eps * cond_th), cond_uv) << "psi " << psi;
    }
  }

  // Resolvable and well below the limit: accepted, cond_rb = exact.
  for (int psi : {0, 44, 88, 200}) {
    const std::pair<double, double> th = theta_eig.at(psi);
    const double exact = th.second / th.first;
    ASSERT_GT(th.first, 2.0 * floor_theta) << "psi " << psi << " not resolvable";
    ASSERT_LT(exact, limit);
    const ReducedBasis b = craig_chang_martinez(bd.stiffness, bd.mass, p_theta, psi);
    const double rel = std::abs(b.cond_rb - exact) / exact;
    const double tol = cond_tolerance(th.first, th.second, 2.0 * floor_theta);
    std::printf("CCM u,v,theta psi = %3d: accepted, cond_rb = %.4e, exact %.4e, relative "
                "difference %.3e (tolerance %.3e); u,v boundary: %.4e\n",
                psi, b.cond_rb, exact, rel, tol, cond_uv_exact.at(psi));
    EXPECT_LE(rel, tol);
  }

  // Exact cond(R_B) beyond 1/(n eps): must be refused.
  {
    const int psi = 550;
    const std::pair<double, double> th = theta_eig.at(psi);
    ASSERT_GE(th.second / th.first, limit);
    std::printf("CCM u,v,theta psi = %d (exact cond %.3e >= %.3e): ", psi, th.second / th.first,
                limit);
    try {
      const ReducedBasis b = craig_chang_martinez(bd.stiffness, bd.mass, p_theta, psi);
      std::printf("accepted, cond_rb = %.3e\n", b.cond_rb);
      ADD_FAILURE() << "a numerically singular R_B was accepted";
    } catch (const ReductionError& e) {
      std::printf("refused: %s\n", e.what());
      EXPECT_NE(std::string(e.what()).find("cond(R_B)"), std::string::npos);
    }
  }

  // Below the round-off floor, exact cond below the limit: decided by round-off.
  struct Probe {
    const char* name;
    const Partition* partition;
    const std::vector<int>* boundary;
    int psi;
    double floor;
  };
  for (const Probe& probe : {Probe{"u,v,theta", &p_theta, &with_theta, 480, floor_theta},
                             Probe{"u,v,theta", &p_theta, &with_theta, 500, floor_theta},
                             Probe{"u,v", &md.p, &md.p.boundary, 550, floor_uv}}) {
    const std::pair<double, double> e =
        extreme_eigenvalues(residual_flexibility_tail(full(), *probe.boundary, probe.psi));
    ASSERT_LT(e.first, 2.0 * probe.floor);
    ASSERT_LT(e.second / e.first, limit);
    std::printf("CCM %s psi = %d (exact cond %.3e, lambda_min %.3e < floor 2||E|| = %.3e): ",
                probe.name, probe.psi, e.second / e.first, e.first, 2.0 * probe.floor);
    try {
      const ReducedBasis b =
          craig_chang_martinez(bd.stiffness, bd.mass, *probe.partition, probe.psi);
      const ReducedEigen red = reduced_eigen(b);
      double below_ratio = -std::numeric_limits<double>::infinity(), err20 = 0.0;
      for (int i = 0; i < b.n_reduced(); ++i)
        below_ratio = std::max(below_ratio, (full().values(i) - red.eig.values(i)) /
                                                (red.bound(i) + full_bound()(i)));
      for (int i = 0; i < 20; ++i)
        err20 = std::max(err20, std::abs(red.eig.values(i) - full().values(i)) / full().values(i));
      std::printf("accepted, cond_rb = %.3e (exact %.3e); lowest 20 eigenvalues max relative "
                  "error %.3e (free modes 0..%d are in the basis); Rayleigh-Ritz shortfall %.2e "
                  "of bound\n",
                  b.cond_rb, e.second / e.first, err20, probe.psi - 1, below_ratio);
      EXPECT_LE(below_ratio, 1.0);
    } catch (const ReductionError& ex) {
      std::printf("refused: %s\n", ex.what());
      EXPECT_NE(std::string(ex.what()).find("cond(R_B)"), std::string::npos);
    }
  }
}

// ------------------------------------ characteristic constraint modes

/// Bound of the eigenvalue change from forming S^T A S (A = K^ or M^ of the CB
/// basis, S = diag(I, Psi_c)): each product of inner dimension k rounds by at
/// most k eps |.||.| (first order), two products: 2 k eps (|S||x|)^T |A| (|S||x|),
/// for K^ and lambda times for M^ (x M^_cc-normalised).
Eigen::VectorXd congruence_bounds(const ReducedBasis& cb, const Eigen::MatrixXd& s,
                                  const DenseEigen& e) {
  const Eigen::MatrixXd sx = s.cwiseAbs() * e.vectors.cwiseAbs();
  const double k = static_cast<double>(s.rows());
  Eigen::VectorXd bound(e.values.size());
  for (int i = 0; i < e.values.size(); ++i)
    bound(i) = 2.0 * k * eps *
               (sx.col(i).dot(cb.stiffness.cwiseAbs() * sx.col(i)) +
                std::abs(e.values(i)) * sx.col(i).dot(cb.mass.cwiseAbs() * sx.col(i)));
  return bound;
}

/// S = diag(I_eta, Psi_c) of a CC basis.
Eigen::MatrixXd congruence(const ReducedBasis& cc, int eta) {
  const int n_b = static_cast<int>(cc.boundary_shapes.rows());
  const int n_c = static_cast<int>(cc.boundary_shapes.cols());
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(eta + n_b, eta + n_c);
  s.topLeftCorner(eta, eta).setIdentity();
  s.bottomRightCorner(n_b, n_c) = cc.boundary_shapes;
  return s;
}

// V3, CC (Castanier, Tan, Pierre 2001, eq. 7): Psi_c^T M^_BB Psi_c = I and
// Psi_c^T K^_BB Psi_c = diag(lambda_c), lambda_c the eigenvalues of the CB
// basis's boundary pencil (K^_BB, M^_BB) solved here by dsygvd. Bounds: the
// B-orthonormality of a Cholesky-reduced solve, n_B eps cond(M^_BB), plus the
// rounding of S^T M^ S, 2 (eta + n_B) eps |x_i|^T |M^_BB| |x_j|; K^ the same
// times lambda plus n_B eps ||K^_BB|| |x_i| |x_j|, and dsygvd's own bound.
TEST_F(ReductionBases, CharacteristicConstraintModesOrthonormalAndDiagonal) {
  const Model& md = model();
  const int nb = md.p.n_boundary();
  for (int eta : {0, 8}) {
    const ReducedBasis& cb = basis("cb", eta);
    const ReducedBasis cc = characteristic_constraint(md.bd.stiffness, md.bd.mass, md.p, eta, nb);
    ASSERT_EQ(cc.n_reduced(), eta + nb);
    EXPECT_TRUE(cc.boundary_position.empty());
    const Eigen::MatrixXd k_bb = cb.stiffness.bottomRightCorner(nb, nb);
    const Eigen::MatrixXd m_bb = cb.mass.bottomRightCorner(nb, nb);
    const DenseEigen ref = dense_eigen(k_bb, m_bb);
    const Eigen::VectorXd ref_bound = solve_bounds(ref, norm_inf(k_bb), norm_inf(m_bb));
    const std::pair<double, double> m_ext = extreme_eigenvalues(m_bb);
    const double cond_m = m_ext.second / m_ext.first;
    const Eigen::MatrixXd x = cc.boundary_shapes.cwiseAbs();
    const Eigen::MatrixXd m_abs = x.transpose() * m_bb.cwiseAbs() * x;
    const Eigen::VectorXd x_norm = cc.boundary_shapes.colwise().norm();
    const double k_norm = norm_inf(k_bb);
    double m_ratio = 0.0, off_ratio = 0.0, diag_ratio = 0.0, diag_err = 0.0;
    for (int j = 0; j < nb; ++j)
      for (int i = 0; i < nb; ++i) {
        const double m_bound = nb * eps * cond_m + 2.0 * (eta + nb) * eps * m_abs(i, j);
        const double k_round = nb * eps * k_norm * x_norm(i) * x_norm(j);
        const double mij = cc.mass(eta + i, eta + j);
        const double kij = cc.stiffness(eta + i, eta + j);
        m_ratio = std::max(m_ratio, std::abs(mij - (i == j ? 1.0 : 0.0)) / m_bound);
        if (i != j) {
          off_ratio =
              std::max(off_ratio, std::abs(kij) /
                                      (std::max(ref.values(i), ref.values(j)) * m_bound + k_round));
        } else {
          const double err = std::abs(kij - ref.values(i));
          diag_err = std::max(diag_err, err / ref.values(i));
          diag_ratio =
              std::max(diag_ratio, err / (ref_bound(i) + ref.values(i) * m_bound + k_round));
        }
      }
    std::printf("CC eta = %d, n_c = n_B = %d (cond M^_BB %.3e): M^_cc(B, B) - I %.2e of bound; "
                "K^_cc(B, B) off-diagonal %.2e of bound; diagonal vs dsygvd's lambda_c: max "
                "relative %.3e (%.2e of bound)\n",
                eta, nb, cond_m, m_ratio, off_ratio, diag_err, diag_ratio);
    EXPECT_LE(m_ratio, 1.0);
    EXPECT_LE(off_ratio, 1.0);
    EXPECT_LE(diag_ratio, 1.0);
    // Fewer boundary modes keep the lowest: K^_cc(B, B)'s diagonal is
    // dsygvd's n_c lowest lambda_c (bounds as above).
    const int n_c = 8;
    const ReducedBasis few = characteristic_constraint(md.bd.stiffness, md.bd.mass, md.p, eta, n_c);
    double few_ratio = 0.0;
    for (int i = 0; i < n_c; ++i) {
      const double m_bound = nb * eps * cond_m + 2.0 * (eta + nb) * eps * m_abs(i, i);
      const double k_round = nb * eps * k_norm * x_norm(i) * x_norm(i);
      few_ratio = std::max(few_ratio, std::abs(few.stiffness(eta + i, eta + i) - ref.values(i)) /
                                          (ref_bound(i) + ref.values(i) * m_bound + k_round));
    }
    std::printf("  n_c = %d: K^_cc(B, B)'s diagonal vs dsygvd's lowest %d lambda_c: %.2e of "
                "bound\n",
                n_c, n_c, few_ratio);
    EXPECT_LE(few_ratio, 1.0);
  }
}

// V4, CC: T_cc = T_cb S with S = diag(I, Psi_c). With every boundary mode S is
// square and invertible, the pencils congruent: CC's eigenvalues are CB's.
// With n_c < n_B, span(T_cc) is inside span(T_cb) and inside CC's with more
// boundary modes (the same Psi_c columns, a prefix): Rayleigh-Ritz
// (Courant-Fischer) makes lambda_i(CC, n_c) >= lambda_i(CC, n_c') >=
// lambda_i(CB) >= lambda_i(full) (checked on every eigenvalue against CB, on
// the lowest 10 against fewer boundary modes). Tolerances: the dense solves'
// bounds of the two problems compared and congruence_bounds (the CB matrices
// are common).
// The frequency errors against the full model are printed: CC's accuracy.
TEST_F(ReductionBases, CharacteristicConstraintRayleighRitz) {
  const Model& md = model();
  const int nb = md.p.n_boundary();
  const int eta = 8;
  const int lowest = 10;
  const ReducedBasis& cb = basis("cb", eta);
  const DenseEigen cb_eig = dense_eigen(cb.stiffness, cb.mass);
  const Eigen::VectorXd cb_bound = solve_bounds(cb_eig, norm_inf(cb.stiffness), norm_inf(cb.mass));
  Eigen::VectorXd previous, previous_bound;
  for (int n_c : {2, 4, 8, 16, 32, nb}) {
    const ReducedBasis cc = characteristic_constraint(md.bd.stiffness, md.bd.mass, md.p, eta, n_c);
    ASSERT_EQ(cc.n_reduced(), eta + n_c);
    const DenseEigen e = dense_eigen(cc.stiffness, cc.mass);
    const Eigen::VectorXd bound = solve_bounds(e, norm_inf(cc.stiffness), norm_inf(cc.mass)) +
                                  congruence_bounds(cb, congruence(cc, eta), e);
    double below_cb = -std::numeric_limits<double>::infinity(), equal_cb = 0.0,
           rise = -std::numeric_limits<double>::infinity(), err = 0.0;
    for (int i = 0; i < eta + n_c; ++i)
      below_cb = std::max(below_cb, (cb_eig.values(i) - e.values(i)) / (bound(i) + cb_bound(i)));
    if (n_c == nb)
      for (int i = 0; i < eta + n_c; ++i)
        equal_cb =
            std::max(equal_cb, std::abs(cb_eig.values(i) - e.values(i)) / (bound(i) + cb_bound(i)));
    for (int i = 0; i < std::min(lowest, eta + n_c); ++i) {
      err = std::max(err, std::sqrt(e.values(i) / full().values(i)) - 1.0);
      if (previous.size() > i)
        rise = std::max(rise, (e.values(i) - previous(i)) / (bound(i) + previous_bound(i)));
    }
    std::printf("CC eta = %d, n_c = %2d (r = %2d): lowest %d frequencies max relative error "
                "%.3e vs full; (CB - CC) %.2e of bound%s; rise vs fewer boundary modes %.2e of "
                "bound\n",
                eta, n_c, eta + n_c, std::min(lowest, eta + n_c), err, below_cb,
                n_c == nb ? (", |CB - CC| " + std::to_string(equal_cb) + " of bound").c_str() : "",
                previous.size() > 0 ? rise : 0.0);
    EXPECT_LE(below_cb, 1.0) << "n_c " << n_c << ": below CB's eigenvalues";
    EXPECT_LE(equal_cb, 1.0) << "n_c " << n_c << ": not CB's eigenvalues";
    if (previous.size() > 0) {
      EXPECT_LE(rise, 1.0) << "n_c " << n_c << ": above the eigenvalues with fewer modes";
    }
    previous = e.values;
    previous_bound = bound;
  }
  EXPECT_THROW(characteristic_constraint(md.bd.stiffness, md.bd.mass, md.p, eta, 0),
               ReductionError);
  EXPECT_THROW(characteristic_constraint(md.bd.stiffness, md.bd.mass, md.p, eta, nb + 1),
               ReductionError);
}

} // namespace
} // namespace rsi

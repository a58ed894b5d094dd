// V3 / V4: the reduction bases of the bladed disk (SPEC §3, §4; paper
// eqs. 3-20). Fixed-interface and free modes are orthonormal, the
// Craig-Bampton stiffness is block diagonal, the eta = psi = 0 limits are
// the Guyan condensation (the Schur complement), static tip loads are
// reproduced exactly, and the reduced eigenvalues are Rayleigh-Ritz upper
// bounds that decrease as modes are added. Last, the Craig-Chang-Martinez
// boundary extended to the tip rotations (paper §5.3, Bladh et al. 2003).
//
// Every reference quantity is computed here independently of reduced/:
// dense LAPACKE dsygvd eigenproblems, dense Eigen Cholesky factorizations
// (reduced/ uses CHOLMOD and Spectra's Lanczos).

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <lapacke.h>

#include "bladed_disk.hpp"
#include "craig_bampton.hpp"
#include "craig_chang_martinez.hpp"
#include "guyan.hpp"
#include "partition.hpp"
#include "reduction.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// Infinity norm: an upper bound of the 2-norm of a symmetric matrix.
double norm_inf(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  return a.cwiseAbs().rowwise().sum().maxCoeff();
}

/// All eigenpairs of A x = lambda B x (A, B symmetric, B positive definite),
/// by LAPACKE dsygvd; eigenvectors B-normalised.
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

/// Extreme eigenvalues of a symmetric matrix (Eigen, values only).
std::pair<double, double> extreme_eigenvalues(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  const Eigen::VectorXd w =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, Eigen::EigenvaluesOnly).eigenvalues();
  return {w(0), w(w.size() - 1)};
}

/// Backward-error bound of eigenvalue i of A x = lambda B x solved densely
/// (dsygvd is backward stable: perturbations ~ n eps ||A||, n eps ||B||),
/// plus dA, dB the errors already present in A and B:
/// |d lambda| <= (n eps (||A|| + |lambda| ||B||) + dA + |lambda| dB) ||x||^2, x B-normalised.
Eigen::VectorXd eigenvalue_bounds(const DenseEigen& e, double a_norm, double b_norm, double da,
                                  double db) {
  const int n = static_cast<int>(e.values.size());
  Eigen::VectorXd bound(n);
  for (int i = 0; i < n; ++i) {
    const double lam = std::abs(e.values(i));
    bound(i) = (n * eps * (a_norm + lam * b_norm) + da + lam * db) * e.vectors.col(i).squaredNorm();
  }
  return bound;
}

/// Reduced eigenproblem of a basis with its error bounds: K^, M^ carry the
/// rounding of the products T^T K T, T^T M T, n eps ||K|| ||T||_F^2 (and M).
struct ReducedEigen {
  DenseEigen eig;
  Eigen::VectorXd bound;
};

class ReductionBases : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    bd = new BladedDisk(assemble_bladed_disk(
        load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json")));
    k = new Eigen::MatrixXd(bd->stiffness);
    m = new Eigen::MatrixXd(bd->mass);
    p = new Partition(make_partition(bd->n_dofs(), bd->boundary));
    full = new DenseEigen(dense_eigen(*k, *m));
    k_norm = norm_inf(*k);
    m_norm = norm_inf(*m);
    full_bound = new Eigen::VectorXd(eigenvalue_bounds(*full, k_norm, m_norm, 0.0, 0.0));
    const std::pair<double, double> ek = extreme_eigenvalues(*k);
    cond_k = ek.second / ek.first;
    bases = new std::map<std::pair<std::string, int>, ReducedBasis>();
  }
  static void TearDownTestSuite() {
    delete bases;
    delete full_bound;
    delete full;
    delete p;
    delete m;
    delete k;
    delete bd;
  }

  static const ReducedBasis& basis(const std::string& method, int modes) {
    const std::pair<std::string, int> key{method, modes};
    auto it = bases->find(key);
    if (it == bases->end()) it = bases->emplace(key, reduce_bladed_disk(*bd, method, modes)).first;
    return it->second;
  }

  static ReducedEigen reduced_eigen(const ReducedBasis& b) {
    ReducedEigen out;
    out.eig = dense_eigen(b.stiffness, b.mass);
    const double t_f2 = b.transformation.squaredNorm();
    const int n = bd->n_dofs();
    out.bound = eigenvalue_bounds(out.eig, norm_inf(b.stiffness), norm_inf(b.mass),
                                  n * eps * k_norm * t_f2, n * eps * m_norm * t_f2);
    return out;
  }

  static BladedDisk* bd;
  static Eigen::MatrixXd* k;
  static Eigen::MatrixXd* m;
  static Partition* p;
  static DenseEigen* full;
  static Eigen::VectorXd* full_bound;
  static double k_norm, m_norm, cond_k;
  static std::map<std::pair<std::string, int>, ReducedBasis>* bases;
};
BladedDisk* ReductionBases::bd = nullptr;
Eigen::MatrixXd* ReductionBases::k = nullptr;
Eigen::MatrixXd* ReductionBases::m = nullptr;
Partition* ReductionBases::p = nullptr;
DenseEigen* ReductionBases::full = nullptr;
Eigen::VectorXd* ReductionBases::full_bound = nullptr;
double ReductionBases::k_norm = 0.0;
double ReductionBases::m_norm = 0.0;
double ReductionBases::cond_k = 0.0;
std::map<std::pair<std::string, int>, ReducedBasis>* ReductionBases::bases = nullptr;

// ---------------------------------------------------------------- V3

// V3, Craig-Bampton (paper eqs. 3-7): the first eta columns of T, restricted
// to I, are fixed-interface modes: Phi^T M_II Phi = I, Phi^T K_II Phi =
// diag(omega_i^2) with omega_i^2 the eigenvalues of (K_II, M_II) computed
// here by dense dsygvd; their rows on B are exactly zero; the coupling block
// K^(modal, boundary) = Phi^T (K_II Psi + K_IB) is zero (Psi solves K_II Psi = -K_IB).
TEST_F(ReductionBases, CraigBamptonFixedInterfaceModes) {
  const Eigen::MatrixXd k_ii = take_rows(take_rows(*k, p->interior).transpose(), p->interior);
  const Eigen::MatrixXd m_ii = take_rows(take_rows(*m, p->interior).transpose(), p->interior);
  const DenseEigen fixed = dense_eigen(k_ii, m_ii);
  const int n_i = p->n_interior();
  const double k_ii_norm = norm_inf(k_ii);
  const double m_ii_norm = norm_inf(m_ii);
  const Eigen::VectorXd fixed_bound = eigenvalue_bounds(fixed, k_ii_norm, m_ii_norm, 0.0, 0.0);
  // Lanczos (Spectra, eta < n_I / 4) stops at a relative residual 1e-12 of
  // the shift-inverted operator: eigenvalues are then within 1e-12 relative.
  const double lanczos_tol = 1e-12;
  for (int eta : {88, n_i}) {
    const ReducedBasis& b = basis("cb", eta);
    const Eigen::MatrixXd t_b = take_rows(b.transformation, p->boundary);
    const Eigen::MatrixXd phi = take_rows(b.transformation.leftCols(eta), p->interior);
    const double boundary_rows = t_b.leftCols(eta).cwiseAbs().maxCoeff();
    // The modes are placed on I only: their B rows are exact zeros.
    std::printf("CB eta = %d: max |T(B, modal)| = %.3e (exact 0)\n", eta, boundary_rows);
    EXPECT_EQ(boundary_rows, 0.0);

    const Eigen::VectorXd norm2 = phi.colwise().squaredNorm();
    // Phi^T M_II Phi - I: rounding of the products and of the solver, n eps ||M_II|| |phi_i| |phi_j|.
    const Eigen::MatrixXd mass_error = phi.transpose() * m_ii * phi - Eigen::MatrixXd::Identity(eta, eta);
    const Eigen::MatrixXd k_modal = phi.transpose() * k_ii * phi;
    double worst_m = 0.0, worst_k_off = 0.0, worst_k_diag = 0.0, worst_m_ratio = 0.0,
           worst_off_ratio = 0.0, worst_diag_ratio = 0.0;
    for (int j = 0; j < eta; ++j)
      for (int i = 0; i < eta; ++i) {
        const double cross = std::sqrt(norm2(i) * norm2(j));
        const double m_bound = n_i * eps * m_ii_norm * cross;
        worst_m = std::max(worst_m, std::abs(mass_error(i, j)));
        worst_m_ratio = std::max(worst_m_ratio, std::abs(mass_error(i, j)) / m_bound);
        if (i != j) {
          // K-orthogonality: product rounding n eps ||K_II|| |phi_i| |phi_j| (Lanczos adds
          // only tol^2 lambda_max ~ 6e-13, second order in the residual).
          const double off_bound = n_i * eps * k_ii_norm * cross + lanczos_tol * lanczos_tol * fixed.values(n_i - 1);
          worst_k_off = std::max(worst_k_off, std::abs(k_modal(i, j)));
          worst_off_ratio = std::max(worst_off_ratio, std::abs(k_modal(i, j)) / off_bound);
        } else {
          // omega_i^2: dense backward-error bound of both solves, plus the Lanczos tolerance.
          const double diag_bound = fixed_bound(i) + n_i * eps * (k_ii_norm + fixed.values(i) * m_ii_norm) * norm2(i) +
                                    lanczos_tol * fixed.values(i);
          const double err = std::abs(k_modal(i, i) - fixed.values(i));
          worst_k_diag = std::max(worst_k_diag, err / fixed.values(i));
          worst_diag_ratio = std::max(worst_diag_ratio, err / diag_bound);
        }
      }
    std::printf("  max|Phi^T M_II Phi - I| = %.3e (%.3f of bound)\n", worst_m, worst_m_ratio);
    std::printf("  max|Phi^T K_II Phi off-diagonal| = %.3e (%.3f of bound), relative to omega_1^2: %.3e\n",
                worst_k_off, worst_off_ratio, worst_k_off / fixed.values(0));
    std::printf("  max|phi_i^T K_II phi_i - omega_i^2| / omega_i^2 = %.3e (%.3f of bound)\n", worst_k_diag,
                worst_diag_ratio);
    EXPECT_LE(worst_m_ratio, 1.0);
    EXPECT_LE(worst_off_ratio, 1.0);
    EXPECT_LE(worst_diag_ratio, 1.0);

    // Reduced stiffness blocks (as stored in the basis).
    const Eigen::MatrixXd k_mb = b.stiffness.block(0, eta, eta, p->n_boundary());
    const Eigen::MatrixXd k_mm = b.stiffness.topLeftCorner(eta, eta);
    const Eigen::MatrixXd m_mm = b.mass.topLeftCorner(eta, eta);
    const double k_hat_norm = norm_inf(b.stiffness);
    // K^(modal, B) = Phi^T (K_II Psi + K_IB): zero up to the Cholesky residual of Psi and
    // the rounding of T^T K T, each <= n eps ||K|| |phi_i| |T e_b|: bound 2 n eps ||K|| |phi_i| |T e_b|.
    const Eigen::VectorXd t_col = b.transformation.colwise().norm();
    double worst_mb = 0.0, worst_mb_ratio = 0.0;
    for (int j = 0; j < p->n_boundary(); ++j)
      for (int i = 0; i < eta; ++i) {
        const double bound = 2.0 * bd->n_dofs() * eps * k_norm * t_col(i) * t_col(eta + j);
        worst_mb = std::max(worst_mb, std::abs(k_mb(i, j)));
        worst_mb_ratio = std::max(worst_mb_ratio, std::abs(k_mb(i, j)) / bound);
      }
    const double mm_diag = (k_mm.diagonal() - fixed.values.head(eta)).cwiseQuotient(fixed.values.head(eta)).cwiseAbs().maxCoeff();
    const double mm_off = (k_mm - Eigen::MatrixXd(k_mm.diagonal().asDiagonal())).cwiseAbs().maxCoeff();
    const double m_err = (m_mm - Eigen::MatrixXd::Identity(eta, eta)).cwiseAbs().maxCoeff();
    std::printf("  K^(modal,B): max %.3e, / ||K^|| = %.3e (%.3f of bound 2 n eps ||K|| |t_i| |t_b|)\n", worst_mb,
                worst_mb / k_hat_norm, worst_mb_ratio);
    std::printf("  K^(modal,modal): max rel diag error %.3e, max off-diagonal %.3e (/||K^|| %.3e); "
                "M^(modal,modal) - I: %.3e\n",
                mm_diag, mm_off, mm_off / k_hat_norm, m_err);
    EXPECT_LE(worst_mb_ratio, 1.0);
  }
}

// Explore CCM.
TEST_F(ReductionBases, ExploreCcm) {
  const int n = bd->n_dofs();
  const int nb = p->n_boundary();
  for (int psi : {10, 44, 88, 200, 400}) {
    const ReducedBasis& b = basis("ccm", psi);
    const Eigen::MatrixXd a = b.transformation.leftCols(nb);
    const Eigen::MatrixXd t_m = b.transformation.rightCols(psi);
    const Eigen::MatrixXd x = b.mass.topLeftCorner(nb, nb).ldlt().solve(b.mass.block(0, nb, nb, psi));
    const Eigen::MatrixXd phi = t_m - a * x;
    const Eigen::MatrixXd mm = phi.transpose() * *m * phi - Eigen::MatrixXd::Identity(psi, psi);
    const Eigen::MatrixXd kk = phi.transpose() * *k * phi;
    const Eigen::MatrixXd ka = phi.transpose() * *k * a;
    double diag = 0.0;
    for (int i = 0; i < psi; ++i) diag = std::max(diag, std::abs(kk(i, i) - full->values(i)) / full->values(i));
    const double off = (kk - Eigen::MatrixXd(kk.diagonal().asDiagonal())).cwiseAbs().maxCoeff();
    // compare X with Phi_1B from lowest modes
    const Modes fm = lowest_modes(bd->stiffness, bd->mass, psi, few_modes(psi, n));
    const double phib = (fm.shapes - phi).cwiseAbs().maxCoeff();
    std::printf("CCM psi %d: |Phi^T M Phi - I| %.3e, rel diag %.3e, off %.3e, |Phi^T K A| %.3e (||K^|| %.3e) vs lowest_modes %.3e max|phi| %.3e\n",
                psi, mm.cwiseAbs().maxCoeff(), diag, off, ka.cwiseAbs().maxCoeff(), norm_inf(b.stiffness), phib, fm.shapes.cwiseAbs().maxCoeff());
  }
}
// TESTS_END
} // namespace
} // namespace rsi

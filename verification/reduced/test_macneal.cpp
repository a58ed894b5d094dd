// MacNeal's method (reduced/bases/macneal.hpp; SPEC §8; MacNeal 1971 as the
// 'MCN' basis of NLvib / NLstep, Monjaraz-Tec, Gross, Krack, Comput. Struct.
// 260 (2022) 106698) on the paper's bladed disk, boundary = the 44 tip u, v.
//
// What must hold, from the derivation in macneal.hpp:
// - M^ = diag(0_B, I_psi): boundary block and coupling exactly zero;
// - T is Craig-Chang-Martinez's T for the same psi, K^ = T^T K T;
// - the finite eigenvalues of (K^, M^) are omega_1^2 .. omega_psi^2 of the
//   full model (static condensation of the massless boundary leaves
//   Omega_1^2), so omega_max = omega_psi and the critical step 2/omega_psi;
// - K^ condensed onto u_B is ((K^-1)_BB)^-1: static boundary loads exact.
//
// The references are computed here, independently of reduced/: the full
// eigenvalues by a dense LAPACKE dsygvd, K^-1 by a dense Eigen Cholesky,
// and the finite eigenvalues a second way, without condensation, from the
// inverted pencil M^ x = mu K^ x (K^ positive definite: a symmetric-definite
// problem whose infinite eigenvalues become mu = 0). Tolerances are
// first-order round-off bounds (n eps times norms or condition numbers, the
// convention of test_reduction_bases), printed with the measured errors.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
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
#include "craig_chang_martinez.hpp"
#include "critical_step.hpp"
#include "dense_norms.hpp"
#include "macneal.hpp"
#include "partition.hpp"
#include "reduced_run.hpp"
#include "reduction.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
/// Spectra's relative tolerance in lowest_modes (modal_analysis.cpp): the
/// free modes of CCM / MacNeal come from it when 4 psi < n.
constexpr double lanczos_tol = 1e-12;

/// All eigenpairs of A x = lambda B x (B positive definite) by LAPACKE
/// dsygvd, B-normalised, ascending.
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

/// Backward error of each eigenvalue of dense_eigen (dsygvd backward stable):
/// n eps (||A|| + |lambda_i| ||B||) ||x_i||^2.
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
  Eigen::MatrixXd k, m;  ///< dense K, M
  Eigen::MatrixXd k_abs; ///< |K|
  double k_norm = 0.0, m_norm = 0.0;
  Eigen::LLT<Eigen::MatrixXd> k_llt; ///< dense Cholesky of K
  DenseEigen full;                   ///< every mode (dsygvd)
  Eigen::VectorXd full_bound;
  double cond_k = 0.0;

  int n() const { return bd.n_dofs(); }
};

const std::vector<int> mode_counts{1, 10, 44, 88, 200};

class MacNeal : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    auto md = std::make_unique<Model>();
    md->bd = assemble_bladed_disk(
        load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json"));
    md->p = make_partition(md->n(), md->bd.boundary);
    md->k = Eigen::MatrixXd(md->bd.stiffness);
    md->m = Eigen::MatrixXd(md->bd.mass);
    md->k_abs = md->k.cwiseAbs();
    md->k_norm = norm_inf(md->k);
    md->m_norm = norm_inf(md->m);
    md->k_llt.compute(md->k);
    ASSERT_EQ(md->k_llt.info(), Eigen::Success) << "dense Cholesky of K";
    md->full = dense_eigen(md->k, md->m);
    md->full_bound = solve_bounds(md->full, md->k_norm, md->m_norm);
    const std::pair<double, double> ek = extreme_eigenvalues(md->k);
    md->cond_k = ek.second / ek.first;
    std::printf("bladed disk: n = %d, n_B = %d, ||K||_inf = %.3e, ||M||_inf = %.3e, cond_2(K) = "
                "%.3e; full omega_1 = %.6e, omega_max = %.6e rad/s\n",
                md->n(), md->p.n_boundary(), md->k_norm, md->m_norm, md->cond_k,
                std::sqrt(md->full.values(0)), std::sqrt(md->full.values(md->n() - 1)));
    s_model = std::move(md);
    s_bases = std::make_unique<std::map<std::pair<std::string, int>, ReducedBasis>>();
  }
  static void TearDownTestSuite() {
    s_bases.reset();
    s_model.reset();
  }

  static const Model& model() { return *s_model; }

  /// reduce_bladed_disk, once per (method, modes).
  static const ReducedBasis& basis(const std::string& method, int modes) {
    const std::pair<std::string, int> key{method, modes};
    auto it = s_bases->find(key);
    if (it == s_bases->end())
      it = s_bases->emplace(key, reduce_bladed_disk(model().bd, method, modes)).first;
    return it->second;
  }

  static std::unique_ptr<Model> s_model;
  static std::unique_ptr<std::map<std::pair<std::string, int>, ReducedBasis>> s_bases;
};
std::unique_ptr<Model> MacNeal::s_model;
std::unique_ptr<std::map<std::pair<std::string, int>, ReducedBasis>> MacNeal::s_bases;

/// The modal coordinates of q (not boundary ones).
std::vector<int> modal_positions(const ReducedBasis& b) {
  std::vector<int> out;
  for (int i = 0; i < b.n_reduced(); ++i)
    if (std::find(b.boundary_position.begin(), b.boundary_position.end(), i) ==
        b.boundary_position.end())
      out.push_back(i);
  return out;
}

// macneal.hpp: M^ = diag(0_B, I_psi) is set, not computed: the boundary
// block, the coupling and the modal block minus I are exact zeros. The
// coordinates are CCM's, q = (q_B, u_1), boundary first.
TEST_F(MacNeal, BoundaryMassBlockAndCouplingExactlyZero) {
  const int nb = model().p.n_boundary();
  for (int psi : mode_counts) {
    const ReducedBasis& b = basis("macneal", psi);
    const std::vector<int> o = modal_positions(b);
    const double m_bb =
        dense_block(b.mass, b.boundary_position, b.boundary_position).cwiseAbs().maxCoeff();
    const double m_bo = dense_block(b.mass, b.boundary_position, o).cwiseAbs().maxCoeff();
    const double m_ob = dense_block(b.mass, o, b.boundary_position).cwiseAbs().maxCoeff();
    const double m_oo =
        (dense_block(b.mass, o, o) - Eigen::MatrixXd::Identity(psi, psi)).cwiseAbs().maxCoeff();
    std::printf("MacNeal psi = %3d: r = %d; max|M^_BB| = %.1e, max|M^_Bq| = %.1e, max|M^_qB| = "
                "%.1e, max|M^_qq - I| = %.1e (all exact 0); massless_boundary %d\n",
                psi, b.n_reduced(), m_bb, m_bo, m_ob, m_oo, b.massless_boundary);
    ASSERT_EQ(b.n_reduced(), nb + psi);
    for (int i = 0; i < nb; ++i)
      ASSERT_EQ(b.boundary_position[i], i);
    EXPECT_TRUE(b.massless_boundary);
    EXPECT_EQ(m_bb, 0.0);
    EXPECT_EQ(m_bo, 0.0);
    EXPECT_EQ(m_ob, 0.0);
    EXPECT_EQ(m_oo, 0.0);
  }
}

// macneal.hpp: T is CCM's (the same residual_flexibility_transformation,
// deterministic): identical bits, the same K^ (finish_basis on the same T),
// the same cond(R_B). And K^ = T^T K T recomputed here with the dense K,
// to the rounding of both products: 2 n eps (|T|^T |K| |T|)_ij.
TEST_F(MacNeal, TransformationIsCraigChangMartinezAndStiffnessIsTransformedK) {
  const Model& md = model();
  const int n = md.n();
  for (int psi : mode_counts) {
    const ReducedBasis& b = basis("macneal", psi);
    const ReducedBasis& ccm = basis("ccm", psi);
    const double dt = (b.transformation - ccm.transformation).cwiseAbs().maxCoeff();
    const double dk = (b.stiffness - ccm.stiffness).cwiseAbs().maxCoeff();
    const Eigen::MatrixXd ktk = b.transformation.transpose() * md.k * b.transformation;
    const Eigen::MatrixXd t_abs = b.transformation.cwiseAbs();
    const Eigen::MatrixXd bound = 2.0 * n * eps * t_abs.transpose() * md.k_abs * t_abs;
    const Eigen::MatrixXd err = (b.stiffness - ktk).cwiseAbs();
    const double ratio = err.cwiseQuotient(bound).maxCoeff();
    std::printf("MacNeal psi = %3d vs CCM psi = %3d: max|dT| = %.1e, max|dK^| = %.1e (exact 0), "
                "cond(R_B) %.6e vs %.6e; K^ vs T^T K T: max %.3e = %.3e ||K^|| (%.2e of bound)\n",
                psi, psi, dt, dk, b.cond_rb, ccm.cond_rb, err.maxCoeff(),
                err.maxCoeff() / norm_inf(b.stiffness), ratio);
    EXPECT_EQ(dt, 0.0);
    EXPECT_EQ(dk, 0.0);
    EXPECT_EQ(b.cond_rb, ccm.cond_rb);
    EXPECT_LE(ratio, 1.0);
  }
}

// macneal.hpp and craig_chang_martinez.hpp: one pool for several bases
// (test_component_rows builds the full modes, CCM(0), CCM(psi) and
// MacNeal(psi) of a large model from one). The pool of psi modes, every one
// kept, is what the count-based builder computes: the same bits. Keeping
// none of a pool of 20 leaves R = K^-1 E_B, the flexibility the count-based
// CCM(0) computes by the same refined solve (both pools take the Lanczos
// path here, 4 x 20 < n): the same bits as CCM(0).
TEST_F(MacNeal, PoolBuildsTheCountBasedBases) {
  const Model& md = model();
  const Eigen::SparseMatrix<double>& k = md.bd.stiffness;
  const Eigen::SparseMatrix<double>& m = md.bd.mass;
  const int psi = 20;
  const FreeInterfacePool pool = free_interface_pool(k, m, md.p, psi, "pool");
  ASSERT_FALSE(pool.complete); // the Lanczos path, as on the 3D models
  std::vector<int> all(psi);
  std::iota(all.begin(), all.end(), 0);
  const auto now = std::chrono::steady_clock::now();
  const ReducedBasis mcn = macneal(k, m, md.p, pool, all, now);
  const ReducedBasis ccm = craig_chang_martinez(k, m, md.p, pool, all, now);
  const ReducedBasis ccm0 = craig_chang_martinez(k, m, md.p, pool, {}, now);
  const auto max_diff = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return a.rows() == b.rows() && a.cols() == b.cols() ? (a - b).cwiseAbs().maxCoeff()
                                                        : std::numeric_limits<double>::infinity();
  };
  const double d_mcn_t = max_diff(mcn.transformation, basis("macneal", psi).transformation);
  const double d_mcn_k = max_diff(mcn.stiffness, basis("macneal", psi).stiffness);
  const double d_mcn_m = max_diff(mcn.mass, basis("macneal", psi).mass);
  const double d_ccm_t = max_diff(ccm.transformation, basis("ccm", psi).transformation);
  const double d_ccm_m = max_diff(ccm.mass, basis("ccm", psi).mass);
  const double d_ccm0_t = max_diff(ccm0.transformation, basis("ccm", 0).transformation);
  const double d_ccm0_k = max_diff(ccm0.stiffness, basis("ccm", 0).stiffness);
  std::printf("pool of %d: MacNeal-%d max|dT| %.1e, |dK^| %.1e, |dM^| %.1e; CCM-%d |dT| %.1e, "
              "|dM^| %.1e; none kept vs CCM(0) |dT| %.1e, |dK^| %.1e (all exact 0)\n",
              psi, psi, d_mcn_t, d_mcn_k, d_mcn_m, psi, d_ccm_t, d_ccm_m, d_ccm0_t, d_ccm0_k);
  EXPECT_EQ(d_mcn_t, 0.0);
  EXPECT_EQ(d_mcn_k, 0.0);
  EXPECT_EQ(d_mcn_m, 0.0);
  EXPECT_EQ(d_ccm_t, 0.0);
  EXPECT_EQ(d_ccm_m, 0.0);
  EXPECT_EQ(d_ccm0_t, 0.0);
  EXPECT_EQ(d_ccm0_k, 0.0);
  EXPECT_EQ(mcn.mode_index, all);
  EXPECT_TRUE(mcn.massless_boundary);
  EXPECT_THROW(macneal(k, m, md.p, pool, {}, now), ReductionError); // psi >= 1
}

// macneal.hpp: the finite eigenvalues of (K^, M^) are the lowest psi full
// ones. Two evaluations against the dense full solve:
// (a) reduced_eigenvalues (critical_step.hpp: massless boundary condensed,
//     then a dense solve), what the suite reports;
// (b) here, without condensation: M^ x = mu K^ x (dsygvd, K^ positive
//     definite), omega^2 = 1/mu for the psi nonzero mu, the n_B others zero.
// Bound of (a) for eigenvalue i, with z_i the reduced eigenvector (M^-normalised,
// T z_i = phi_i; from (b)), first order:
//   n eps (|T||z_i|)^T |K| (|T||z_i|)            rounding of K^ = T^T K T
//   + n_B eps cond(K^_BB) |z_iB|^T |K^_BB| |z_iB|  the condensation's solve
//   + psi eps ||K_c||                            its dense eigensolve
//   + lanczos_tol omega_i^2 (4 psi < n)           the kept free modes' accuracy,
//     or the dense bound again (the dense path of CCM: all modes by dsygvd)
//   + the full dense bound n eps (||K|| + w2 ||M||) ||phi_i||^2.
// Bound of (b) against (a): dsygvd on (M^, K^), |dmu| <= r eps (||M^|| +
// mu ||K^||) ||x||^2 with x K^-normalised, relative |dmu| / mu, plus the
// condensation's own two terms.
struct FiniteEigen {
  Eigen::VectorXd values;                 ///< reduced_eigenvalues (a)
  Eigen::VectorXd bound;                  ///< of |(a)_i - full_i|
  Eigen::VectorXd inverse_values;         ///< 1/mu (b), ascending
  Eigen::VectorXd inverse_bound;          ///< of |(b)_i - (a)_i|
  double zero_mu = 0.0, zero_ratio = 0.0; ///< the n_B mu = 0: max |mu|, ratio to its bound
};

FiniteEigen finite_eigen(const Model& md, const ReducedBasis& b) {
  const int n = md.n();
  const int nb = md.p.n_boundary();
  const int psi = b.n_modes;
  const int r = b.n_reduced();
  FiniteEigen out;
  out.values = reduced_eigenvalues(b);
  if (out.values.size() != psi) throw std::runtime_error("not one finite eigenvalue per mode");
  const DenseEigen inv = dense_eigen(b.mass, b.stiffness);
  const Eigen::VectorXd inv_bound = solve_bounds(inv, norm_inf(b.mass), norm_inf(b.stiffness));
  for (int i = 0; i < nb; ++i) {
    out.zero_mu = std::max(out.zero_mu, std::abs(inv.values(i)));
    out.zero_ratio = std::max(out.zero_ratio, std::abs(inv.values(i)) / inv_bound(i));
  }
  const std::vector<int> o = modal_positions(b);
  const Eigen::MatrixXd k_bb = dense_block(b.stiffness, b.boundary_position, b.boundary_position);
  const std::pair<double, double> ebb = extreme_eigenvalues(k_bb);
  const double cond_bb = ebb.second / ebb.first;
  const Eigen::MatrixXd k_c =
      dense_block(b.stiffness, o, o) -
      dense_block(b.stiffness, o, b.boundary_position) *
          k_bb.llt().solve(dense_block(b.stiffness, b.boundary_position, o));
  const double kc_norm = norm_inf(k_c);
  const bool lanczos = 4 * psi < n;
  out.bound.resize(psi);
  out.inverse_values.resize(psi);
  out.inverse_bound.resize(psi);
  for (int i = 0; i < psi; ++i) {
    const int j = r - 1 - i; // mu descending = omega^2 ascending
    const double mu = inv.values(j);
    const Eigen::VectorXd z = inv.vectors.col(j) / std::sqrt(mu); // M^-normalised
    const Eigen::VectorXd z_b = z.head(nb);
    const Eigen::VectorXd tz = b.transformation.cwiseAbs() * z.cwiseAbs();
    const double condensation =
        nb * eps * cond_bb * z_b.cwiseAbs().dot(k_bb.cwiseAbs() * z_b.cwiseAbs()) +
        psi * eps * kc_norm;
    const double w2 = md.full.values(i);
    out.bound(i) = n * eps * tz.dot(md.k_abs * tz) + condensation +
                   (lanczos ? lanczos_tol * w2 : md.full_bound(i)) + md.full_bound(i);
    out.inverse_values(i) = 1.0 / mu;
    out.inverse_bound(i) = inv_bound(j) / mu * out.values(i) + condensation;
  }
  return out;
}

/// Bound of the largest eigenvalue of a dense reduced solve (K^, M^ positive
/// definite): r eps (||K^|| + w2 ||M^||) ||x||^2 (dsygvd) + n eps ((|T||x|)^T
/// |K| (|T||x|) + w2 (|T||x|)^T |M| (|T||x|)) (forming K^, M^).
std::pair<double, double> reduced_top(const Model& md, const ReducedBasis& b) {
  const int r = b.n_reduced();
  const DenseEigen e = dense_eigen(b.stiffness, b.mass);
  const double w2 = e.values(r - 1);
  const Eigen::VectorXd x = e.vectors.col(r - 1);
  const Eigen::VectorXd tx = b.transformation.cwiseAbs() * x.cwiseAbs();
  const double bound = r * eps * (norm_inf(b.stiffness) + w2 * norm_inf(b.mass)) * x.squaredNorm() +
                       md.n() * eps * (tx.dot(md.k_abs * tx) + w2 * tx.dot(md.m.cwiseAbs() * tx));
  return {w2, bound};
}

TEST_F(MacNeal, FiniteEigenvaluesAreTheLowestFullOnes) {
  const Model& md = model();
  const int nb = md.p.n_boundary();
  for (int psi : mode_counts) {
    const FiniteEigen f = finite_eigen(md, basis("macneal", psi));
    double err_a = 0.0, ratio_a = 0.0, err_b = 0.0, ratio_b = 0.0;
    for (int i = 0; i < psi; ++i) {
      const double e_a = std::abs(f.values(i) - md.full.values(i));
      err_a = std::max(err_a, e_a / md.full.values(i));
      ratio_a = std::max(ratio_a, e_a / f.bound(i));
      const double e_b = std::abs(f.inverse_values(i) - f.values(i));
      err_b = std::max(err_b, e_b / f.values(i));
      ratio_b = std::max(ratio_b, e_b / f.inverse_bound(i));
    }
    std::printf("MacNeal psi = %3d: %d finite eigenvalues (condensed) vs the lowest %d full ones: "
                "max relative error %.3e (%.2e of bound); vs the inverted pencil M^ x = mu K^ x: "
                "%.3e (%.2e of bound); its %d zero mu: max |mu| %.3e (%.2e of bound)\n",
                psi, static_cast<int>(f.values.size()), psi, err_a, ratio_a, err_b, ratio_b, nb,
                f.zero_mu, f.zero_ratio);
    EXPECT_LE(ratio_a, 1.0);
    EXPECT_LE(ratio_b, 1.0);
    EXPECT_LE(f.zero_ratio, 1.0);
  }
}

// macneal.hpp: K^ statically condensed onto u_B (the modal coordinates
// eliminated) is ((K^-1)_BB)^-1, the full model's boundary stiffness, so
// any boundary load gets the full static response (K^ and T are CCM's;
// test_reduction_bases checks CCM the same way).
// - S G - I, G = (K^-1)_BB by the dense Cholesky of K: both S^-1 and G are
//   backward-stable solutions of K u = e_b (relative 2 n eps cond(K) + n_B
//   eps cond(R_B), the CCM bound), and S G - I = S (G - S^-1) amplifies by
//   cond(G) = cond(S); forming S adds n_B eps cond(S).
// - T K^-1 T^T f against K^-1 f for a random tip load (fixed seed): the
//   bound 2 n eps cond(K) + n_B eps cond(R_B) of test_reduction_bases.
TEST_F(MacNeal, StaticBoundaryResponseExact) {
  const Model& md = model();
  const int n = md.n();
  const int nb = md.p.n_boundary();
  const Eigen::MatrixXd g =
      take_rows(md.k_llt.solve(place_rows(n, md.p.boundary, Eigen::MatrixXd::Identity(nb, nb))),
                md.p.boundary);
  const std::pair<double, double> eg = extreme_eigenvalues(g);
  const double cond_g = eg.second / eg.first;
  std::mt19937 generator(2022);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd f_b(nb);
  for (int i = 0; i < nb; ++i)
    f_b(i) = 1000.0 * uniform(generator); // [N]
  const Eigen::VectorXd f = place_rows(n, md.p.boundary, f_b);
  const Eigen::VectorXd u = md.k_llt.solve(f);
  std::printf("cond_2(G = (K^-1)_BB) = %.3e\n", cond_g);
  for (int psi : mode_counts) {
    const ReducedBasis& b = basis("macneal", psi);
    const std::vector<int> o = modal_positions(b);
    const Eigen::MatrixXd k_oo = dense_block(b.stiffness, o, o);
    const Eigen::MatrixXd k_ob = dense_block(b.stiffness, o, b.boundary_position);
    const Eigen::LLT<Eigen::MatrixXd> k_oo_llt(k_oo);
    ASSERT_EQ(k_oo_llt.info(), Eigen::Success);
    const Eigen::MatrixXd s = dense_block(b.stiffness, b.boundary_position, b.boundary_position) -
                              k_ob.transpose() * k_oo_llt.solve(k_ob);
    const std::pair<double, double> es = extreme_eigenvalues(s);
    const double static_bound = 2.0 * n * eps * md.cond_k + nb * eps * b.cond_rb;
    const double s_err = norm2(s * g - Eigen::MatrixXd::Identity(nb, nb));
    const double s_bound = cond_g * (static_bound + nb * eps * es.second / es.first);

    const Eigen::LLT<Eigen::MatrixXd> k_hat(b.stiffness);
    ASSERT_EQ(k_hat.info(), Eigen::Success) << "K^ positive definite";
    const Eigen::VectorXd u_red = b.transformation * k_hat.solve(b.transformation.transpose() * f);
    const double u_err = (u_red - u).norm() / u.norm();
    std::printf("MacNeal psi = %3d: ||S G - I||_2 = %.3e (%.2e of bound %.3e); static tip load "
                "||T q - K^-1 f|| / ||K^-1 f|| = %.3e (%.2e of bound %.3e)\n",
                psi, s_err, s_err / s_bound, s_bound, u_err, u_err / static_bound, static_bound);
    EXPECT_LE(s_err, s_bound);
    EXPECT_LE(u_err, static_bound);
  }
}

// macneal.hpp / SPEC §8: the stable step of MacNeal is set by the kept free
// modes, 2/omega_psi. reduced_omega_max (critical_step.hpp, used by rsi
// reduce and run_reduced) against omega_psi of the dense full solve: first
// order |d omega| / omega = |d w2| / (2 w2), with |d w2| the bound of the top
// finite eigenvalue above. Printed with CB's and CCM's reduced omega_max at
// the same mode count. CCM's basis contains Phi_1, so its largest eigenvalue
// is at least the largest Rayleigh quotient there, omega_psi^2
// (Courant-Fischer): MacNeal's step is never shorter than CCM's, to the sum
// of both eigenvalue bounds.
TEST_F(MacNeal, CriticalStepIsTwoOverOmegaPsi) {
  const Model& md = model();
  std::printf("  psi | omega_psi (full) | MacNeal omega_max | rel. diff (of bound) | CCM omega_max "
              "| CB omega_max [rad/s] | critical steps MacNeal / CCM / CB [s]\n");
  for (int psi : mode_counts) {
    const ReducedBasis& b = basis("macneal", psi);
    const double w2_psi = md.full.values(psi - 1);
    const double omega_psi = std::sqrt(w2_psi);
    const double mcn = reduced_omega_max(b);
    const double ccm = reduced_omega_max(basis("ccm", psi));
    const double cb = reduced_omega_max(basis("cb", psi));
    const double top_bound = finite_eigen(md, b).bound(psi - 1);
    const double rel = std::abs(mcn - omega_psi) / omega_psi;
    const double rel_bound = 0.5 * top_bound / w2_psi;
    const std::pair<double, double> ccm_top = reduced_top(md, basis("ccm", psi));
    const double ccm_excess = mcn * mcn - ccm_top.first;
    std::printf("  %3d | %.9e | %.9e | %.2e (%.2e) | %.6e | %.6e | %.4e / %.4e / %.4e\n", psi,
                omega_psi, mcn, rel, rel / rel_bound, ccm, cb, 2.0 / mcn, 2.0 / ccm, 2.0 / cb);
    EXPECT_LE(rel, rel_bound);
    EXPECT_LE(ccm_excess, top_bound + ccm_top.second) << "MacNeal omega_max above CCM's";
  }
}

// macneal.hpp: valid range 1 <= psi <= n - n_B, ReductionError otherwise;
// run_reduced refuses a massless boundary (its integrator inverts M^).
TEST_F(MacNeal, RefusesOutOfRangeModesAndExplicitRuns) {
  const Model& md = model();
  for (int psi : {0, -1, md.n() - md.p.n_boundary() + 1}) {
    try {
      (void)macneal(md.bd.stiffness, md.bd.mass, md.p, psi);
      ADD_FAILURE() << "psi = " << psi << " accepted";
    } catch (const ReductionError& e) {
      std::printf("psi = %d refused: %s\n", psi, e.what());
      EXPECT_NE(std::string(e.what()).find("MacNeal takes 1 to 638"), std::string::npos);
    }
  }
  const Case c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
  try {
    (void)run_reduced(c, basis("macneal", 10), {});
    ADD_FAILURE() << "a massless boundary was integrated explicitly";
  } catch (const ReductionError& e) {
    std::printf("run_reduced refused: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("massless boundary"), std::string::npos);
  }
}

} // namespace
} // namespace rsi

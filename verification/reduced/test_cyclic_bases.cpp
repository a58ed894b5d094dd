// Bases of a cyclic component by its turns (reduced/bases/cyclic_symmetry.hpp,
// turned_constraint_modes.hpp, turned_residual_flexibility.hpp; issue 27's
// bases of the default disk), on the
// 3D bladed disk's CI model (data/cases/bladed-disk3d-ci.json: 6 sectors,
// 29,484 dofs, 288 boundary dofs; gmsh + ccx, cached in RSI_CCX_CACHE,
// default build/ccx-cache). Skipped, saying why, without gmsh or ccx.
//
// What is checked against what (u = 2^-53, the unit roundoff):
// - the turn: the boundary in 16 orbits (one blade's tip nodes) of 6, and
//   P^T K P - K, P^T M P - M the model's rounding only: below 1e-8 of
//   max |K|, |M| (ccx integrates each sector's elements at coordinates
//   turned in floating point; a model that is not cyclic gives O(1)), so
//   that the bounds below, which carry them, stay far below the entries;
// - the turned constraint modes solve the static problem K_II psi + K_IB e
//   = 0: the residual (compensated, accurate_solve.hpp) of boundary dof
//   (t, c), t = P^k r, is sum_d R_cd P^k (K phi_d + E_k phi_d) on the
//   interior rows, E_k = P^kT K P^k - K, phi_d the representative's field
//   solved to the last bit (|K phi_d|_I <= a few u |K| |phi_d|): bounded by
//   sum_d |R_cd| |P^k| (|E_k| |phi_d| + gamma |K| |phi_d|), gamma = (m + 10) u,
//   m the most nonzeros of a row of K (the residual's products), plus the
//   turn's 3-term sums' rounding 3 u |K| |P^k| |phi_d|;
// - K^ and M^ by the turns equal the direct products T^T A T of the same T:
//   the block of boundary triples (t, t') is R^k (T^T A T)_(r, P^-k t')
//   R^kT, exact for P^kT A P^k = A and T's turned columns exactly turned;
//   the difference is R^k Psi_r^T E_k Psi_t'' R^kT, entrywise at most
//   |R^k| |Psi_r|^T |E_k| |Psi_t''| |R^k|^T (rigorous), plus rounding taken
//   to first order: both products' n-term sums, gamma_n |T|^T |A| |T| at
//   (t, t') and |R^k| gamma_n (|T|^T |A| |T|)_(r, t'') |R^k|^T, and the turned
//   columns' 3-term sums, 12 u |T|^T |A| |T| (gamma_n = (n + m + 12) u is
//   itself some 3e4 times a typical sum's rounding); the rows of the
//   fixed-interface modes are the same product, and the boundary's columns
//   against them its transpose (the direct product's asymmetry, within
//   gamma_n). The basis as built (its halves averaged) is checked the same
//   way: half the bound at (i, j) and at (j, i), and the direct product's
//   own asymmetry;
// - CCM and MacNeal by the turns: the rows of reduction_rows.hpp and the
//   expansion's bound (ResidualFlexibilityBasesPassTheRows, its comment).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "accurate_solve.hpp"
#include "calculix_matrices.hpp"
#include "calculix_run.hpp"
#include "child_process.hpp"
#include "component_case.hpp"
#include "craig_bampton.hpp"
#include "craig_chang_martinez.hpp"
#include "cyclic_symmetry.hpp"
#include "macneal.hpp"
#include "partition.hpp"
#include "reduction.hpp"
#include "reduction_rows.hpp"
#include "turned_constraint_modes.hpp"
#include "turned_residual_flexibility.hpp"

namespace rsi {
namespace {

constexpr double u = std::numeric_limits<double>::epsilon() / 2;
const std::string ci_case = RSI_SOURCE_DIR "/data/cases/bladed-disk3d-ci.json";

std::string cache_dir() {
  const char* env = std::getenv("RSI_CCX_CACHE");
  return env && *env ? env : RSI_BINARY_DIR "/ccx-cache";
}

std::string missing() {
  if (!executable_on_path("gmsh")) return "gmsh is not on PATH (Debian package gmsh)";
  try {
    find_ccx();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

ComponentCase ci_component_case() {
  std::ifstream in(ci_case);
  return parse_component_case(nlohmann::json::parse(in), ci_case);
}

Eigen::SparseMatrix<double> absolute(const Eigen::SparseMatrix<double>& a) {
  return a.cwiseAbs();
}

/// Most nonzeros of a column of the symmetric a.
int widest(const Eigen::SparseMatrix<double>& a) {
  int m = 0;
  for (int j = 0; j < a.outerSize(); ++j)
    m = std::max(m, static_cast<int>(a.outerIndexPtr()[j + 1] - a.outerIndexPtr()[j]));
  return m;
}

/// P^kT A P^k - A.
Eigen::SparseMatrix<double> turned_difference(const CyclicSymmetry& s, int k,
                                              const Eigen::SparseMatrix<double>& a) {
  const Eigen::SparseMatrix<double> p = turn_matrix(s, k, static_cast<int>(a.rows()));
  return Eigen::SparseMatrix<double>(p.transpose() * a * p) - a;
}

class CyclicBases : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    s_missing = missing();
    if (!s_missing.empty()) return;
    try {
      ComponentCase cc = ci_component_case();
      s_model = std::make_unique<Component>(load_component(cc, {"", cache_dir()}));
      s_partition =
          std::make_unique<Partition>(make_partition(s_model->n_dofs(), s_model->boundary));
      s_cyclic = std::make_unique<CyclicBoundary>(
          cyclic_boundary(*s_model, cc.gmsh_bladed_disk.sectors, *s_partition));
      s_basis = std::make_unique<ReducedBasis>(
          craig_bampton(s_model->stiffness, s_model->mass, *s_partition, 20, s_cyclic.get()));
    } catch (const std::exception& e) {
      s_error = e.what();
    }
  }
  static void TearDownTestSuite() {
    s_basis.reset();
    s_cyclic.reset();
    s_partition.reset();
    s_model.reset();
  }
  void SetUp() override {
    if (!s_missing.empty()) GTEST_SKIP() << "not run: " << s_missing;
    ASSERT_TRUE(s_basis) << "building the cyclic basis failed: " << s_error;
  }
  static inline std::string s_missing;
  static inline std::string s_error;
  static inline std::unique_ptr<Component> s_model;
  static inline std::unique_ptr<Partition> s_partition;
  static inline std::unique_ptr<CyclicBoundary> s_cyclic;
  static inline std::unique_ptr<ReducedBasis> s_basis;
};

// The turn (a permutation of the nodes with dofs, N turns the identity:
// cyclic_symmetry refuses anything else) puts the 96 tip nodes in 16
// orbits of 6, one blade's tip nodes (gmsh_blade.hpp's 16) the
// representatives; the model's asymmetry is ccx's rounding (header).
TEST_F(CyclicBases, TurnMapsTheDiskOntoItself) {
  const CyclicSymmetry& s = s_cyclic->symmetry;
  EXPECT_EQ(s.sectors, 6);
  EXPECT_EQ(s_partition->n_boundary(), 288);
  EXPECT_EQ(s_cyclic->orbits.n_representatives(), 16);
  const double dk = relative_asymmetry(s, s_model->stiffness);
  const double dm = relative_asymmetry(s, s_model->mass);
  std::printf("turn of %zu nodes, %d boundary orbits of %d; max|P^T K P - K| / max|K| = %.3e, "
              "max|P^T M P - M| / max|M| = %.3e\n",
              s.triples.size(), s_cyclic->orbits.n_representatives(), s.sectors, dk, dm);
  EXPECT_LT(dk, 1e-8);
  EXPECT_LT(dm, 1e-8);
  // Another sector count is not a symmetry of the model: refused naming a node.
  try {
    cyclic_symmetry(*s_model, 7);
    ADD_FAILURE() << "a 6-sector disk taken as 7-fold cyclic";
  } catch (const ReductionError& e) {
    EXPECT_NE(std::string(e.what()).find("not 7-fold cyclic"), std::string::npos) << e.what();
  }
}

TEST_F(CyclicBases, TurnedConstraintModesSolveTheStaticProblem) {
  const Component& c = *s_model;
  const Partition& p = *s_partition;
  const CyclicBoundary& cyc = *s_cyclic;
  const BoundaryOrbits& o = cyc.orbits;
  const int eta = 20;
  const Eigen::MatrixXd psi =
      take_rows(s_basis->transformation.rightCols(p.n_boundary()), p.interior);
  const Eigen::SparseMatrix<double> k_ii = sparse_block(c.stiffness, p.interior, p.interior);
  const Eigen::MatrixXd k_ib(sparse_block(c.stiffness, p.interior, p.boundary));
  const Eigen::MatrixXd r = compensated_residual(k_ii, {}, {-k_ib, {}}, psi);
  const double gamma = (widest(c.stiffness) + 10) * u;
  // The representatives' whole fields phi (as T holds them).
  const std::vector<int> reps = o.representative_positions();
  Eigen::MatrixXd phi(c.n_dofs(), static_cast<Eigen::Index>(reps.size()));
  for (size_t i = 0; i < reps.size(); ++i)
    phi.col(static_cast<Eigen::Index>(i)) = s_basis->transformation.col(eta + reps[i]);
  const Eigen::MatrixXd abs_k_phi = absolute(c.stiffness) * phi.cwiseAbs();
  double worst = 0.0, worst_turned = 0.0;
  for (int k = 0; k < o.sectors; ++k) {
    const Eigen::SparseMatrix<double> e = turned_difference(cyc.symmetry, k, c.stiffness);
    const Eigen::SparseMatrix<double> abs_turn = absolute(turn_matrix(cyc.symmetry, k, c.n_dofs()));
    const Eigen::MatrixXd per_field = absolute(e) * phi.cwiseAbs() + gamma * abs_k_phi;
    const Eigen::MatrixXd turned = take_rows(
        abs_turn * per_field + 3.0 * u * (absolute(c.stiffness) * (abs_turn * phi.cwiseAbs())),
        p.interior);
    const Eigen::Matrix3d rot = turn_rotation(cyc.symmetry, k).cwiseAbs();
    for (int rep = 0; rep < o.n_representatives(); ++rep)
      for (int comp = 0; comp < 3; ++comp) {
        const int j =
            o.position[static_cast<size_t>(rep)][static_cast<size_t>(k)][static_cast<size_t>(comp)];
        const Eigen::VectorXd bound = rot(comp, 0) * turned.col(3 * rep) +
                                      rot(comp, 1) * turned.col(3 * rep + 1) +
                                      rot(comp, 2) * turned.col(3 * rep + 2);
        const double ratio =
            (r.col(j).cwiseAbs().array() / bound.array().max(std::numeric_limits<double>::min()))
                .maxCoeff();
        worst = std::max(worst, ratio);
        if (k > 0) worst_turned = std::max(worst_turned, r.col(j).cwiseAbs().maxCoeff());
      }
  }
  std::printf("K_II psi + K_IB: worst residual / bound %.3e over %d columns (%d solved); largest "
              "turned residual %.3e N/mm, ||K||_max %.3e\n",
              worst, p.n_boundary(), static_cast<int>(reps.size()), worst_turned,
              c.stiffness.coeffs().cwiseAbs().maxCoeff());
  EXPECT_LE(worst, 1.0);
}

/// The entrywise bound on |T^T A T by the turns - the direct product| (the
/// header's), T a CB basis of eta modes and the turned constraint modes.
Eigen::MatrixXd turned_projection_bound(const Eigen::SparseMatrix<double>& a,
                                        const Eigen::MatrixXd& t, int eta,
                                        const CyclicBoundary& cyc) {
  const Eigen::MatrixXd abs_t = t.cwiseAbs();
  const Eigen::MatrixXd scale = abs_t.transpose() * (absolute(a) * abs_t);
  const double gamma = (static_cast<double>(t.rows()) + widest(a) + 12) * u;
  const BoundaryOrbits& o = cyc.orbits;
  const std::vector<int> reps = o.representative_positions();
  Eigen::MatrixXd abs_reps(t.rows(), static_cast<Eigen::Index>(reps.size()));
  for (size_t i = 0; i < reps.size(); ++i)
    abs_reps.col(static_cast<Eigen::Index>(i)) = abs_t.col(eta + reps[i]);
  // |Psi_r|^T |E_k| |T|, turn by turn: the asymmetry's share, entrywise.
  std::vector<Eigen::MatrixXd> asym(static_cast<size_t>(o.sectors));
  for (int k = 0; k < o.sectors; ++k)
    asym[static_cast<size_t>(k)] =
        abs_reps.transpose() * (absolute(turned_difference(cyc.symmetry, k, a)) * abs_t);
  const Eigen::Index r = t.cols();
  Eigen::MatrixXd bound = 2.0 * gamma * scale;
  for (Eigen::Index i = eta; i < r; ++i)
    for (Eigen::Index j = eta; j < r; ++j) {
      // Row triple t = P^k rep, column triple t' with t'' = P^-k t'.
      const size_t bi = static_cast<size_t>(i - eta), bj = static_cast<size_t>(j - eta);
      const int k = o.turns[bi];
      const auto& back = o.position[static_cast<size_t>(o.rep[bj])]
                                   [static_cast<size_t>((o.turns[bj] - k + o.sectors) % o.sectors)];
      const Eigen::Matrix3d rot = turn_rotation(cyc.symmetry, k).cwiseAbs();
      double e = 0.0, turned_rounding = 0.0;
      for (int d = 0; d < 3; ++d)
        for (int f = 0; f < 3; ++f) {
          const double w = rot(o.component[bi], d) * rot(o.component[bj], f);
          const Eigen::Index col = eta + back[static_cast<size_t>(f)];
          e += w * asym[static_cast<size_t>(k)](3 * o.rep[bi] + d, col);
          turned_rounding += w * scale(eta + reps[static_cast<size_t>(3 * o.rep[bi] + d)], col);
        }
      bound(i, j) = e + gamma * (scale(i, j) + turned_rounding) + 12.0 * u * scale(i, j);
    }
  return bound;
}

void expect_projection_is_direct(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& t,
                                 const Eigen::MatrixXd& by_turns, const Eigen::MatrixXd& built,
                                 int eta, const CyclicBoundary& cyc, const char* name) {
  const Eigen::MatrixXd direct = t.transpose() * (a * t);
  const Eigen::MatrixXd abs_t = t.cwiseAbs();
  const Eigen::MatrixXd scale = abs_t.transpose() * (absolute(a) * abs_t);
  const double gamma = (static_cast<double>(t.rows()) + widest(a) + 12) * u;
  const Eigen::MatrixXd bound = turned_projection_bound(a, t, eta, cyc);
  const Eigen::Index r = t.cols();
  const auto worst_of = [&](const Eigen::MatrixXd& m, const Eigen::MatrixXd& b) {
    return ((m - direct).cwiseAbs().array() / b.array()).maxCoeff();
  };
  // The built basis: (B + B^T) / 2 against D, within half the bound at (i, j)
  // and at (j, i) and half the direct product's own asymmetry (2 gamma scale).
  const Eigen::MatrixXd built_bound =
      0.5 * (bound + Eigen::MatrixXd(bound.transpose())) + gamma * scale;
  const double worst = worst_of(by_turns, bound);
  const double worst_built = worst_of(built, built_bound);
  const double size = direct.cwiseAbs().maxCoeff();
  std::printf("%s by the turns against T^T A T (%ld x %ld): worst |difference| / bound %.3e "
              "(as built: %.3e); largest difference %.3e, largest bound %.3e, of max |T^T A T| "
              "= %.3e\n",
              name, static_cast<long>(r), static_cast<long>(r), worst, worst_built,
              (by_turns - direct).cwiseAbs().maxCoeff() / size, bound.maxCoeff() / size, size);
  EXPECT_LE(worst, 1.0) << name;
  EXPECT_LE(worst_built, 1.0) << name;
  // The bound far below the entries: a wrong block or turn (an error of the
  // entries' size) cannot hide under it.
  EXPECT_LT(bound.maxCoeff() / size, 1e-4) << name;
}

TEST_F(CyclicBases, ProjectionByTurnsIsTheDirectProduct) {
  const Eigen::MatrixXd& t = s_basis->transformation;
  const int eta = 20;
  expect_projection_is_direct(s_model->stiffness, t,
                              cyclic_projection(s_model->stiffness, t, eta, *s_cyclic),
                              s_basis->stiffness, eta, *s_cyclic, "K^");
  expect_projection_is_direct(s_model->mass, t, cyclic_projection(s_model->mass, t, eta, *s_cyclic),
                              s_basis->mass, eta, *s_cyclic, "M^");
}

/// T's boundary rows are [I, 0] exactly (q_B = u_B).
bool boundary_rows_exact(const ReducedBasis& b, const Partition& p) {
  const Eigen::MatrixXd rows = take_rows(b.transformation, p.boundary);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(rows.rows(), rows.cols());
  expected.leftCols(p.n_boundary()).setIdentity();
  return rows == expected;
}

// G = (K^-1)_BB by the turns (turned_residual_flexibility.hpp, from the
// representatives' refined columns x_(r,d) = K^-1 e_(r,d)):
// - column t = P^k r of K^-1 E_B turned as the constraint modes, x_t =
//   sum_d R_cd P^k x_(r,d), solves K x = e_t up to sum_d R_cd P^k (E_k
//   x_(r,d) + rho_d), E_k = P^kT K P^k - K, |rho_d| <= gamma |K| |x_(r,d)|
//   (refined to the last bit; gamma = (m + 10) u), plus the turn's 3-term
//   sums, 3 u |K| |P^k| |x|: the constraint modes' bound above;
// - G's row t is x_t's boundary rows (G = G^T): each entry the same nine
//   products R_cd x R_c'e in another order, so within 2 gamma_11 of
//   sum |R_cd| |x| |R_c'e| <= 2 gamma_11 9 max |x| over the 3 x 3 block.
void expect_turned_flexibility(const Component& c, const Partition& p, const CyclicBoundary& cyc,
                               const Eigen::MatrixXd& x_r, const Eigen::MatrixXd& g) {
  const BoundaryOrbits& o = cyc.orbits;
  const int n = c.n_dofs();
  const int nb = p.n_boundary();
  const double gamma = (widest(c.stiffness) + 10) * u;
  const Eigen::MatrixXd abs_x = x_r.cwiseAbs();
  const Eigen::MatrixXd abs_k_x = absolute(c.stiffness) * abs_x;
  Eigen::MatrixXd x(n, nb), bound(n, nb);
  for (int k = 0; k < o.sectors; ++k) {
    const Eigen::MatrixXd turned = k == 0 ? x_r : turn_fields(cyc.symmetry, k, x_r);
    const Eigen::SparseMatrix<double> abs_turn = absolute(turn_matrix(cyc.symmetry, k, n));
    const Eigen::MatrixXd per_field =
        abs_turn *
            (absolute(turned_difference(cyc.symmetry, k, c.stiffness)) * abs_x + gamma * abs_k_x) +
        3.0 * u * (absolute(c.stiffness) * (abs_turn * abs_x));
    const Eigen::Matrix3d rot = turn_rotation(cyc.symmetry, k);
    for (int rep = 0; rep < o.n_representatives(); ++rep)
      for (int comp = 0; comp < 3; ++comp) {
        const int at =
            o.position[static_cast<size_t>(rep)][static_cast<size_t>(k)][static_cast<size_t>(comp)];
        x.col(at).setZero();
        bound.col(at).setZero();
        for (int d = 0; d < 3; ++d) {
          x.col(at) += rot(comp, d) * turned.col(3 * rep + d);
          bound.col(at) += std::abs(rot(comp, d)) * per_field.col(3 * rep + d);
        }
      }
  }
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(n, nb);
  for (int j = 0; j < nb; ++j)
    unit(p.boundary[static_cast<size_t>(j)], j) = 1.0;
  const Eigen::MatrixXd r = compensated_residual(c.stiffness, {}, {unit, {}}, x);
  const double worst =
      (r.cwiseAbs().array() / bound.array().max(std::numeric_limits<double>::min())).maxCoeff();
  // G's rows against x_t's boundary rows, block by block.
  const Eigen::MatrixXd g_test = take_rows(x, p.boundary).transpose();
  double worst_g = 0.0;
  const auto at = [&](int rep, int k, int comp) {
    return o.position[static_cast<size_t>(rep)][static_cast<size_t>(k)][static_cast<size_t>(comp)];
  };
  for (int k = 0; k < o.sectors; ++k)
    for (int rep = 0; rep < o.n_representatives(); ++rep)
      for (int rep2 = 0; rep2 < o.n_representatives(); ++rep2)
        for (int k2 = 0; k2 < o.sectors; ++k2) {
          // Row triple P^k rep, column triple P^k2 rep2, turned back by k.
          const int back = (k2 - k + o.sectors) % o.sectors;
          double block_max = 0.0;
          for (int d = 0; d < 3; ++d)
            for (int e = 0; e < 3; ++e)
              block_max = std::max(
                  block_max,
                  std::abs(x_r(p.boundary[static_cast<size_t>(at(rep2, back, e))], 3 * rep + d)));
          const double limit =
              std::max(2.0 * 11.0 * u * 9.0 * block_max, std::numeric_limits<double>::min());
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
              const int row = at(rep, k, a), col = at(rep2, k2, b);
              worst_g = std::max(worst_g, std::abs(g(row, col) - g_test(row, col)) / limit);
            }
        }
  std::printf("K^-1 E_B by the turns: worst |K x_t - e_t| / bound %.3e over %d columns (%d "
              "solved); G against the turned columns' boundary rows: worst |difference| / bound "
              "%.3e\n",
              worst, nb, static_cast<int>(x_r.cols()), worst_g);
  EXPECT_LE(worst, 1.0);
  EXPECT_LE(worst_g, 1.0);
}

// CCM and MacNeal by the turns (turned_residual_flexibility.hpp) pass the
// rows the direct bases pass, with the bounds of
// verification/support/reduction_rows.hpp (CHOLMOD's own factor of K, its
// own modes): the exact static response to boundary loads (span T holds
// K^-1 E_B = Psi G), the boundary stiffness G^-1, and MacNeal's: T = CCM's
// T, a massless boundary, K^ = T^T K T, its finite eigenvalues the lowest 20
// full ones; K^ and M^ from the expansion within its bound (below). CCM(0)
// by the turns is Guyan's by the turns (the same call). The T entries are
// not compared with the direct basis: C = Omega^-2 Phi_1B^T R_B^-1
// amplifies any change of (K^-1)_BB by cond(R_B) and by what the 20 modes
// cancel of it (measured: T 1.7e-5 off the direct one on this model,
// 1.1e-7 on it made cyclic to 2.7e-16, the rows unchanged), a change of
// coordinates within the span, not of the reduced model.
TEST_F(CyclicBases, ResidualFlexibilityBasesPassTheRows) {
  const Component& c = *s_model;
  const Partition& p = *s_partition;
  // CCM-20 with the pieces of its T; MacNeal-20 as the commands build it.
  TurnedResidualPieces pieces;
  const std::vector<int> reps = s_cyclic->orbits.representative_positions();
  const FreeInterfacePool pool = free_interface_pool(c.stiffness, c.mass, p, 20, "CCM", &reps);
  const ReducedBasis ccm =
      turned_residual_flexibility(c.stiffness, c.mass, p, pool, *s_cyclic, "CCM", &pieces);
  // Two builds of the same pool (K's CHOLMOD factor, the same Lanczos) give
  // the same bits: MacNeal's T and K^ are compared with CCM's exactly below.
  Component cyclic = c;
  cyclic.cyclic_bases = s_cyclic->symmetry.sectors;
  const ReducedBasis mn = reduce(cyclic, "macneal", 20, 0);
  EXPECT_TRUE(boundary_rows_exact(ccm, p));
  EXPECT_TRUE(boundary_rows_exact(mn, p));
  expect_turned_flexibility(c, p, *s_cyclic, pool.flexibility.value, pieces.g);

  const rows::Component rc(c.stiffness, c.mass, c.boundary);
  const rows::StaticRow st =
      rows::static_response(rc, ccm, rows::random_boundary_loads(p.n_boundary()));
  std::printf("CCM-20 by the turns, static boundary loads: response %.3e (%.2e of bound), "
              "boundary stiffness ||S G - I|| %.3e (%.2e of bound), cond(G) %.3e, cond(R_B) "
              "%.6e\n",
              st.response.error, st.response.ratio, st.boundary_stiffness.error,
              st.boundary_stiffness.ratio, st.cond_g, ccm.cond_rb);
  EXPECT_LE(st.response.ratio, 1.0);
  EXPECT_LE(st.boundary_stiffness.ratio, 1.0);

  const Modes full = rows::full_modes(rc, 20);
  const rows::MacNealRow r =
      rows::macneal_row(rc, mn, ccm, *s_basis, full, rows::full_modes_by_lanczos(rc));
  std::printf("MacNeal-20 by the turns: |M^ boundary| %.1e, |M^_qq - I| %.1e, |T - T_CCM| %.1e; "
              "K^ vs T^T K T %.3e (%.2e of bound); finite eigenvalues vs full relative %.3e "
              "(%.2e); vs CCM %.3e (%.2e)\n",
              r.boundary_mass, r.modal_mass, r.t_vs_ccm, r.stiffness.error, r.stiffness.ratio,
              r.eigenvalues.error, r.eigenvalues.ratio, r.below_ccm.error, r.below_ccm.ratio);
  EXPECT_EQ(r.boundary_mass, 0.0);
  EXPECT_EQ(r.modal_mass, 0.0);
  EXPECT_EQ(r.t_vs_ccm, 0.0);
  EXPECT_LE(r.stiffness.ratio, 1.0);
  EXPECT_LE(r.eigenvalues.ratio, 1.0);
  EXPECT_LE(r.below_ccm.ratio, 1.0);

  // K^ and M^ from the expansion T^T A T = [Psi^T A Psi, 0; 0, 0] + E X W +
  // W^T X^T E^T + W^T Z W (turned_residual_flexibility.hpp) against T^T A T
  // of T as built: the Guyan block by the turns within its bound above
  // (halves averaged, the direct product's asymmetry added), and the
  // rounding of the products X = Psi^T (A Y), X W, Z = Y^T (A Y), W^T Z W,
  // their four-term sum, T = fl(Y W) + [Psi, 0] itself (twice, first order)
  // and the test's own product, each at most gamma_k U^T |A| U with
  // U = [|Psi|, 0] + |Y| |W| >= |T| and k <= n + m + 2 psi + 4: in all
  // (5 (n + m) + 8 psi + 10) u U^T |A| U, m the widest column of A.
  EXPECT_TRUE(mn.stiffness == ccm.stiffness); // MacNeal's K^ is CCM's (macneal.hpp)
  const Eigen::MatrixXd& t = ccm.transformation;
  Eigen::MatrixXd envelope = pieces.y.cwiseAbs() * pieces.w.cwiseAbs();
  envelope.leftCols(p.n_boundary()) += pieces.psi.cwiseAbs();
  const int nb = p.n_boundary();
  for (int which = 0; which < 2; ++which) {
    const Eigen::SparseMatrix<double>& a = which == 0 ? c.stiffness : c.mass;
    const Eigen::MatrixXd& built = which == 0 ? ccm.stiffness : ccm.mass;
    const Eigen::MatrixXd direct = t.transpose() * (a * t);
    const double gamma =
        (5.0 * (c.n_dofs() + widest(a)) + 8.0 * static_cast<double>(pieces.w.rows()) + 10.0) * u;
    Eigen::MatrixXd bound = gamma * (envelope.transpose() * (absolute(a) * envelope));
    const Eigen::MatrixXd guyan_bound = turned_projection_bound(a, pieces.psi, 0, *s_cyclic);
    bound.topLeftCorner(nb, nb) += 0.5 * (guyan_bound + guyan_bound.transpose());
    const double worst = ((built - direct).cwiseAbs().array() / bound.array()).maxCoeff();
    const double size = direct.cwiseAbs().maxCoeff();
    std::printf("CCM-20 by the turns: %s vs T^T A T worst |difference| / bound %.3e; largest "
                "difference %.3e, largest bound %.3e, of max |T^T A T| = %.3e\n",
                which == 0 ? "K^" : "M^", worst, (built - direct).cwiseAbs().maxCoeff() / size,
                bound.maxCoeff() / size, size);
    EXPECT_LE(worst, 1.0);
    // A wrong block (an error of the entries' size) cannot hide: the bound
    // stays below 1e-3 of the largest entry (4.2e-4 for K^ measured, looser
    // than CB's 1e-4: U counts the cancellation in Psi - Y C).
    EXPECT_LT(bound.maxCoeff() / size, 1e-3);
  }
}

// The case key: a cyclic source only (exit 2 in the CLI, as every case error).
TEST(CyclicBasesCase, KeyNeedsACyclicSource) {
  const std::string blade = RSI_SOURCE_DIR "/data/cases/blade3d.json";
  std::ifstream in(blade);
  nlohmann::json j = nlohmann::json::parse(in);
  j["component"]["cyclic_bases"] = true;
  try {
    parse_component_case(j, blade);
    ADD_FAILURE() << "cyclic_bases accepted on a blade";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("component.cyclic_bases"), std::string::npos) << e.what();
  }
  std::ifstream in2(ci_case);
  nlohmann::json d = nlohmann::json::parse(in2);
  d["component"]["cyclic_bases"] = "yes";
  EXPECT_THROW(parse_component_case(d, ci_case), std::exception);
  d["component"]["cyclic_bases"] = true;
  EXPECT_TRUE(parse_component_case(d, ci_case).cyclic_bases);
}

} // namespace
} // namespace rsi

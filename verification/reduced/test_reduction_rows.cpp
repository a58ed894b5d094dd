// The rows V3 / V4 of SPEC §4 and MacNeal's through verification/
// reduction_rows (functions any component's test can call: no dense n x n,
// sparse solves, lowest modes only), here on the paper's bladed disk with
// the 44 tip u, v as boundary. test_reduction_bases checks the same rows on
// this model against dense references; this suite checks the reusable
// functions and prints what they measure. Each row returns its errors with
// their worst ratio to a first-order round-off bound (the bounds are stated
// in reduction_rows.hpp): the assertion is ratio <= 1.

#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "reduction.hpp"
#include "reduction_rows.hpp"

namespace rsi {
namespace {

using rows::Measure;

class ReductionRows : public ::testing::Test {
protected:
  static constexpr int n_full = 100; ///< full modes computed (the rows need the lowest only)

  static void SetUpTestSuite() {
    s_bd = std::make_unique<BladedDisk>(assemble_bladed_disk(
        load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json")));
    s_c = std::make_unique<rows::Component>(s_bd->stiffness, s_bd->mass, s_bd->boundary);
    s_full = std::make_unique<Modes>(rows::full_modes(*s_c, n_full));
    std::printf("component: n = %d, n_B = %d, ||K||_inf = %.3e, ||M||_inf = %.3e, cond_2(K) = "
                "%.3e (Lanczos), omega_max = %.6e rad/s; %d full modes (%s)\n",
                s_c->n(), s_c->n_boundary(), s_c->k_norm(), s_c->m_norm(), s_c->cond_k(),
                std::sqrt(s_c->lambda_max()), n_full, by_lanczos() ? "Lanczos" : "dsygvd");
  }
  static void TearDownTestSuite() {
    s_full.reset();
    s_c.reset();
    s_bd.reset();
  }
  static const rows::Component& component() { return *s_c; }
  static const Modes& full() { return *s_full; }
  static bool by_lanczos() { return rows::full_modes_by_lanczos(*s_c); }
  static ReducedBasis basis(const std::string& method, int modes) {
    return reduce_bladed_disk(*s_bd, method, modes);
  }

  static std::unique_ptr<BladedDisk> s_bd;
  static std::unique_ptr<rows::Component> s_c;
  static std::unique_ptr<Modes> s_full;
};
std::unique_ptr<BladedDisk> ReductionRows::s_bd;
std::unique_ptr<rows::Component> ReductionRows::s_c;
std::unique_ptr<Modes> ReductionRows::s_full;

void print_mode_row(const char* what, const rows::ModeRow& r) {
  std::printf("%s: %d modes (%s): |Phi^T M Phi - I| %.3e (%.2e of bound); K off-diagonal %.3e "
              "omega_m^2 (%.2e); K diagonal vs omega^2 relative %.3e (%.2e); residual %.3e\n",
              what, r.n_modes, r.lanczos ? "Lanczos" : "dsygvd", r.mass.error, r.mass.ratio,
              r.stiffness_off.error, r.stiffness_off.ratio, r.stiffness_diag.error,
              r.stiffness_diag.ratio, r.residual);
}

void expect_mode_row(const rows::ModeRow& r) {
  EXPECT_LE(r.mass.ratio, 1.0);
  EXPECT_LE(r.stiffness_off.ratio, 1.0);
  EXPECT_LE(r.stiffness_diag.ratio, 1.0);
}

// V3: Phi^T M Phi = I, Phi^T K Phi = Omega^2 for the full modes, the
// fixed-interface modes (as CB computes them) and the free modes (as CCM
// and MacNeal compute them), whose eigenvalues also match the full ones.
TEST_F(ReductionRows, ModesOrthonormal) {
  const rows::Component& c = component();
  const rows::ModeRow f = rows::full_mode_row(c, full());
  print_mode_row("full", f);
  expect_mode_row(f);
  for (int eta : {44, 88, 300}) {
    const rows::ModeRow r = rows::fixed_interface_row(c, eta);
    print_mode_row("fixed-interface", r);
    expect_mode_row(r);
  }
  for (int psi : {10, 44, 88}) {
    const rows::FreeModeRow r = rows::free_mode_row(c, psi, full());
    print_mode_row("free", r.modes);
    std::printf("  free vs full eigenvalues: max relative %.3e (%.2e of bound)\n",
                r.eigenvalues.error, r.eigenvalues.ratio);
    expect_mode_row(r.modes);
    EXPECT_LE(r.eigenvalues.ratio, 1.0);
  }
}

// V3: Craig-Bampton's reduced stiffness is block diagonal.
TEST_F(ReductionRows, CraigBamptonBlockDiagonal) {
  for (int eta : {10, 44, 88}) {
    const rows::BlockRow r = rows::cb_block_diagonal(component(), basis("cb", eta));
    std::printf("CB %2d: |K^(modal, B)| %.3e ||K^|| (%.2e of bound); |M^(modal) - I| %.3e "
                "(%.2e); K^(modal) off-diagonal %.3e ||K^|| (%.2e)\n",
                eta, r.coupling.error, r.coupling.ratio, r.modal_mass.error, r.modal_mass.ratio,
                r.modal_stiffness_off.error, r.modal_stiffness_off.ratio);
    EXPECT_LE(r.coupling.ratio, 1.0);
    EXPECT_LE(r.modal_mass.ratio, 1.0);
    EXPECT_LE(r.modal_stiffness_off.ratio, 1.0);
  }
}

// V4: static boundary loads (four random loads, fixed seed) reproduced by
// CB, CCM and MacNeal at any mode count, and K^ condensed onto the boundary
// = ((K^-1)_BB)^-1.
TEST_F(ReductionRows, StaticBoundaryLoadsExact) {
  const rows::Component& c = component();
  std::mt19937 generator(2007);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd loads(c.n_boundary(), 4);
  for (Eigen::Index j = 0; j < loads.cols(); ++j)
    for (Eigen::Index i = 0; i < loads.rows(); ++i)
      loads(i, j) = 1000.0 * uniform(generator); // [N]
  for (const char* method : {"cb", "ccm", "macneal"})
    for (int modes : {0, 10, 44, 88}) {
      if (std::string(method) == "macneal" && modes == 0) continue; // psi >= 1
      const rows::StaticRow r = rows::static_response(c, basis(method, modes), loads);
      std::printf("%-7s %2d: static response %.3e (%.2e of bound); ||S G - I||_2 %.3e (%.2e of "
                  "bound; cond(G) %.3e)\n",
                  method, modes, r.response.error, r.response.ratio, r.boundary_stiffness.error,
                  r.boundary_stiffness.ratio, r.cond_g);
      EXPECT_LE(r.response.ratio, 1.0);
      EXPECT_LE(r.boundary_stiffness.ratio, 1.0);
    }
}

// V4: CB(0) = CCM(0) = Guyan, matrices to round-off.
TEST_F(ReductionRows, ZeroModeLimitsAreGuyan) {
  const std::vector<rows::ZeroModeRow> rs =
      rows::zero_mode_limits(component(), basis("guyan", 0), basis("cb", 0), basis("ccm", 0));
  for (const rows::ZeroModeRow& r : rs) {
    std::printf("%s(0) vs Guyan: T max %.1f ulp, ||dT||_2 %.3e (%.2e of bound); ||dK^|| / ||K^|| "
                "%.3e (%.2e); ||dM^|| / ||M^|| %.3e (%.2e)\n",
                r.method.c_str(), r.t_ulps, r.transformation.error, r.transformation.ratio,
                r.stiffness.error, r.stiffness.ratio, r.mass.error, r.mass.ratio);
    EXPECT_LE(r.transformation.ratio, 1.0);
    EXPECT_LE(r.stiffness.ratio, 1.0);
    EXPECT_LE(r.mass.ratio, 1.0);
  }
}

// V4: Rayleigh-Ritz upper bounds, and decrease with the mode count, CB and CCM.
TEST_F(ReductionRows, RayleighRitzBoundsAndDecrease) {
  for (const char* method : {"cb", "ccm"}) {
    std::vector<ReducedBasis> bases;
    for (int modes : {0, 4, 8, 16, 32, 64, 88})
      bases.push_back(basis(method, modes));
    std::vector<const ReducedBasis*> nested;
    for (const ReducedBasis& b : bases)
      nested.push_back(&b);
    const std::vector<rows::RitzRow> rs =
        rows::rayleigh_ritz(component(), nested, full(), by_lanczos(), 20);
    for (const rows::RitzRow& r : rs) {
      std::printf("%-3s %2d (r = %3d): lowest 20 relative error %.3e; shortfall %.3e (%.2e of "
                  "bound); top %.3e (%.2e); rise %.3e (%.2e); omega_max %.6e rad/s\n",
                  r.method.c_str(), r.n_modes, r.n_reduced, r.lowest_error, r.below.error,
                  r.below.ratio, r.top.error, r.top.ratio, r.rise.error, r.rise.ratio, r.omega_max);
      EXPECT_LE(r.below.ratio, 1.0);
      EXPECT_LE(r.top.ratio, 1.0);
      EXPECT_LE(r.rise.ratio, 1.0);
    }
  }
}

// MacNeal: zero boundary mass, CCM's T, K^ = T^T K T, the finite eigenvalues
// the lowest psi full ones, omega_max = omega_psi, never above CCM's.
TEST_F(ReductionRows, MacNealMasslessBoundary) {
  for (int psi : {1, 10, 44, 88}) {
    const rows::MacNealRow r =
        rows::macneal_row(component(), basis("macneal", psi), basis("ccm", psi), basis("cb", psi),
                          full(), by_lanczos());
    std::printf("MacNeal %2d: |M^ boundary| %.1e, |M^_qq - I| %.1e, |T - T_CCM| %.1e (exact 0); "
                "K^ vs T^T K T %.3e (%.2e of bound); finite eigenvalues vs full relative %.3e "
                "(%.2e); omega_max %.9e vs omega_psi %.9e; CCM %.6e, CB %.6e rad/s; vs CCM "
                "%.3e (%.2e)\n",
                psi, r.boundary_mass, r.modal_mass, r.t_vs_ccm, r.stiffness.error,
                r.stiffness.ratio, r.eigenvalues.error, r.eigenvalues.ratio, r.omega_max,
                r.omega_psi, r.omega_max_ccm, r.omega_max_cb, r.below_ccm.error, r.below_ccm.ratio);
    EXPECT_EQ(r.boundary_mass, 0.0);
    EXPECT_EQ(r.modal_mass, 0.0);
    EXPECT_EQ(r.t_vs_ccm, 0.0);
    EXPECT_LE(r.stiffness.ratio, 1.0);
    EXPECT_LE(r.eigenvalues.ratio, 1.0);
    EXPECT_LE(r.below_ccm.ratio, 1.0);
  }
}

} // namespace
} // namespace rsi

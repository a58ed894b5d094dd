// The reduced solver's own tip/flexible-casing law and modal casing step
// (reduced/solid_casing_part.hpp, issue 27 items 3 and 4) against the
// reference's law (reference/contact/solid_casing_contact.hpp), written
// apart: their agreement is the evidence. On the CI casing's deck
// (data/cases/casing3d-ci.json, meshed by gmsh into the build's cache; no
// ccx needed) with 24 tips at radius 271.5 mm, heights -25 .. 25 mm,
// turning at 1344 rad/s, and a casing basis Phi of m = 6 random columns on
// its dofs (the law does not care whether they are modes):
// - gaps, slips and rows at a casing state p (c = Phi p) and tip
//   displacements equal the reference's on the system vector [u_tips; Phi p]
//   (rows: B on the tips, the reference's casing rows times Phi = H);
// - the step's casing share of W is dt^2 H H^T;
// - the casing's central-difference identity: E_{n+1/2} - E_{-1/2} =
//   W_ext + W_contact over 40 steps with random multipliers and a load
//   that stops after step 20, to the rounding of the sums.
// Skipped without gmsh.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "case_file.hpp"
#include "component_case.hpp"
#include "component_integration_error.hpp"
#include "gmsh_blade_fit.hpp"
#include "solid_casing_contact.hpp"
#include "solid_casing_part.hpp"

namespace rsi {
namespace {

constexpr double kOmega = 1344.0, kTipRadius = 271.5, kDt = 1e-7;
constexpr int kTips = 24, kModes = 6;

struct CasingTips {
  CalculixDeck deck;
  std::vector<RigidSurfaceNode> tips;                   ///< the reference's (system dofs)
  std::map<int, std::array<int, 3>> system_casing_dofs; ///< node -> system dofs
  std::map<int, std::array<int, 3>> basis_casing_dofs;  ///< node -> rows of Phi
  int n_casing = 0;
  int n_dofs = 0;
  CasingBasis basis;
};

CasingTips setup() {
  const std::string case_path = std::string(RSI_SOURCE_DIR) + "/data/cases/casing3d-ci.json";
  const ComponentCase c = parse_component_case(read_case_document(case_path), case_path);
  ComponentLoadOptions options;
  const char* cache = std::getenv("RSI_CCX_CACHE");
  options.ccx_cache = cache && *cache ? cache : RSI_BINARY_DIR "/ccx-cache";
  CasingTips s;
  s.deck = component_deck(c, options).deck;
  for (int k = 0; k < kTips; ++k) {
    RigidSurfaceNode tip;
    const double phi = -M_PI + 2.0 * M_PI * (k + 0.31) / kTips;
    tip.position = Eigen::Vector3d(kTipRadius * std::cos(phi), kTipRadius * std::sin(phi),
                                   -25.0 + 50.0 * k / (kTips - 1));
    tip.dofs = {3 * k, 3 * k + 1, 3 * k + 2};
    s.tips.push_back(tip);
  }
  const std::vector<int>& flange = s.deck.nsets.at("FLANGE");
  const std::set<int> clamped(flange.begin(), flange.end());
  for (const ComponentNode& node : s.deck.nodes)
    if (!clamped.count(node.id)) {
      const int k = s.n_casing;
      s.basis_casing_dofs[node.id] = {k, k + 1, k + 2};
      s.system_casing_dofs[node.id] = {3 * kTips + k, 3 * kTips + k + 1, 3 * kTips + k + 2};
      s.n_casing += 3;
    }
  s.n_dofs = 3 * kTips + s.n_casing;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  s.basis.shapes.resize(s.n_casing, kModes);
  for (int i = 0; i < s.n_casing; ++i)
    for (int j = 0; j < kModes; ++j)
      s.basis.shapes(i, j) = u(random);
  s.basis.omega_squared.resize(kModes);
  for (int j = 0; j < kModes; ++j)
    s.basis.omega_squared(j) = std::pow(2.0 * M_PI * 2000.0 * (j + 1), 2);
  s.basis.n_modes = kModes;
  return s;
}

RigidCasing tips_of(const CasingTips& s) {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> index;
  for (int k = 0; k < kTips; ++k) {
    positions.push_back(s.tips[k].position);
    index.push_back({3 * k, 3 * k + 1, 3 * k + 2});
  }
  return RigidCasing(positions, index, CasingGap{}, kOmega, kOmega);
}

Eigen::RowVectorXd dense(const SparseRow& row, int n) {
  Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(n);
  for (const auto& [dof, value] : row)
    r(dof) += value;
  return r;
}

#define SKIP_WITHOUT_GMSH()                                                                        \
  if (const std::string missing = testing::missing_programs({"gmsh"}); !missing.empty()) {         \
    std::printf("not run: %s not on PATH (Debian gmsh)\n", missing.c_str());                       \
    GTEST_SKIP() << missing << " not on PATH";                                                     \
  }

TEST(SolidCasingPart, AgreesWithTheReferenceLaw) {
  SKIP_WITHOUT_GMSH();
  const CasingTips s = setup();
  const CasingSurface surface(s.deck, "SINNER");
  const SolidCasingContact law(s.tips, surface, s.system_casing_dofs, kOmega, 0.1);
  // A step and multipliers that move the casing by about 1e-2 mm in two steps.
  const double dt = 1e-5;
  SolidCasingPart part(tips_of(s), 3 * kTips, dt, surface, s.basis_casing_dofs, s.basis, {});
  std::mt19937 random(13);
  std::uniform_real_distribution<double> u(-1e-2, 1e-2); // mm
  std::uniform_real_distribution<double> l(0.0, 1e7);    // N
  // Two steps with random multipliers: p_n and p_{n-1} not zero.
  part.start();
  Eigen::VectorXd u_now = Eigen::VectorXd::Zero(3 * kTips), lambda(3 * kTips);
  for (int n = 0; n < 2; ++n) {
    part.predict(u_now, u_now, n * dt, (n + 1) * dt);
    for (int i = 0; i < 3 * kTips; ++i)
      lambda(i) = l(random);
    part.correct(lambda);
    part.advance();
  }
  const Eigen::VectorXd p = part.modal_state();
  ASSERT_GT(p.norm(), 0.0);
  Eigen::VectorXd u_trial(3 * kTips);
  for (int i = 0; i < 3 * kTips; ++i) {
    u_now(i) = u(random);
    u_trial(i) = u(random);
  }
  const double t_next = 3 * dt;
  part.predict(u_trial, u_now, 2 * dt, t_next);
  const Eigen::MatrixXd& h = part.casing_rows();
  ASSERT_EQ(h.rows(), 3 * kTips);
  ASSERT_EQ(h.cols(), kModes);
  Eigen::VectorXd current(s.n_dofs), predicted(s.n_dofs);
  current << u_now, s.basis.shapes * p;
  predicted << u_trial, s.basis.shapes * part.trial_state();
  FrictionalContactGeometry step;
  law.evaluate(current, predicted, t_next, dt, step);
  double worst_g = 0.0, worst_s = 0.0, worst_row = 0.0, row_scale = 0.0;
  for (int c = 0; c < kTips; ++c) {
    worst_g = std::max(worst_g, std::abs(part.prediction()(3 * c) - step.normal_gap(c)));
    for (int k = 0; k < 2; ++k)
      worst_s =
          std::max(worst_s, std::abs(part.prediction()(3 * c + 1 + k) - step.slip(2 * c + k)));
  }
  // Rows: the reference's on the tips = B, its casing part times Phi = H.
  for (int r = 0; r < 3 * kTips; ++r) {
    const Eigen::RowVectorXd ref = dense(step.rows[static_cast<size_t>(r)], s.n_dofs);
    const Eigen::RowVectorXd casing_part = ref.tail(s.n_casing) * s.basis.shapes;
    worst_row =
        std::max(worst_row, (ref.head(3 * kTips) - part.rows().row(r)).cwiseAbs().maxCoeff());
    worst_row = std::max(worst_row, (casing_part - h.row(r)).cwiseAbs().maxCoeff());
    row_scale = std::max(row_scale, casing_part.cwiseAbs().maxCoeff());
  }
  // Gaps at the new level after the correction: gaps_at against
  // evaluate(x, x) with x the corrected state.
  for (int i = 0; i < 3 * kTips; ++i)
    lambda(i) = l(random);
  part.correct(lambda);
  part.advance();
  part.gaps_at(u_trial, t_next);
  Eigen::VectorXd after(s.n_dofs);
  after << u_trial, s.basis.shapes * part.modal_state();
  FrictionalContactGeometry level;
  law.evaluate(after, after, t_next, dt, level);
  double worst_level = 0.0;
  for (int c = 0; c < kTips; ++c)
    worst_level = std::max(worst_level, std::abs(part.gap()(c) - level.normal_gap(c)));
  const double casing_size = (s.basis.shapes * part.modal_state()).cwiseAbs().maxCoeff();
  std::printf("vs the reference law: predicted gaps within %.2e mm, slips %.2e mm, gaps at "
              "the level %.2e mm (casing displacements up to %.2e mm); rows (B; H = G_c Phi) "
              "within %.2e of the largest |H| %.3e; 24 tips, m = %d\n",
              worst_g, worst_s, worst_level, casing_size, worst_row, row_scale, kModes);
  // Gaps: rho - r ~ 0.5 mm from numbers of 272 mm (2 ulp of 272: 1.2e-13
  // mm) plus sums of 21 products summed in another order (H p here, G_c
  // (Phi p) there): 32 eps x |H| |p| m. Slips: the latter alone.
  const double eps = std::numeric_limits<double>::epsilon();
  const double sums = 32.0 * eps * row_scale * part.modal_state().cwiseAbs().maxCoeff() * kModes +
                      32.0 * eps * 1e-2;
  EXPECT_LE(worst_g, 1.2e-13 + sums);
  EXPECT_LE(worst_level, 1.2e-13 + sums);
  EXPECT_LE(worst_s, sums + 32.0 * eps * kTipRadius * kOmega * dt);
  EXPECT_GT(casing_size, 1e-3); // the casing terms are not negligible in the comparison
  // Rows: 18 products N_i d_a Phi_ka summed in another order: 32 eps x the largest.
  EXPECT_LE(worst_row, 32.0 * eps * row_scale);
}

TEST(SolidCasingPart, CasingShareOfWIsDtSquaredHHt) {
  SKIP_WITHOUT_GMSH();
  const CasingTips s = setup();
  SolidCasingPart part(tips_of(s), 3 * kTips, kDt, CasingSurface(s.deck, "SINNER"),
                       s.basis_casing_dofs, s.basis, {});
  part.start();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3 * kTips);
  part.predict(zero, zero, 0.0, kDt);
  Eigen::MatrixXd w = Eigen::MatrixXd::Identity(3 * kTips, 3 * kTips);
  part.add_flexibility(w);
  const Eigen::MatrixXd& h = part.casing_rows();
  const Eigen::MatrixXd expected =
      Eigen::MatrixXd::Identity(3 * kTips, 3 * kTips) + kDt * kDt * h * h.transpose();
  const double error = (w - expected).cwiseAbs().maxCoeff();
  // Each entry a sum of m = 6 products, summed in another order (rank update).
  const double bound = 16.0 * std::numeric_limits<double>::epsilon() * kModes * kDt * kDt *
                       h.cwiseAbs2().rowwise().sum().maxCoeff();
  std::printf("W_c = dt^2 H H^T within %.2e (bound %.2e), symmetric: %s\n", error, bound,
              w.isApprox(w.transpose(), 0.0) ? "exactly" : "no");
  EXPECT_LE(error, bound);
  EXPECT_EQ((w - w.transpose()).cwiseAbs().maxCoeff(), 0.0);
  // The contact at t = 0 (t_next = t_n) holds the casing: no share.
  part.predict(zero, zero, 0.0, 0.0);
  Eigen::MatrixXd held = Eigen::MatrixXd::Identity(3 * kTips, 3 * kTips);
  part.add_flexibility(held);
  EXPECT_EQ(held, Eigen::MatrixXd::Identity(3 * kTips, 3 * kTips));
}

TEST(SolidCasingPart, EnergyIdentityOfTheCasingStep) {
  SKIP_WITHOUT_GMSH();
  const CasingTips s = setup();
  std::mt19937 random(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SolidCasingLoad load;
  load.force.resize(s.n_casing);
  for (int i = 0; i < s.n_casing; ++i)
    load.force(i) = 100.0 * u(random); // N
  load.duration = 20.5 * kDt;
  SolidCasingPart part(tips_of(s), 3 * kTips, kDt, CasingSurface(s.deck, "SINNER"),
                       s.basis_casing_dofs, s.basis, load);
  part.start();
  const double e0 = part.energy();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3 * kTips);
  Eigen::VectorXd lambda(3 * kTips);
  double scale = std::abs(e0);
  for (int n = 0; n < 40; ++n) {
    part.predict(zero, zero, n * kDt, (n + 1) * kDt);
    for (int i = 0; i < 3 * kTips; ++i)
      lambda(i) = n % 3 == 0 ? 0.0 : 1e3 * std::abs(u(random));
    part.correct(lambda);
    part.advance();
    scale = std::max({scale, std::abs(part.energy()), std::abs(part.external_work()),
                      std::abs(part.contact_work())});
    EXPECT_EQ(part.load_share(n), n <= 20 ? 1.0 : 0.0) << "step " << n;
  }
  const double error = std::abs(part.energy() - e0 - part.external_work() - part.contact_work());
  std::printf("casing step over 40 steps: E %.6e, E0 %.3e, W_ext %.6e, W_contact %.6e; "
              "|E - E0 - W_ext - W_contact| = %.2e (%.2e of the scale)\n",
              part.energy(), e0, part.external_work(), part.contact_work(), error, error / scale);
  EXPECT_GT(std::abs(part.external_work()), 0.0);
  EXPECT_GT(std::abs(part.contact_work()), 0.0);
  // The identity holds per step to the rounding of its terms (a few eps of
  // the scale each); 40 steps: 1e3 eps x the scale.
  EXPECT_LE(error, 1e3 * std::numeric_limits<double>::epsilon() * scale);
}

TEST(SolidCasingPart, Refusals) {
  SKIP_WITHOUT_GMSH();
  const CasingTips s = setup();
  const CasingSurface surface(s.deck, "SINNER");
  CasingBasis empty;
  EXPECT_THROW(SolidCasingPart(tips_of(s), 3 * kTips, kDt, surface, s.basis_casing_dofs, empty, {}),
               std::invalid_argument);
  SolidCasingLoad bad;
  bad.force = Eigen::VectorXd::Ones(3);
  EXPECT_THROW(
      SolidCasingPart(tips_of(s), 3 * kTips, kDt, surface, s.basis_casing_dofs, s.basis, bad),
      std::invalid_argument);
  std::vector<Eigen::Vector3d> positions{Eigen::Vector3d(271.5, 0.0, 0.0)};
  const RigidCasing gapped(positions, {{0, 1, 2}}, CasingGap{CasingGapKind::constant, 0.1}, kOmega,
                           kOmega);
  EXPECT_THROW(SolidCasingPart(gapped, 3, kDt, surface, s.basis_casing_dofs, s.basis, {}),
               std::invalid_argument);
  // A tip past the surface's axial end (the ring is 60 mm wide about z = 0).
  const RigidCasing off({Eigen::Vector3d(271.5, 0.0, 80.0)}, {{0, 1, 2}}, CasingGap{}, kOmega,
                        kOmega);
  EXPECT_THROW(SolidCasingPart(off, 3, kDt, surface, s.basis_casing_dofs, s.basis, {}),
               ComponentIntegrationError);
}

} // namespace
} // namespace rsi

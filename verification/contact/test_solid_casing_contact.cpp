// Blade tips against the flexible solid casing (reference/contact/
// solid_casing_contact.hpp, issue 27 item 3), on the CI casing's deck
// (data/cases/casing3d-ci.json, meshed by gmsh into the build's cache; its
// dofs numbered here, no ccx needed) and 24 tips at radius 271.5 mm, 0.5 mm
// inside the casing's 272 mm, at heights -25 .. 25 mm, turning at 1344 rad/s.
// Each check against arithmetic, or against the rigid casing's law:
// - the law is linear in the correction: g and s of u~ + du are g~ + G du
//   and s~ + T du (the rows are exact), to the sums' rounding;
// - with the casing at rest, the tip's gap, slip and rows are
//   RigidSurfaceContact's with g0 = rho - r (the casing's radius under the
//   tip minus the tip's) and the same speed;
// - both moved by one rigid translation d (the casing by d, the tip by d
//   seen in its turned frame) keep the gap at rest and slide by r Omega dt
//   only;
// - every row's force B^T lambda sums to zero over tip and casing in the
//   casing's frame (action = reaction: sum N_i = 1);
// - the point found lies on the tip's ray at its angle phi + Omega t.
// Skipped without gmsh.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "case_file.hpp"
#include "component_case.hpp"
#include "gmsh_blade_fit.hpp"
#include "solid_casing_contact.hpp"

namespace rsi {
namespace {

constexpr double kOmega = 1344.0, kTipRadius = 271.5;

struct CasingAndTips {
  CalculixDeck deck;
  std::map<int, std::array<int, 3>> casing_dofs;
  std::vector<RigidSurfaceNode> tips;
  int n_dofs = 0;
};

CasingAndTips setup() {
  const std::string case_path = std::string(RSI_SOURCE_DIR) + "/data/cases/casing3d-ci.json";
  const ComponentCase c = parse_component_case(read_case_document(case_path), case_path);
  ComponentLoadOptions options;
  const char* cache = std::getenv("RSI_CCX_CACHE");
  options.ccx_cache = cache && *cache ? cache : RSI_BINARY_DIR "/ccx-cache";
  CasingAndTips s;
  s.deck = component_deck(c, options).deck;
  // The tips first (3 dofs each), then every casing node off the flange.
  const int n_tips = 24;
  for (int k = 0; k < n_tips; ++k) {
    RigidSurfaceNode tip;
    const double phi = -M_PI + 2.0 * M_PI * (k + 0.31) / n_tips;
    tip.position = Eigen::Vector3d(kTipRadius * std::cos(phi), kTipRadius * std::sin(phi),
                                   -25.0 + 50.0 * k / (n_tips - 1));
    tip.dofs = {3 * k, 3 * k + 1, 3 * k + 2};
    s.tips.push_back(tip);
  }
  const std::vector<int>& flange = s.deck.nsets.at("FLANGE");
  const std::set<int> clamped(flange.begin(), flange.end());
  int next = 3 * n_tips;
  for (const ComponentNode& node : s.deck.nodes)
    if (!clamped.count(node.id)) {
      s.casing_dofs[node.id] = {next, next + 1, next + 2};
      next += 3;
    }
  s.n_dofs = next;
  return s;
}

#define SKIP_WITHOUT_GMSH()                                                                        \
  if (const std::string missing = testing::missing_programs({"gmsh"}); !missing.empty()) {         \
    std::printf("not run: %s not on PATH (Debian gmsh)\n", missing.c_str());                       \
    GTEST_SKIP() << missing << " not on PATH";                                                     \
  }

double dot(const SparseRow& row, const Eigen::VectorXd& x) {
  double sum = 0.0;
  for (const auto& [dof, value] : row)
    sum += value * x(dof);
  return sum;
}

TEST(SolidCasingContact, LinearInTheCorrection) {
  SKIP_WITHOUT_GMSH();
  const CasingAndTips s = setup();
  const SolidCasingContact law(s.tips, CasingSurface(s.deck, "SINNER"), s.casing_dofs, kOmega, 0.1);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1e-2, 1e-2); // mm
  Eigen::VectorXd current(s.n_dofs), predicted(s.n_dofs), du(s.n_dofs);
  for (int i = 0; i < s.n_dofs; ++i) {
    current(i) = u(random);
    predicted(i) = u(random);
    du(i) = u(random);
  }
  const double t = 1.234e-3, dt = 1e-6;
  FrictionalContactGeometry at, moved;
  law.evaluate(current, predicted, t, dt, at);
  law.evaluate(current, predicted + du, t, dt, moved);
  double worst = 0.0;
  for (int c = 0; c < law.n_contacts(); ++c) {
    // Each a sum of at most 21 terms of 1e-2 mm (2 x 10^-2 x 21 eps x a few) on top of
    // rho - r ~ 0.5 mm: 1e-15 mm.
    worst =
        std::max(worst, std::abs(moved.normal_gap(c) - at.normal_gap(c) - dot(at.rows[3 * c], du)));
    for (int k = 0; k < 2; ++k)
      worst = std::max(worst, std::abs(moved.slip(2 * c + k) - at.slip(2 * c + k) -
                                       dot(at.rows[3 * c + 1 + k], du)));
  }
  EXPECT_LE(worst, 1e-15);
  std::printf("g, s of u~ + du = g~ + G du, s~ + T du within %.1e mm (24 tips)\n", worst);
}

TEST(SolidCasingContact, CasingAtRestIsTheRigidLaw) {
  SKIP_WITHOUT_GMSH();
  const CasingAndTips s = setup();
  const SolidCasingContact law(s.tips, CasingSurface(s.deck, "SINNER"), s.casing_dofs, kOmega, 0.1);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1e-2, 1e-2);
  Eigen::VectorXd current = Eigen::VectorXd::Zero(s.n_dofs), predicted = current;
  for (int i = 0; i < 3 * static_cast<int>(s.tips.size()); ++i) {
    current(i) = u(random);
    predicted(i) = u(random);
  }
  const double t = 2.5e-4, dt = 1e-6;
  FrictionalContactGeometry solid;
  law.evaluate(current, predicted, t, dt, solid);
  for (int c = 0; c < law.n_contacts(); ++c) {
    const double g0 = law.point(c, t).rho - kTipRadius;
    const RigidSurfaceContact rigid({s.tips[c]}, ImposedGap::constant(g0), kOmega, 0.1);
    FrictionalContactGeometry expected;
    rigid.evaluate(current, predicted, t, dt, expected);
    // The frames from atan2 and from x / r agree to a few ulp (1e-16); the
    // slips are sums of 1e-2 mm terms: 1e-15 mm. The gap: the law's r is
    // |(x, y)| of the tip's coordinates, 271.5 to an ulp there (5.7e-14 mm),
    // and rho - r cancels to 0.5 mm: 2 ulp of 272 mm, 1.2e-13 mm.
    EXPECT_NEAR(solid.normal_gap(c), expected.normal_gap(0), 1.2e-13) << "tip " << c;
    EXPECT_NEAR(solid.slip(2 * c), expected.slip(0), 1e-15) << "tip " << c;
    EXPECT_NEAR(solid.slip(2 * c + 1), expected.slip(1), 1e-15) << "tip " << c;
    for (int r = 0; r < 3; ++r) {
      const SparseRow& mine = solid.rows[3 * c + r];
      const SparseRow& theirs = expected.rows[r];
      for (const auto& [dof, value] : theirs) {
        double found = 0.0;
        for (const auto& [d, v] : mine)
          if (d == dof) found = v;
        EXPECT_NEAR(found, value, 1e-15) << "tip " << c << " row " << r << " dof " << dof;
      }
    }
  }
}

TEST(SolidCasingContact, RigidTranslationKeepsTheGapAndSlidesByROmegaDt) {
  SKIP_WITHOUT_GMSH();
  const CasingAndTips s = setup();
  const SolidCasingContact law(s.tips, CasingSurface(s.deck, "SINNER"), s.casing_dofs, kOmega, 0.1);
  const double t = 3.1e-3, dt = 1e-6;
  const Eigen::Vector3d d(0.03, -0.02, 0.01); // mm, in the casing's frame
  // The tip's displacement in its frame, turned by -Omega t from the casing's.
  const Eigen::Vector3d in_rotor = Eigen::AngleAxisd(-kOmega * t, Eigen::Vector3d::UnitZ()) * d;
  Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.n_dofs), moved = zero;
  for (const RigidSurfaceNode& tip : s.tips)
    for (int k = 0; k < 3; ++k)
      moved(tip.dofs[k]) = in_rotor(k);
  for (const auto& [id, dofs] : s.casing_dofs)
    for (int k = 0; k < 3; ++k)
      moved(dofs[k]) = d(k);
  FrictionalContactGeometry rest, translated;
  int checked = 0;
  law.evaluate(zero, zero, t, dt, rest);
  law.evaluate(zero, moved, t, dt, translated);
  for (int c = 0; c < law.n_contacts(); ++c) {
    // A face off the flange: sum N_i d = d (a clamped node has no dof to
    // move: the tips above faces that touch the flange are left out).
    const SurfacePoint p = law.point(c, t);
    bool free = true;
    for (const int id : law.surface().face_nodes(p.face))
      free = free && s.casing_dofs.count(id);
    if (!free) continue;
    ++checked;
    // |d| = 0.037 mm moved through sums of 7 terms: 1e-16 mm; 1e-15.
    EXPECT_NEAR(translated.normal_gap(c), rest.normal_gap(c), 1e-15) << "tip " << c;
    EXPECT_NEAR(translated.slip(2 * c), 0.0, 1e-15) << "tip " << c;
    EXPECT_NEAR(translated.slip(2 * c + 1), kTipRadius * kOmega * dt, 1e-15) << "tip " << c;
  }
  EXPECT_GE(checked, 20) << "too few tips above faces off the flange";
}

TEST(SolidCasingContact, ForcesBalanceAndTheFaceFollowsTheTip) {
  SKIP_WITHOUT_GMSH();
  const CasingAndTips s = setup();
  const SolidCasingContact law(s.tips, CasingSurface(s.deck, "SINNER"), s.casing_dofs, kOmega, 0.1);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.n_dofs);
  std::map<int, std::pair<int, int>> owner; // dof -> (casing node or -1 - tip, component)
  for (const auto& [id, dofs] : s.casing_dofs)
    for (int k = 0; k < 3; ++k)
      owner[dofs[k]] = {id, k};
  int checked = 0;
  for (const double t : {0.0, 7.7e-4, 4.2e-3}) {
    FrictionalContactGeometry g;
    law.evaluate(zero, zero, t, 1e-6, g);
    const Eigen::AngleAxisd turn(kOmega * t, Eigen::Vector3d::UnitZ());
    for (int c = 0; c < law.n_contacts(); ++c) {
      // The point lies on the tip's ray at phi + Omega t, height Z: X(xi,
      // eta) = rho e_r + Z e_z to 1e-12 mm (six positions of 277 mm at most
      // summed, 2 eps each: 7.4e-13 mm).
      const SurfacePoint p = law.point(c, t);
      const double theta =
          std::atan2(s.tips[c].position.y(), s.tips[c].position.x()) + kOmega * t;
      const std::array<double, 6> n = triangle6_shape_functions(p.xi, p.eta);
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int i = 0; i < 6; ++i)
        x += n[i] * law.surface().face_positions(p.face)[i];
      const Eigen::Vector3d on_ray(p.rho * std::cos(theta), p.rho * std::sin(theta),
                                   s.tips[c].position.z());
      EXPECT_LE((x - on_ray).norm(), 1e-12) << "tip " << c << " at t = " << t;
      for (int r = 0; r < 3; ++r) {
        Eigen::Vector3d on_tip = Eigen::Vector3d::Zero(), on_casing = Eigen::Vector3d::Zero();
        for (const auto& [dof, value] : g.rows[3 * c + r]) {
          if (dof < 3 * static_cast<int>(s.tips.size()))
            on_tip(dof % 3) += value;
          else
            on_casing(owner.at(dof).second) += value;
        }
        // Free faces only (a clamped node takes its share of the reaction).
        bool free = true;
        for (const int id : law.surface().face_nodes(p.face))
          free = free && s.casing_dofs.count(id);
        if (!free) continue;
        ++checked;
        EXPECT_LE((turn * on_tip + on_casing).norm(), 1e-15) << "tip " << c << " row " << r;
      }
    }
  }
  EXPECT_GE(checked, 3 * 3 * 20) << "too few tips above faces off the flange";
}

TEST(SolidCasingContact, Refusals) {
  SKIP_WITHOUT_GMSH();
  const CasingAndTips s = setup();
  const CasingSurface surface(s.deck, "SINNER");
  std::vector<RigidSurfaceNode> tips = s.tips;
  tips[3].position.z() = 40.0; // the casing spans |z| <= 30
  EXPECT_THROW(SolidCasingContact(tips, surface, s.casing_dofs, kOmega, 0.1),
               std::invalid_argument);
  tips = s.tips;
  tips[2].dofs[0] = tips[1].dofs[2];
  EXPECT_THROW(SolidCasingContact(tips, surface, s.casing_dofs, kOmega, 0.1),
               std::invalid_argument);
  EXPECT_THROW(SolidCasingContact(s.tips, surface, s.casing_dofs, kOmega, -0.1),
               std::invalid_argument);
  try {
    SolidCasingContact(tips, surface, s.casing_dofs, kOmega, 0.1);
    ADD_FAILURE() << "a dof used twice: accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("used twice"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace rsi

// The 3D node-to-rigid-surface contact law (SPEC §8; issue 12 item 1;
// shared/external/rotor37/README.md): contact frame, imposed oval gap,
// casing sliding, the per-step gap, slip increment and rows, and one step
// of the frictional problem on it against its closed form.

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "frictional_contact_problem.hpp"
#include "frictional_contact_solver.hpp"
#include "rigid_surface_contact.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// Nodes at the given positions, dofs 3c, 3c + 1, 3c + 2 (+ offset).
std::vector<RigidSurfaceNode> nodes_at(const std::vector<Eigen::Vector3d>& x, int offset = 0) {
  std::vector<RigidSurfaceNode> nodes;
  for (std::size_t c = 0; c < x.size(); ++c) {
    RigidSurfaceNode n;
    for (int k = 0; k < 3; ++k)
      n.dofs[k] = offset + 3 * static_cast<int>(c) + k;
    n.position = x[c];
    nodes.push_back(n);
  }
  return nodes;
}

/// Blade-tip-like nodes of Rotor 37's size [mm] in all four quadrants.
std::vector<Eigen::Vector3d> positions() {
  return {{250.0, 10.0, -3.0},
          {-40.0, 246.0, 12.0},
          {-180.0, -170.0, 0.5},
          {0.0, -251.0, 7.0},
          {123.4, -219.9, -1.0}};
}

TEST(RigidSurfaceContact, FrameOrthonormalRightHanded) {
  const RigidSurfaceContact law(nodes_at(positions()), ImposedGap::constant(0.1), 1344.0, 0.15);
  for (int c = 0; c < law.n_contacts(); ++c) {
    const ContactFrame& f = law.frame(c);
    const Eigen::Vector3d& x = law.node(c).position;
    Eigen::Matrix3d e;
    e << f.normal, f.tangent1, f.tangent2;
    const double orthonormality = (e.transpose() * e - Eigen::Matrix3d::Identity()).norm();
    const double handedness = e.determinant() - 1.0;
    const Eigen::Vector3d radial(x(0), x(1), 0.0);
    const double inward = (f.normal + radial.normalized()).norm();
    const Eigen::Vector3d along(-std::sin(f.angle), std::cos(f.angle), 0.0);
    std::printf("node %d: r %.6f phi %.6f, |E^T E - I| %.2e, det - 1 %.2e, |e_n + x^| %.2e, "
                "|e_t2 - (-sin, cos, 0)| %.2e\n",
                c, f.radius, f.angle, orthonormality, handedness, inward,
                (f.tangent2 - along).norm());
    // e_n = -(x, y, 0)/r: two divisions by r = hypot(x, y) (hypot within 1
    // ulp): each component within 2 eps relative, so |e_n|^2 - 1 within 4 eps
    // and the Frobenius norm of E^T E - I (9 entries, e_t1 exact, e_t2 a
    // permutation of e_n's components) within 3 * 4 eps = 12 eps.
    EXPECT_LE(orthonormality, 12 * eps);
    // det[e_n, e_t1, e_t2] = (e_n x e_t1) . e_t2 = |e_t2|^2: within 4 eps of 1.
    EXPECT_LE(std::abs(handedness), 4 * eps);
    // The README's e_n = -(x, y, 0)/|(x, y)|: two normalisations, 2 eps each
    // component, sqrt(2) * 4 eps in norm; 8 eps.
    EXPECT_LE(inward, 8 * eps);
    EXPECT_EQ(f.tangent1, Eigen::Vector3d::UnitZ()); // the README's axial e_t1, exact
    // e_t2 = (-sin phi, cos phi, 0) with phi = atan2(y, x): atan2, sin, cos
    // within 1 ulp each (glibc), 2 eps per component against y/r, x/r: 8 eps.
    EXPECT_LE((f.tangent2 - along).norm(), 8 * eps);
    // Along the rotation (Omega > 0 counter-clockwise about z): z . (x^ x e_t2) = 1.
    EXPECT_GT(radial.cross(f.tangent2).z(), 0.0);
  }
}

TEST(RigidSurfaceContact, OvalGapPeriodMinimumSymmetry) {
  const double gm = 0.356, w = 0.15, omega = 1344.0; // the README's rubbing case [mm, rad/s]
  const ImposedGap gap = ImposedGap::oval(gm);
  // Minimum -g_m at mod(theta, pi) = pi/2: x = 0, exp(0) = 1, g = g_m (1 - 2)
  // exactly (pi/2 and (pi/2)/pi = 1/2 are exact in binary).
  EXPECT_EQ(gap(M_PI / 2), -gm);
  EXPECT_EQ(gap(M_PI / 2 - 3 * M_PI), -gm); // negative theta: floored modulo
  // Maximum at the ends of the period: g_m (1 - 2 exp(-1/(4 w^2))), a few
  // roundings (a subtraction, a division, a square, exp within 1 ulp, a
  // product): 8 eps relative.
  const double end = gm * (1.0 - 2.0 * std::exp(-1.0 / (4 * w * w)));
  std::printf("g(0) = %.17g, closed form %.17g\n", gap(0.0), end);
  EXPECT_LE(std::abs(gap(0.0) - end), 8 * eps * gm);
  // Every value in [-g_m, g(0)]: 1 - 2 exp(-x^2) >= -1 with exp <= 1 exactly.
  double lowest = 1.0, highest = -1.0;
  for (int i = -4000; i <= 4000; ++i) {
    const double theta = 1e-3 * i;
    lowest = std::min(lowest, gap(theta));
    highest = std::max(highest, gap(theta));
    // Even in theta: mod(-theta, pi) = pi - mod(theta, pi) gives x -> -x
    // (a truncated fmod would not). mod is exact (Sterbenz) up to the
    // rounding of pi floor(theta/pi), so |x| differs by ~2 eps |theta| /
    // (pi w); |dg/dx| = 4 g_m |x| exp(-x^2) <= 4 g_m / sqrt(2e) = 1.72 g_m:
    // |g(-theta) - g(theta)| <= 1.72 g_m (4 eps (|theta| + pi)/(pi w) + 8 eps).
    const double bound = 1.72 * gm * (4 * eps * (std::abs(theta) + M_PI) / (M_PI * w) + 8 * eps);
    EXPECT_LE(std::abs(gap(-theta) - gap(theta)), bound) << "theta " << theta;
  }
  std::printf("sampled range [%.17g, %.17g]\n", lowest, highest);
  EXPECT_GE(lowest, -gm);
  EXPECT_LE(highest, end + 8 * eps * gm); // g(0) is the maximum (the closed form above)

  // Period pi/Omega in time, through the law (node at phi = atan2(y, x)).
  const RigidSurfaceContact law(nodes_at(positions()), gap, omega, 0.15);
  const double period = M_PI / omega;
  double worst = 0.0, worst_bound = 0.0;
  for (int c = 0; c < law.n_contacts(); ++c)
    for (int i = 0; i < 50; ++i) {
      const double t = 1.37e-4 * i;
      const double difference = std::abs(law.imposed_gap(c, t + period) - law.imposed_gap(c, t));
      // theta = Omega t + phi: its rounding (3 eps |theta| for t + period,
      // Omega t, + phi) moves x by 3 eps |theta|/(pi w) on each side, plus
      // the modulo as above: |dg/dx| <= 1.72 g_m.
      const double theta = std::abs(omega * (t + period)) + M_PI;
      const double bound = 1.72 * gm * (2 * 5 * eps * theta / (M_PI * w) + 8 * eps);
      EXPECT_LE(difference, bound) << "node " << c << " t " << t;
      worst = std::max(worst, difference);
      worst_bound = std::max(worst_bound, bound);
    }
  std::printf("period pi/Omega: worst |g(t + T) - g(t)| = %.3e mm (bound %.3e)\n", worst,
              worst_bound);
  // Half a period later the gap is not the same (it is not a shorter period).
  EXPECT_GT(std::abs(law.imposed_gap(0, 0.5 * period) - law.imposed_gap(0, 0.0)), 0.1 * gm);
  // The minimum of node c falls at Omega t + phi_c = pi/2: each node meets it at its own time.
  const ContactFrame& f = law.frame(1);
  const double t_min = (M_PI / 2 - f.angle) / omega;
  EXPECT_LE(std::abs(law.imposed_gap(1, t_min) + gm), 1.72 * gm * 8 * eps * M_PI / (M_PI * w));
}

TEST(RigidSurfaceContact, StepGapSlipAndRows) {
  const double omega = 1344.0, dt = 2 * M_PI / omega / 1000; // 1000 steps a revolution
  const double g0 = 0.05;
  const int offset = 7; // the nodes' dofs inside a larger system vector
  const RigidSurfaceContact law(nodes_at(positions(), offset), ImposedGap::constant(g0), omega,
                                0.15);
  const int n = offset + 3 * law.n_contacts() + 4;
  FrictionalContactGeometry geo;

  // A node at rest: g~ = g0 and s~ = (0, +r Omega dt) (the casing moves by
  // -r Omega dt along e_t2). r Omega dt: two roundings, 2 eps relative.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  law.evaluate(zero, zero, 1.0, dt, geo);
  ASSERT_EQ(geo.normal_gap.size(), law.n_contacts());
  ASSERT_EQ(geo.slip.size(), 2 * law.n_contacts());
  ASSERT_EQ(geo.rows.size(), 3u * law.n_contacts());
  for (int c = 0; c < law.n_contacts(); ++c) {
    const ContactFrame& f = law.frame(c);
    const double expected = f.radius * omega * dt;
    std::printf("node %d at rest: s~ = (%.3e, %.17g), r Omega dt = %.17g mm\n", c, geo.slip(2 * c),
                geo.slip(2 * c + 1), expected);
    EXPECT_EQ(geo.normal_gap(c), g0);
    EXPECT_EQ(geo.slip(2 * c), 0.0);
    EXPECT_LE(std::abs(geo.slip(2 * c + 1) - expected), 2 * eps * expected);
    // The casing's velocity -r Omega e_t2, and the relative increment of the
    // node (at rest) against it, -v_casing dt, is +r Omega dt e_t2 (2 eps).
    const Eigen::Vector3d relative = -law.casing_velocity(c) * dt;
    EXPECT_LE((relative - expected * f.tangent2).norm(), 4 * eps * expected);
  }

  // Random u_n, u~: g~ = g0 + e_n . u~, s~ = (e_t1 . du, e_t2 . du + r Omega dt),
  // and the law is linear: at u~ + v, evaluate gives g~ + G v, s~ + T v.
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  Eigen::VectorXd un(n), up(n), v(n);
  for (int i = 0; i < n; ++i) {
    un(i) = u(rng);
    up(i) = un(i) + 0.01 * u(rng);
    v(i) = 0.01 * u(rng);
  }
  law.evaluate(un, up, 0.3, dt, geo);
  FrictionalContactGeometry moved;
  law.evaluate(un, up + v, 0.3, dt, moved);
  for (int c = 0; c < law.n_contacts(); ++c) {
    const ContactFrame& f = law.frame(c);
    const Eigen::Vector3d x_next = up.segment<3>(offset + 3 * c);
    const Eigen::Vector3d increment = x_next - un.segment<3>(offset + 3 * c);
    // Sums of 3 products and one more term: gamma_4 of the magnitudes of
    // the terms (0.11 mm displacements, 0.05 mm gap, r Omega dt <= 1.6 mm):
    // 4 eps * 2 mm.
    const double tol = 4 * eps * 2.0;
    EXPECT_LE(std::abs(geo.normal_gap(c) - (g0 + f.normal.dot(x_next))), tol);
    EXPECT_LE(std::abs(geo.slip(2 * c) - f.tangent1.dot(increment)), tol);
    EXPECT_LE(std::abs(geo.slip(2 * c + 1) - (f.tangent2.dot(increment) + f.radius * omega * dt)),
              tol);
    // Rows: e_n, e_t1, e_t2 on the node's dofs, nothing else.
    const Eigen::Vector3d* expected[3] = {&f.normal, &f.tangent1, &f.tangent2};
    for (int i = 0; i < 3; ++i) {
      Eigen::VectorXd dense = Eigen::VectorXd::Zero(n);
      for (const auto& [dof, value] : geo.rows[3 * c + i])
        dense(dof) += value;
      EXPECT_EQ(dense.segment<3>(offset + 3 * c), *expected[i]);
      EXPECT_EQ(dense.norm(), expected[i]->norm());
    }
    // Linearity: the moved state's gap and slip are g~ + G v and s~ + T v.
    EXPECT_LE(std::abs(moved.normal_gap(c) - (geo.normal_gap(c) + dot(geo.rows[3 * c], v))),
              2 * tol);
    for (int k = 0; k < 2; ++k)
      EXPECT_LE(
          std::abs(moved.slip(2 * c + k) - (geo.slip(2 * c + k) + dot(geo.rows[3 * c + 1 + k], v))),
          2 * tol);
  }
  // Moving a node along e_n opens its gap by the distance moved; along -e_n closes it.
  Eigen::VectorXd pushed = zero;
  pushed.segment<3>(offset) = 0.02 * law.frame(0).normal;
  law.evaluate(zero, pushed, 1.0, dt, geo);
  EXPECT_NEAR(geo.normal_gap(0), g0 + 0.02, 4 * eps * 0.07); // |e_n|^2 = 1 within 4 eps
  pushed.segment<3>(offset) = -0.02 * law.frame(0).normal;
  law.evaluate(zero, pushed, 1.0, dt, geo);
  EXPECT_NEAR(geo.normal_gap(0), g0 - 0.02, 4 * eps * 0.07);
}

// One step of the frictional problem on the law: one node of mass m (M = m
// I), pressed into the casing (g~ < 0) while the casing slides past it.
// B's rows are orthonormal, so W = dt^2/m I: lambda_n = -g~ m/dt^2; the
// stick trial -s~ m/dt^2 has |s~| = r Omega dt >> mu |g~|, so the node
// slips, and the friction force lambda_t2 e_t2 = -mu lambda_n e_t2 on the
// node points along the casing's velocity -r Omega e_t2: the casing drags
// the tip with it.
TEST(RigidSurfaceContact, OneStepSlipDragsNodeWithCasing) {
  const double omega = 1344.0, dt = 1e-6, mass = 1e-6, mu = 0.15; // [rad/s, s, t]
  const std::vector<Eigen::Vector3d> x = {{-180.0, -170.0, 0.5}};
  const RigidSurfaceContact law(nodes_at(x), ImposedGap::constant(-1e-4), omega, mu);
  FrictionalContactGeometry geo;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3);
  law.evaluate(zero, zero, dt, dt, geo);
  Eigen::Matrix3d b;
  for (int i = 0; i < 3; ++i) {
    b.row(i).setZero();
    for (const auto& [dof, value] : geo.rows[i])
      b(i, dof) = value;
  }
  const Eigen::Matrix3d w = (dt * dt / mass) * b * b.transpose();
  const FrictionalContactProblem p(2, mu, 0.5 * (w + w.transpose()), geo.normal_gap, geo.slip);
  const FrictionalContactSolution sol = FrictionalContactSolver().solve(p);
  ASSERT_TRUE(sol.ok()) << sol.message;
  const FrictionalContactCertificate cert = certify(p, sol.lambda);
  const double lambda_n = 1e-4 * mass / (dt * dt); // 100 N
  std::printf("lambda = (%.17g, %.3e, %.17g) N, closed form (%.17g, 0, %.17g); %s\n", sol.lambda(0),
              sol.lambda(1), sol.lambda(2), lambda_n, -mu * lambda_n, cert.summary().c_str());
  EXPECT_EQ(cert.classes[0], ContactClass::slip);
  // W = dt^2/m B B^T with B orthonormal to 12 eps (frame test): W = dt^2/m
  // (I + E), |E| <= 12 eps; lambda_n = -g~/W_nn to 12 eps + the solver's
  // 10 roundings (test_frictional_contact) = 22 eps relative; lambda_t adds
  // the solver's stopping level eta = 4 * 4 eps = 16 eps of Lambda: 38 eps.
  EXPECT_LE(std::abs(sol.lambda(0) - lambda_n), 22 * eps * lambda_n);
  EXPECT_LE(std::abs(sol.lambda(1)), 38 * eps * lambda_n);
  EXPECT_LE(std::abs(sol.lambda(2) + mu * lambda_n), 38 * eps * lambda_n);
  // The force on the node, B^T lambda, against the casing's velocity: same
  // direction in the tangent plane.
  const Eigen::Vector3d force = b.transpose() * sol.lambda;
  const Eigen::Vector3d tangential = force - force.dot(law.frame(0).normal) * law.frame(0).normal;
  EXPECT_GT(tangential.dot(law.casing_velocity(0)), 0.0);
}

// The rotation direction (data/README.md rubbing.rotation_speed and
// tip_sliding): a node at rest slides by +r Omega_s dt along e_t2 with
// Omega_s = Omega (with the rotation) or -Omega (against it, NLstep's
// PLAUSIBLE set-up); the gap phase is Omega t + phi for either sign of
// Omega. Source: the header's s~ and g0 formulas; tolerances as in
// StepGapSlipAndRows (r Omega dt: 2 eps relative; theta: exact inputs).
TEST(RigidSurfaceContact, RotationDirectionAndSlidingSign) {
  const double omega = 1344.0, dt = 2 * M_PI / omega / 1000;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3 * static_cast<int>(positions().size()));
  FrictionalContactGeometry geo;
  struct Case {
    double omega, sliding, sign; // sign of the expected s~_t2 / (r |Omega| dt)
    const char* name;
  };
  const Case cases[] = {{omega, omega, +1.0, "counter-clockwise, with the rotation"},
                        {omega, -omega, -1.0, "counter-clockwise, against (NLstep)"},
                        {-omega, -omega, -1.0, "clockwise, with the rotation"},
                        {-omega, omega, +1.0, "clockwise, against"}};
  for (const Case& k : cases) {
    const RigidSurfaceContact law(nodes_at(positions()), ImposedGap::constant(0.05), k.omega, 0.15,
                                  k.sliding);
    EXPECT_EQ(law.sliding_speed(), k.sliding);
    law.evaluate(zero, zero, 1.0, dt, geo);
    for (int c = 0; c < law.n_contacts(); ++c) {
      const ContactFrame& f = law.frame(c);
      const double expected = k.sign * f.radius * omega * dt;
      EXPECT_LE(std::abs(geo.slip(2 * c + 1) - expected), 2 * eps * std::abs(expected)) << k.name;
      EXPECT_LE((law.casing_velocity(c) * dt + expected * f.tangent2).norm(),
                4 * eps * std::abs(expected))
          << k.name;
    }
    std::printf("%s: node 0 at rest slides s~_t2 = %+.17g mm a step\n", k.name, geo.slip(1));
  }
  // Gap phase theta = Omega t + phi: the oval's minimum -g_m at theta = pi/2
  // is met at t = (pi/2 - phi)/Omega for Omega > 0 and at (-pi/2 - phi)/Omega
  // for Omega < 0 (theta = -pi/2 = pi/2 mod pi), whatever Omega_s.
  const double gm = 0.356;
  for (double w : {omega, -omega})
    for (double sliding : {w, -w}) {
      const RigidSurfaceContact law(nodes_at(positions()), ImposedGap::oval(gm), w, 0.15, sliding);
      for (int c = 0; c < law.n_contacts(); ++c) {
        const double phi = law.frame(c).angle;
        const double t = (w > 0 ? M_PI / 2 - phi : -M_PI / 2 - phi) / w + 2 * M_PI / omega;
        // theta rounded in t, Omega t, + phi (3 eps |theta| <= 3 eps 12):
        // x = (mod/pi - 1/2)/w moves by 36 eps/(pi 0.15); g - (-g_m) =
        // 2 g_m (1 - exp(-x^2)) <= 2 g_m x^2: far below 1e-20.
        EXPECT_NEAR(law.imposed_gap(c, t), -gm, 1e-20 + 8 * eps * gm) << "Omega " << w;
      }
    }
}

TEST(RigidSurfaceContact, RejectsBadArguments) {
  const std::vector<Eigen::Vector3d> x = {{250.0, 10.0, 0.0}};
  EXPECT_THROW(RigidSurfaceContact({}, ImposedGap::constant(0.1), 1.0, 0.1), std::invalid_argument);
  EXPECT_THROW(
      RigidSurfaceContact(nodes_at({{0.0, 0.0, 3.0}}), ImposedGap::constant(0.1), 1.0, 0.1),
      std::invalid_argument); // on the axis
  EXPECT_THROW(RigidSurfaceContact(nodes_at(x), ImposedGap::oval(0.0), 1.0, 0.1),
               std::invalid_argument);
  EXPECT_THROW(RigidSurfaceContact(nodes_at(x), ImposedGap::oval(0.3, -1.0), 1.0, 0.1),
               std::invalid_argument);
  EXPECT_THROW(RigidSurfaceContact(nodes_at(x), ImposedGap::constant(NAN), 1.0, 0.1),
               std::invalid_argument);
  EXPECT_THROW(RigidSurfaceContact(nodes_at(x), ImposedGap::constant(0.1), INFINITY, 0.1),
               std::invalid_argument);
  EXPECT_THROW(RigidSurfaceContact(nodes_at(x), ImposedGap::constant(0.1), 1.0, 0.1, NAN),
               std::invalid_argument);
  EXPECT_THROW(RigidSurfaceContact(nodes_at(x), ImposedGap::constant(0.1), 1.0, -0.1),
               std::invalid_argument);
  std::vector<RigidSurfaceNode> twice = nodes_at({{250.0, 10.0, 0.0}, {0.0, 250.0, 0.0}});
  twice[1].dofs[2] = twice[0].dofs[0];
  EXPECT_THROW(RigidSurfaceContact(twice, ImposedGap::constant(0.1), 1.0, 0.1),
               std::invalid_argument);
  std::vector<RigidSurfaceNode> negative = nodes_at(x);
  negative[0].dofs[1] = -1;
  try {
    RigidSurfaceContact(negative, ImposedGap::constant(0.1), 1.0, 0.1);
    ADD_FAILURE() << "a negative dof was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("allowed"), std::string::npos) << e.what();
  }
  const RigidSurfaceContact law(nodes_at(x), ImposedGap::constant(0.1), 1.0, 0.1);
  FrictionalContactGeometry geo;
  const Eigen::VectorXd three = Eigen::VectorXd::Zero(3), two = Eigen::VectorXd::Zero(2);
  EXPECT_THROW(law.evaluate(three, three, 0.0, 0.0, geo), std::invalid_argument); // dt
  EXPECT_THROW(law.evaluate(three, two, 0.0, 1e-6, geo), std::invalid_argument);  // sizes
  EXPECT_THROW(law.evaluate(two, two, 0.0, 1e-6, geo), std::invalid_argument);    // dof outside
  EXPECT_THROW(law.dofs_read(2), std::invalid_argument);
  EXPECT_EQ(law.dofs_read(3), (std::vector<int>{0, 1, 2}));
}

TEST(RigidSurfaceContact, NodesFromComponent) {
  Component c;
  c.name = "tiny";
  // Node 5: dofs 0..2; node 9: dofs 3, 4 (no uz); node 12: dofs 5..7 listed uz, ux, uy.
  c.dofs = {{5, "ux", false}, {5, "uy", false},  {5, "uz", false},  {9, "ux", false},
            {9, "uy", false}, {12, "uz", false}, {12, "ux", false}, {12, "uy", false}};
  c.nodes = {{5, Eigen::Vector3d(1.0, 2.0, 3.0)},
             {9, Eigen::Vector3d(4.0, 5.0, 6.0)},
             {12, Eigen::Vector3d(-7.0, 8.0, 9.0)}};
  const std::vector<RigidSurfaceNode> nodes = rigid_surface_nodes(c, {12, 5}, 100);
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_EQ(nodes[0].dofs, (std::array<int, 3>{{106, 107, 105}}));
  EXPECT_EQ(nodes[0].position, Eigen::Vector3d(-7.0, 8.0, 9.0));
  EXPECT_EQ(nodes[1].dofs, (std::array<int, 3>{{100, 101, 102}}));
  EXPECT_THROW(rigid_surface_nodes(c, {9}), std::invalid_argument); // no uz
  EXPECT_THROW(rigid_surface_nodes(c, {7}), std::invalid_argument); // not a node
  EXPECT_THROW(rigid_surface_nodes(c, {5}, -1), std::invalid_argument);
}

} // namespace
} // namespace rsi

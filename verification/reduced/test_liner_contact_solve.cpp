// The reduced solver's contact solve with an abradable liner
// (reduced/liner_contact_solve) against three independent answers:
//  1. a diagonal W with equal entries on a node's rows (a lumped mass) is the
//     full-order run's node-by-node problem: each node's bar by the
//     reference kernel's compliant solve (reference/contact/abradable_liner),
//     Coulomb by the stick multiplier -s~/w projected on the disk, two nodes
//     over one cell in turn (docs/decisions.md, "The abradable liner");
//  2. a dense W, mu = 0 and bars that stay elastic: the problem is the linear
//     complementarity problem (W_nn + I/k) lambda + g~ + p >= 0, lambda >= 0,
//     complementary, solved by enumerating the active sets;
//  3. a dense W, mu > 0 and yielding bars: the certificate (bar law, cone,
//     stick and slip residuals) at round-off;
// and the rigid limit: bars of huge stiffness and yield give the rigid
// casing's multipliers (reduced/coulomb_node_solve) to within the bars'
// compliance. Then the tip patch (liner_patch_cells.hpp): with a diagonal W
// each node's multiplier satisfies the patch's bar law (the sum over its
// cells, chained) at the final gap, the plastic work is its closed form from
// the final wear, and a patch of zero width is the one-cell solve bit for bit.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "abradable_liner.hpp"
#include "component_integration_error.hpp"
#include "coulomb_node_solve.hpp"
#include "liner_contact_solve.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

AbradableCellsGeometry geometry() {
  AbradableCellsGeometry g;
  g.radius = 250.0;
  g.thickness = 2.0;
  g.n_theta = 8;
  g.n_axial = 1;
  g.z_min = -10.0;
  g.z_max = 10.0;
  return g;
}

AbradableCellsMaterial material(double young = 1000.0, double yield = 10.0) {
  AbradableCellsMaterial m;
  m.young = young;
  m.yield = yield;
  m.hardening = 300.0;
  return m;
}

/// nc nodes, node c at angle phi[c] (sector floor(phi / (pi/4))), all in row 0.
LinerContactLayout layout(const std::vector<double>& phi) {
  LinerContactLayout l;
  l.polar_angle = phi;
  l.axial.assign(phi.size(), 0.0);
  l.omega = 0.0;
  return l;
}

/// A symmetric positive definite 3 nc square W of unit-order entries with
/// strong coupling between nodes.
Eigen::MatrixXd dense_w(int nc, unsigned seed, double scale) {
  std::srand(seed);
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(3 * nc, 3 * nc);
  return scale * (a * a.transpose() / (3.0 * nc) + 0.2 * Eigen::MatrixXd::Identity(3 * nc, 3 * nc));
}

TEST(LinerContactSolve, DiagonalWIsTheFullOrderNodeByNodeSolve) {
  const double mu = 0.3;
  // Nodes 1 and 2 share sector 1; nodes 0 and 3 are alone.
  const std::vector<double> phi = {0.1, 1.0, 1.2, 3.0};
  const int nc = 4;
  const AbradableCellsMaterial mat = material();
  LinerContactSolve solve(nc, 1e-3, mu, AbradableCells(geometry(), mat), layout(phi));
  // c k from 0.2 to 2 (k = 1.96e6 N/mm): the bars yield under the predictions below.
  const Eigen::VectorXd w_node = (Eigen::VectorXd(4) << 1e-7, 4e-7, 2e-7, 1e-6).finished();
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(3 * nc, 3 * nc);
  for (int c = 0; c < nc; ++c) w.block(3 * c, 3 * c, 3, 3).diagonal().setConstant(w_node(c));
  solve.set_contact_matrix(w);

  LinerGeometry rg;
  rg.radius = 250.0;
  rg.thickness = 2.0;
  rg.n_theta = 8;
  rg.n_axial = 1;
  rg.z_min = -10.0;
  rg.z_max = 10.0;
  LinerMaterial rm;
  rm.young = mat.young;
  rm.yield = mat.yield;
  rm.hardening = mat.hardening;
  AbradableLiner liner(rg, rm);

  // Tolerance (derived in test_abradable_cells): 16 eps (1 + c k)
  // max(F, k delta~) for the reference's cancellations and 4 eps F a
  // plastic step for the cells' states rounding apart; here also the
  // indentation delta~ = -g~ - p, formed by each solve its own way (the
  // reduced one through y = g~ + W lambda, less W_nn lambda), rounds at
  // eps (|g~| + p + c F), which the compliant map scales by k / (1 + c k):
  // plus 16 eps k (|g~| + p + c F) / (1 + c k).
  int plastic_steps = 0;
  std::srand(3);
  for (int step = 1; step <= 40; ++step) {
    Eigen::VectorXd predicted = Eigen::VectorXd::Random(3 * nc) * 0.05;
    for (int c = 0; c < nc; ++c) predicted(3 * c) -= 0.03; // mostly closing
    StepReport report;
    solve.solve(predicted, step, report);
    // The full-order run's per-node solve (central_difference.cpp, solve_liner).
    std::vector<std::pair<int, LinerBarResponse>> pending;
    for (int c = 0; c < nc; ++c) {
      const int cell = liner.angular_cell(phi[c]);
      LinerCellState state = liner.state(cell);
      for (const auto& [k, r] : pending)
        if (k == cell) state = r.state;
      const LinerBarResponse r =
          liner.compliant_force(state, -predicted(3 * c) - state.wear, w_node(c));
      pending.push_back({cell, r});
      Eigen::Vector2d lt = -predicted.segment<2>(3 * c + 1) / w_node(c);
      if (lt.norm() > mu * r.force) lt *= mu * r.force / lt.norm();
      const double f = std::max(r.force, 1e-300);
      const double k = solve.cells().stiffness();
      const double delta_pred = -predicted(3 * c) - state.wear;
      const double ck = w_node(c) * k;
      const double tolerance =
          16.0 * eps *
              ((1.0 + ck) * std::max(f, k * delta_pred) +
               k * (std::abs(predicted(3 * c)) + state.wear + w_node(c) * f) / (1.0 + ck)) +
          4.0 * plastic_steps * eps * f;
      EXPECT_NEAR(solve.lambda_next()(3 * c), r.force, tolerance) << "step " << step << " node " << c;
      EXPECT_NEAR((solve.lambda_next().segment<2>(3 * c + 1) - lt).norm(), 0.0, tolerance)
          << "step " << step << " node " << c;
    }
    for (const auto& [k, r] : pending) {
      plastic_steps += r.plastic;
      liner.commit(k, r);
    }
  }
  EXPECT_GT(liner.plastic_work(), 0.0);
  EXPECT_NEAR(solve.plastic_work(), liner.plastic_work(), 1e-12 * liner.plastic_work());
  for (int cell = 0; cell < 8; ++cell)
    EXPECT_NEAR(solve.cells().state(cell).wear, liner.state(cell).wear, 1e-12 * 0.05) << cell;
}

TEST(LinerContactSolve, DenseElasticFrictionlessIsTheLcp) {
  const int nc = 5;
  // One node per sector; a yield far above the forces: the bars stay elastic.
  const std::vector<double> phi = {0.1, 0.9, 1.7, 2.5, 3.3};
  AbradableCells cells(geometry(), material(1000.0, 1e9));
  const double k = cells.stiffness();
  const Eigen::MatrixXd w = dense_w(nc, 11, 1.0 / k); // W and 1/k of one order
  LinerContactSolve solve(nc, 1e-3, 0.0, cells, layout(phi));
  solve.set_contact_matrix(w);
  Eigen::MatrixXd wn(nc, nc);
  for (int i = 0; i < nc; ++i)
    for (int j = 0; j < nc; ++j) wn(i, j) = w(3 * i, 3 * j);
  std::srand(5);
  for (int trial = 0; trial < 30; ++trial) {
    Eigen::VectorXd predicted = Eigen::VectorXd::Random(3 * nc) * 0.01;
    StepReport report;
    solve.start();
    solve.solve(predicted, 1, report);
    // Enumerate the active sets of (W_nn + I/k) lambda + g~ >= 0 _|_ lambda >= 0.
    Eigen::VectorXd found;
    int solutions = 0;
    for (int set = 0; set < (1 << nc); ++set) {
      std::vector<int> a;
      for (int c = 0; c < nc; ++c)
        if (set & (1 << c)) a.push_back(c);
      Eigen::VectorXd lambda = Eigen::VectorXd::Zero(nc);
      if (!a.empty()) {
        Eigen::MatrixXd m(a.size(), a.size());
        Eigen::VectorXd rhs(a.size());
        for (size_t i = 0; i < a.size(); ++i) {
          rhs(i) = -predicted(3 * a[i]);
          for (size_t j = 0; j < a.size(); ++j) m(i, j) = wn(a[i], a[j]) + (i == j ? 1.0 / k : 0.0);
        }
        const Eigen::VectorXd la = m.lu().solve(rhs);
        for (size_t i = 0; i < a.size(); ++i) lambda(a[i]) = la(i);
      }
      Eigen::VectorXd g(nc);
      for (int c = 0; c < nc; ++c) g(c) = predicted(3 * c) + wn.row(c).dot(lambda) + lambda(c) / k;
      const double tol = 1e-12 * 0.01;
      if (lambda.minCoeff() >= 0.0 && g.minCoeff() >= -tol) {
        ++solutions;
        found = lambda;
      }
    }
    ASSERT_EQ(solutions, 1) << "trial " << trial; // a P-matrix: exactly one
    for (int c = 0; c < nc; ++c)
      EXPECT_NEAR(solve.lambda_next()(3 * c), found(c), 1e-10 * found.cwiseAbs().maxCoeff() + 1e-300)
          << "trial " << trial << " node " << c;
  }
}

/// 50 steps of random predictions pushed `push` into the liner, each
/// certified: the solve's own stopping rule puts the cone and stick/slip
/// residuals at round-off (header); W_plastic never decreases. Returns it.
double certified_random_steps(LinerContactSolve& solve, int nc, double push, unsigned seed,
                              double mu) {
  std::srand(seed);
  double plastic = 0.0;
  for (int step = 1; step <= 50; ++step) {
    Eigen::VectorXd predicted = Eigen::VectorXd::Random(3 * nc) * 0.05;
    for (int c = 0; c < nc; ++c) predicted(3 * c) -= push;
    StepReport report;
    solve.solve(predicted, step, report);
    EXPECT_LE(report.max_cone_violation, 1e-12 * solve.lambda_next().cwiseAbs().maxCoeff());
    EXPECT_LE(report.max_stick_slip_residual, 1e-9) << "mu " << mu << " step " << step;
    EXPECT_GE(solve.plastic_work(), plastic);
    plastic = solve.plastic_work();
  }
  return plastic;
}

TEST(LinerContactSolve, DenseYieldingWithFrictionCertifies) {
  const int nc = 6;
  const std::vector<double> phi = {0.1, 0.2, 1.7, 2.5, 3.3, 5.0}; // nodes 0, 1 share a bar
  AbradableCells cells(geometry(), material());
  const Eigen::MatrixXd w = dense_w(nc, 23, 0.5 / cells.stiffness());
  for (double mu : {0.05, 0.3}) {
    LinerContactSolve solve(nc, 1e-3, mu, cells, layout(phi));
    solve.set_contact_matrix(w);
    const double plastic = certified_random_steps(solve, nc, 0.02, 9, mu);
    EXPECT_LE(solve.max_law_residual(), 1e-10) << "mu " << mu;
    EXPECT_GT(plastic, 0.0);
  }
}

TEST(LinerContactSolve, StiffBarsAreTheRigidCasing) {
  const int nc = 4;
  const std::vector<double> phi = {0.1, 0.9, 1.7, 2.5};
  AbradableCells cells(geometry(), material(1e12, 1e12));
  const double k = cells.stiffness();
  const Eigen::MatrixXd w = dense_w(nc, 31, 1e-5);
  const double w_min = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(w).eigenvalues().minCoeff();
  for (double mu : {0.0, 0.2}) {
    LinerContactSolve liner(nc, 1e-3, mu, cells, layout(phi));
    CoulombNodeSolve rigid(nc, 1e-3, mu, CoulombGaussSeidelOptions{}, true);
    liner.set_contact_matrix(w);
    rigid.set_contact_matrix(w);
    std::srand(13);
    for (int step = 1; step <= 20; ++step) {
      Eigen::VectorXd predicted = Eigen::VectorXd::Random(3 * nc) * 0.01;
      StepReport a, b;
      liner.start();
      rigid.start();
      liner.solve(predicted, step, a);
      rigid.solve(predicted, step, b);
      // The bars add the compliance 1/k to each normal row: the multipliers
      // move by about |W^-1| / k of themselves (w_min: W's smallest
      // eigenvalue), a factor 10 for the friction's coupling.
      const double size = rigid.lambda_next().cwiseAbs().maxCoeff();
      EXPECT_LE((liner.lambda_next() - rigid.lambda_next()).cwiseAbs().maxCoeff(),
                10.0 / (k * w_min) * size + 1e-12 * size)
          << "mu " << mu << " step " << step;
    }
    EXPECT_EQ(liner.plastic_work(), 0.0);
  }
}

// The flexible casing's share of W, scale h h^T (reduced/solid_casing_part),
// given to CoulombNodeSolve as h (set_flexibility) and never formed whole,
// against the same W formed and set whole: the same contact states at every
// step, and multipliers that differ by what the two W's rounding allows.
// The two W differ entrywise by at most (m + 2) eps (W_rotor + |s| |h| |h|^T)
// (the product's m terms, the sum, the symmetrisation) and each solve stops
// at a relative change of 1e-14 (CoulombGaussSeidelOptions): |d lambda| <=
// cond(W) ((m + 2) eps + 1e-14) |lambda|, a factor 10 for the friction's
// coupling (as above). The certificate of the never-formed path, evaluated
// on the formed W, is at round-off (the solve's stopping rule).
TEST(CoulombNodeSolve, CasingShareNeverFormedIsTheFormedW) {
  const int nc = 8, m = 5;
  const double scale = 0.3;
  const Eigen::MatrixXd w_rotor = dense_w(nc, 41, 1.0);
  std::srand(43);
  const Eigen::MatrixXd h = Eigen::MatrixXd::Random(3 * nc, m);
  const Eigen::MatrixXd w_full = w_rotor + scale * h * h.transpose();
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(w_full).eigenvalues();
  const double cond = ev.maxCoeff() / ev.minCoeff();
  const double eps = std::numeric_limits<double>::epsilon();
  for (double mu : {0.0, 0.3}) {
    CoulombNodeSolve formed(nc, 1e-3, mu, CoulombGaussSeidelOptions{}, true);
    CoulombNodeSolve shared(nc, 1e-3, mu, CoulombGaussSeidelOptions{}, true);
    formed.set_contact_matrix(w_full);
    shared.set_contact_matrix(w_rotor);
    shared.set_flexibility(&h, scale);
    std::srand(47);
    double worst = 0.0;
    for (int step = 1; step <= 30; ++step) {
      Eigen::VectorXd predicted = Eigen::VectorXd::Random(3 * nc) * 0.05;
      for (int c = 0; c < nc; c += 2) predicted(3 * c) -= 0.03; // half of them closing
      StepReport a, b;
      formed.solve(predicted, step, a);
      shared.solve(predicted, step, b);
      ASSERT_EQ(formed.states(), shared.states()) << "mu " << mu << " step " << step;
      const double size = formed.lambda_next().cwiseAbs().maxCoeff();
      const double diff = (formed.lambda_next() - shared.lambda_next()).cwiseAbs().maxCoeff();
      worst = std::max(worst, diff / (10.0 * cond * ((m + 2) * eps + 1e-14) * size));
      EXPECT_LE(diff, 10.0 * cond * ((m + 2) * eps + 1e-14) * size) << "mu " << mu << " step " << step;
      const ReducedCoulombCertificate cert = reduced_coulomb_certificate(
          w_full, predicted, 2, mu, shared.lambda_next(), shared.states());
      EXPECT_LE(cert.max_cone_violation, 1e-12 * size);
      EXPECT_LE(cert.max_penetration, 1e-12 * predicted.cwiseAbs().maxCoeff());
      // The solve's own certificate (y = g~ + W lambda from W's active
      // columns and h h_A^T lambda_A) against the one on the formed W: y
      // summed in another order, |dy| <= (3 nc + m) eps (|W| + s|h||h|^T)|lambda|;
      // penetration and g lambda_n move by at most that (times |lambda_n|).
      const double dy = (3 * nc + m) * eps *
                        ((w_rotor.cwiseAbs() + scale * h.cwiseAbs() * h.cwiseAbs().transpose()) *
                         shared.lambda_next().cwiseAbs())
                            .maxCoeff();
      EXPECT_LE(std::abs(b.max_penetration - cert.max_penetration), dy);
      EXPECT_LE(std::abs(b.max_complementarity - cert.max_complementarity), dy * size);
    }
    std::printf("mu %.1f: cond(W) %.2f, multipliers within %.2e of the bound over 30 steps\n", mu,
                cond, worst);
  }
}

// The growth of the active set through the casing's share alone: W_rotor =
// I, h = e_n0 - e_n1 (scale 1), so W_n1n0 = -1: contact 0 closing (g~ = -1)
// pulls contact 1 (g~ = 0.2) shut. Exact (mu = 0): [2 -1; -1 2] lambda =
// [1; -0.2], lambda_n = (0.6, 0.2), both closed. Gauss-Seidel on this W
// contracts by rho = 1/4 a sweep: after a last change <= 1e-14 |lambda|
// (its stopping rule) the error is <= 1e-14 rho/(1 - rho) |lambda| < 1e-14,
// plus a few eps of rounding.
TEST(CoulombNodeSolve, CasingShareClosesAContactOutsideTheClosingOnes) {
  const int nc = 2;
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(3 * nc, 1);
  h(0, 0) = 1.0;
  h(3, 0) = -1.0;
  CoulombNodeSolve solve(nc, 1e-3, 0.0, CoulombGaussSeidelOptions{}, true);
  solve.set_contact_matrix(Eigen::MatrixXd::Identity(3 * nc, 3 * nc));
  solve.set_flexibility(&h, 1.0);
  Eigen::VectorXd predicted = Eigen::VectorXd::Zero(3 * nc);
  predicted(0) = -1.0;
  predicted(3) = 0.2;
  StepReport report;
  solve.solve(predicted, 1, report);
  const double tol = 1e-14 + 8 * std::numeric_limits<double>::epsilon();
  EXPECT_NEAR(solve.lambda_next()(0), 0.6, tol);
  EXPECT_NEAR(solve.lambda_next()(3), 0.2, tol);
  EXPECT_NE(solve.states()[1], ReducedContactState::open);
  EXPECT_LE(report.max_penetration, 2 * tol);
}

/// 64 sectors x 4 rows over [-10, 10] (r dtheta = 24.5, dz = 5; centres at
/// z = -7.5, -2.5, 2.5, 7.5): a patch of 60 x 8 covers 2 or 3 sectors and
/// 1 or 2 rows.
AbradableCellsGeometry fine_geometry() {
  AbradableCellsGeometry g = geometry();
  g.n_theta = 64;
  g.n_axial = 4;
  return g;
}

/// Five nodes, turning at 30 rad/s: nodes 0 and 1 share cells, node 4's
/// patch crosses the 0 / 2 pi seam at the start.
LinerContactLayout patch_layout(double circumferential, double axial) {
  LinerContactLayout l;
  l.polar_angle = {0.1, 0.15, 1.0, 3.0, 6.25};
  l.axial = {0.0, 1.0, -3.0, 9.5, 0.0};
  l.omega = 30.0;
  l.patch.circumferential = circumferential;
  l.patch.axial = axial;
  return l;
}

/// A diagonal W, equal entries on a node's three rows (a lumped mass).
Eigen::MatrixXd diagonal_w(const Eigen::VectorXd& w_node) {
  const int nc = static_cast<int>(w_node.size());
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(3 * nc, 3 * nc);
  for (int c = 0; c < nc; ++c) w.block(3 * c, 3 * c, 3, 3).diagonal().setConstant(w_node(c));
  return w;
}

TEST(LinerContactSolve, PatchDiagonalWSatisfiesTheBarLaw) {
  const int nc = 5;
  const double dt = 1e-3, mu = 0.3;
  const AbradableCells fresh(fine_geometry(), material());
  const double k = fresh.stiffness(), kh = fresh.hardening_stiffness();
  const double fy0 = 10.0 * fresh.area(); // A sigma_y
  LinerContactSolve solve(nc, dt, mu, fresh, patch_layout(60.0, 8.0));
  // c k from 0.2 to 10 (k = 6.1e4 N/mm).
  Eigen::VectorXd w_node(nc);
  w_node << 0.2 / k, 1.0 / k, 2.0 / k, 5.0 / k, 10.0 / k;
  solve.set_contact_matrix(diagonal_w(w_node));
  std::srand(41);
  long responses = 0; // (contact, cell) pairs committed: a bound on the plastic increments
  double worst = 0.0, law_bound = 0.0;
  std::vector<double> wear = solve.cells().wear();
  for (int step = 1; step <= 40; ++step) {
    Eigen::VectorXd predicted = Eigen::VectorXd::Random(3 * nc) * 0.05;
    // Closing by 0.03 to 0.09 past the unworn surface: every patch yields.
    for (int c = 0; c < nc; ++c) predicted(3 * c) = -0.06 - 0.03 * predicted(3 * c);
    const double t = step * dt;
    std::vector<std::vector<int>> under(nc);
    for (int c = 0; c < nc; ++c) under[c] = solve.cells_under(c, t);
    std::map<int, BarState> chained; // the test's own chain: cell -> state left this step
    for (int c = 0; c < nc; ++c)
      for (int cell : under[c]) chained.emplace(cell, solve.cells().state(cell));
    StepReport report;
    solve.solve(predicted, step, report);
    const Eigen::VectorXd& lambda = solve.lambda_next();
    double lambda_max = 0.0;
    for (int c = 0; c < nc; ++c) lambda_max = std::max(lambda_max, lambda(3 * c));
    for (int c = 0; c < nc; ++c) {
      // The final gap of node c (W diagonal): g = g~ + W_nn lambda_n.
      const double ln = lambda(3 * c);
      const double g = predicted(3 * c) + w_node(c) * ln;
      double force = 0.0, p_max = 0.0;
      for (int cell : under[c]) {
        BarState& s = chained.at(cell);
        p_max = std::max(p_max, s.wear);
        const BarResponse r = solve.cells().bar(s, -g - s.wear);
        force += r.force;
        s = r.state;
      }
      // Tolerance (derived): -g - p_i rounds at eps (|g~| + W_nn lambda +
      // p), twice, times k for each of the n bars; the multiplier's closed
      // form rounds at (n + 8) eps of itself; and the tangential update in
      // the same sweep does not move it (W diagonal).
      const double n = static_cast<double>(under[c].size());
      const double tolerance =
          4.0 * n * k * eps * (std::abs(predicted(3 * c)) + w_node(c) * ln + p_max) +
          4.0 * (n + 8.0) * eps * ln;
      worst = std::max(worst, std::abs(ln - force) / tolerance);
      EXPECT_LE(std::abs(ln - force), tolerance) << "step " << step << " node " << c;
      // Coulomb with a diagonal W: the stick multiplier -s~ / w on the disk.
      Eigen::Vector2d lt = -predicted.segment<2>(3 * c + 1) / w_node(c);
      if (lt.norm() > mu * ln) lt *= mu * ln / lt.norm();
      EXPECT_NEAR((lambda.segment<2>(3 * c + 1) - lt).norm(), 0.0, 16.0 * eps * lt.norm() + 1e-300);
      responses += static_cast<long>(n);
      // The certificate's compliant residual: the depth d~ = -(y - w lambda)
      // rounds at eps (|g~| + 2 w lambda), which the compliant map (1 /
      // w-Lipschitz) turns into eps (|g~| / w + 2 lambda); twice that, and
      // the two closed forms' (n + 8) eps lambda.
      if (lambda_max > 0.0)
        law_bound =
            std::max(law_bound, (2.0 * eps * (std::abs(predicted(3 * c)) / w_node(c) + 2.0 * ln) +
                                 2.0 * (n + 8.0) * eps * ln) /
                                    lambda_max);
    }
    const std::vector<double> now = solve.cells().wear();
    for (size_t i = 0; i < now.size(); ++i) EXPECT_GE(now[i], wear[i]) << "cell " << i;
    wear = now;
  }
  // W_plastic closed form (SPEC §9): sum_cells A (sigma_y p + H p^2 / (2 h))
  // = sum_cells p (F_Y0 + k_H p / 2) in force variables (the increments'
  // dp (F_Y + k_H dp / 2) telescope to it with linear hardening).
  double closed = 0.0, worn = 0.0;
  for (double p : wear) {
    closed += p * (fy0 + 0.5 * kh * p);
    worn += p > 0.0;
  }
  // Tolerance (derived): each increment's work and each cell's yield force
  // update rounds at a few eps, accumulated over at most `responses` of them.
  const double tolerance = 4.0 * static_cast<double>(responses) * eps * closed;
  std::printf("patch, diagonal W: worst bar-law residual / tolerance %.3g; law residual %.3g "
              "(bound %.3g); W_plastic %.9g vs closed form %.9g (difference %.3g, tolerance %.3g); "
              "%g cells worn\n",
              worst, solve.max_law_residual(), law_bound, solve.plastic_work(), closed,
              std::abs(solve.plastic_work() - closed), tolerance, worn);
  EXPECT_LE(solve.max_law_residual(), law_bound);
  EXPECT_GT(closed, 0.0);
  EXPECT_GT(worn, 8.0); // the patches spread the wear over many cells
  EXPECT_NEAR(solve.plastic_work(), closed, tolerance);
}

// A run of both solves over the same predictions (dense W, friction,
// yielding): `same` a layout with a zero-width patch, `base` one without.
void run_alongside(LinerContactSolve& same, LinerContactSolve& base, const Eigen::MatrixXd& w,
                   int steps, unsigned seed, double& largest_difference, double& largest_force) {
  const int nc = static_cast<int>(w.rows()) / 3;
  same.set_contact_matrix(w);
  base.set_contact_matrix(w);
  std::srand(seed);
  largest_difference = largest_force = 0.0;
  for (int step = 1; step <= steps; ++step) {
    Eigen::VectorXd predicted = Eigen::VectorXd::Random(3 * nc) * 0.05;
    for (int c = 0; c < nc; ++c) predicted(3 * c) -= 0.03;
    StepReport a, b;
    same.solve(predicted, step, a);
    base.solve(predicted, step, b);
    largest_difference = std::max(largest_difference,
                                  (same.lambda_next() - base.lambda_next()).cwiseAbs().maxCoeff());
    largest_force = std::max(largest_force, base.lambda_next().cwiseAbs().maxCoeff());
  }
}

TEST(LinerContactSolve, ZeroWidthPatchIsTheOneCellSolve) {
  const int nc = 5;
  const AbradableCells cells(fine_geometry(), material());
  const Eigen::MatrixXd w = dense_w(nc, 53, 0.5 / cells.stiffness());
  LinerContactLayout none = patch_layout(0.0, 0.0);
  none.patch = TipPatch{};
  // Both widths 0: the same code path, bit for bit (liner_contact_solve.hpp).
  LinerContactSolve zero(nc, 1e-3, 0.2, cells, patch_layout(0.0, 0.0));
  LinerContactSolve base(nc, 1e-3, 0.2, cells, none);
  double difference = 0.0, force = 0.0;
  run_alongside(zero, base, w, 40, 61, difference, force);
  EXPECT_EQ(difference, 0.0); // source: the same arithmetic
  EXPECT_EQ(zero.cells().wear(), base.cells().wear());
  EXPECT_EQ(zero.plastic_work(), base.plastic_work());
  EXPECT_EQ(zero.elastic_energy(), base.elastic_energy());
  EXPECT_GT(zero.plastic_work(), 0.0);
  // A patch far narrower than a cell (1e-9 of its widths) presses the one
  // cell under each node through the patch's own path: the forces equal
  // the one-cell solve's where the bar's piece is classified alike, and
  // otherwise to the rounding of the classification and of the bar law at
  // delta~ - c F (a few eps (1 + c k) of the force, c k ~ 1 here), which
  // the 40 steps' wear and the sweeps' stopping rule (1e-14 of the largest
  // multiplier; the patch path's sweeps may start from the direct solve of
  // liner_slip_set.hpp and the one-cell path's do not, both stop by that
  // rule) carry: 1e-12 of the largest multiplier.
  LinerContactSolve narrow(nc, 1e-3, 0.2, cells, patch_layout(1e-9 * 24.5, 1e-9 * 5.0));
  LinerContactSolve again(nc, 1e-3, 0.2, cells, none);
  run_alongside(narrow, again, w, 40, 61, difference, force);
  for (int c = 0; c < nc; ++c) EXPECT_EQ(narrow.cells_under(c, 0.02).size(), 1u);
  std::printf("narrow patch vs one cell: largest multiplier difference %.3g of %.3g; W_plastic "
              "%.12g vs %.12g\n",
              difference, force, narrow.plastic_work(), again.plastic_work());
  EXPECT_LE(difference, 1e-12 * force);
  EXPECT_NEAR(narrow.plastic_work(), again.plastic_work(), 1e-12 * again.plastic_work());
}

// Dense W, friction, overlapping patches: the certificate (bar law, cone,
// stick and slip) at round-off, as DenseYieldingWithFrictionCertifies
// checks the one-cell solve.
TEST(LinerContactSolve, PatchDenseYieldingWithFrictionCertifies) {
  const int nc = 5;
  const AbradableCells cells(fine_geometry(), material());
  const Eigen::MatrixXd w = dense_w(nc, 71, 0.5 / cells.stiffness());
  for (double mu : {0.0, 0.3}) {
    LinerContactSolve solve(nc, 1e-3, mu, cells, patch_layout(60.0, 8.0));
    solve.set_contact_matrix(w);
    const double plastic = certified_random_steps(solve, nc, 0.05, 73, mu);
    std::printf("patch, dense W, mu %g: law residual %.3g, W_plastic %.6g, sweeps %ld\n", mu,
                solve.max_law_residual(), plastic, solve.sweeps());
    EXPECT_LE(solve.max_law_residual(), 1e-10) << "mu " << mu;
    EXPECT_GT(plastic, 0.0);
  }
}

// Dense W, friction, patches 1.2 rad apart (no shared cell) under a
// casing that slides 5 mm a step past the tips: the steps start from the
// direct solve (liner_slip_set.hpp), and the Gauss-Seidel's stopping rule
// and certificate then hold as in PatchDenseYieldingWithFrictionCertifies.
TEST(LinerContactSolve, PatchDirectStartCertifies) {
  const int nc = 5;
  const AbradableCells cells(fine_geometry(), material());
  const Eigen::MatrixXd w = dense_w(nc, 71, 0.5 / cells.stiffness());
  LinerContactLayout l = patch_layout(60.0, 8.0);
  l.polar_angle = {0.1, 1.3, 2.5, 3.7, 4.9};
  LinerContactSolve solve(nc, 1e-3, 0.3, cells, l);
  solve.set_contact_matrix(w);
  std::srand(79);
  double plastic = 0.0;
  for (int step = 1; step <= 50; ++step) {
    Eigen::VectorXd predicted = Eigen::VectorXd::Random(3 * nc) * 0.05;
    for (int c = 0; c < nc; ++c) {
      predicted(3 * c) -= 0.05;
      predicted(3 * c + 2) += 5.0;
    }
    StepReport report;
    solve.solve(predicted, step, report);
    EXPECT_LE(report.max_cone_violation, 1e-12 * solve.lambda_next().cwiseAbs().maxCoeff());
    EXPECT_LE(report.max_stick_slip_residual, 1e-9) << "step " << step;
    EXPECT_GE(solve.plastic_work(), plastic);
    plastic = solve.plastic_work();
  }
  std::printf("patch, direct start: %ld of 50 steps, %ld sweeps, law residual %.3g, W_plastic "
              "%.6g\n",
              solve.direct_starts(), solve.sweeps(), solve.max_law_residual(), plastic);
  EXPECT_GT(solve.direct_starts(), 0);
  EXPECT_LE(solve.max_law_residual(), 1e-10);
  EXPECT_GT(plastic, 0.0);
}

} // namespace
} // namespace rsi

namespace rsi {
namespace {

// Worn through (liner_contact_solve.hpp, "Worn through"): one node (W =
// c I, c = 1e-9 mm/N) pressing a liner of h = 0.1 mm 0.02 mm deeper each
// step (E 1000, sigma_y 10, H 300 MPa). Loaded monotonically the bar stays
// on its yield line, sigma = sigma_y + H p / h, and the node's predicted
// depth is d~ = p + sigma h / E + c A sigma, so
//   p = (d~ - sigma_y h / E - c A sigma_y) / (1 + H / E + c A H / h):
// 0.0907 mm at step 6 (d~ = 0.12), 0.1059 mm at step 7 (0.14). Step 7's
// commit throws, naming the cell and h, with the wear at that p (the return
// mapping is exact for linear hardening: a few operations rounded at eps,
// 1e-12 relative); every step before leaves the wear below h.
TEST(LinerContactSolve, WornThroughEndsTheRun) {
  AbradableCellsGeometry thin = geometry();
  thin.thickness = 0.1;
  const AbradableCellsMaterial mat = material();
  const double c = 1e-9;
  LinerContactSolve solve(1, 1e-3, 0.0, AbradableCells(thin, mat), layout({1.0}));
  solve.set_contact_matrix(Eigen::MatrixXd::Identity(3, 3) * c);
  const int cell = solve.cells().sector(1.0);
  const double a = solve.cells().area();
  int thrown_at = 0;
  for (int step = 1; step <= 20 && thrown_at == 0; ++step) {
    Eigen::VectorXd predicted = Eigen::VectorXd::Zero(3);
    predicted(0) = -0.02 * step;
    StepReport report;
    try {
      solve.solve(predicted, step, report);
      EXPECT_LT(solve.cells().state(cell).wear, thin.thickness) << "step " << step;
    } catch (const ComponentIntegrationError& e) {
      thrown_at = step;
      const std::string what = e.what();
      EXPECT_NE(what.find("worn through at sector " + std::to_string(cell) + ", row 0"),
                std::string::npos)
          << what;
      EXPECT_NE(what.find("thickness 0.1"), std::string::npos) << what;
      const double p = (0.02 * step - mat.yield * thin.thickness / mat.young - c * a * mat.yield) /
                       (1.0 + mat.hardening / mat.young + c * a * mat.hardening / thin.thickness);
      EXPECT_NEAR(solve.cells().state(cell).wear, p, 1e-12 * p);
      ASSERT_EQ(e.advice().remedies.size(), 1u);
      EXPECT_EQ(e.advice().remedies[0], Remedy::thicker_liner_or_larger_clearance);
    }
  }
  EXPECT_EQ(thrown_at, 7);
}

} // namespace
} // namespace rsi

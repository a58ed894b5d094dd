// V5 (issue 12): the reduced side's solver of one contact step with Coulomb
// friction (stick and slip), CoulombGaussSeidel, and its certificate.
//   - single contacts against closed-form solutions derived by hand (2D stick
//     and slip, 3D stick and slip);
//   - the frictionless diagonal case (contacts decoupled, exact);
//   - the frictionless coupled case against an independent brute-force
//     enumeration of the active sets;
//   - random well-posed problems W = dt^2 B M^-1 B^T (random SPD M, random B,
//     mu in {0, 0.15, 0.5}, d = 1 and 2): the certificate within bounds
//     derived from the stopping rule and round-off (derivation below);
//   - the default 2D case's own W (22 tips closing, sliding and sticking);
//   - a contact whose normal row of W is zero: reported when it closes,
//     harmless when it stays open; bad arguments rejected; non-convergence
//     reported.
//
// Round-off bound used throughout (derived in coulomb_gauss_seidel.hpp and
// here). m = (1+d) nc unknowns, L = max |lambda|, S = max|[g~; s~]| +
// ||W||_inf L (the size of the terms summed into y = [g~; s~] + W lambda),
// Delta the solver's last sweep change. The gaps and slips y carry:
//   ||W||_inf Delta       the contacts' moves after each one's local solve;
//   (m + 1) eps S         forming y in the certificate;
//   (m + 1) eps S + (m + nc) eps S   the solver's y: formed at the sweep
//                         start, then at most nc updates of 1+d terms;
//   8 (1+d) eps S         the local solve: r_c = y_c - W_cc lambda_c (2+d
//                         terms), the LU solve of stick (backward error
//                         3 (1+d) eps on |r| + |W_cc| |lambda| <= 2 S) or
//                         g = 0 of slip (4 terms).
// So delta_y = ||W||_inf Delta + (3m + nc + 2 + 8 (1+d)) eps S.

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "case_file.hpp"
#include "casing.hpp"
#include "coulomb_gauss_seidel.hpp"
#include "reduced_contact.hpp"
#include "reduced_coulomb_certificate.hpp"
#include "reduction.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

double inf_norm(const Eigen::MatrixXd& w) {
  return w.cwiseAbs().rowwise().sum().maxCoeff();
}

/// delta_y of the header comment.
double gap_bound(const Eigen::MatrixXd& w, const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
                 int d, double last_change) {
  const int m = static_cast<int>(w.rows());
  const int nc = m / (1 + d);
  const double l = lambda.cwiseAbs().maxCoeff();
  const double s = q.cwiseAbs().maxCoeff() + inf_norm(w) * l;
  return inf_norm(w) * last_change + (3.0 * m + nc + 2.0 + 8.0 * (1 + d)) * eps * s;
}

void print(const char* name, const CoulombGaussSeidelReport& r,
           const ReducedCoulombCertificate& c) {
  std::printf("%s: %s after %d sweeps (last change %.3e of %.3e); open %d stick %d slip %d; "
              "penetration %.3e, min lambda_n %.3e, |g lambda_n| %.3e, cone %.3e, stick %.3e, "
              "slip %.3e, open %.3e\n",
              name, r.converged() ? "converged" : r.message.c_str(), r.sweeps, r.last_change,
              r.size, c.n_open, c.n_stick, c.n_slip, c.max_penetration, c.min_normal,
              c.max_complementarity, c.max_cone_violation, c.max_stick_residual,
              c.max_slip_residual, c.max_open_residual);
}

struct Solved {
  Eigen::VectorXd lambda;
  CoulombGaussSeidelReport report;
  ReducedCoulombCertificate certificate;
  std::vector<ReducedContactState> state;
};

Solved solve(const Eigen::MatrixXd& w, const Eigen::VectorXd& q, int d, double mu, const char* name,
             const CoulombGaussSeidelOptions& options = {}) {
  CoulombGaussSeidel solver(d, mu, options);
  Solved out;
  out.report = solver.solve(w, q, out.lambda);
  out.state = solver.states();
  out.certificate = reduced_coulomb_certificate(w, q, d, mu, out.lambda, out.state);
  print(name, out.report, out.certificate);
  return out;
}

/// A single contact against its closed form: lambda to a relative bound
/// derived from delta_y through the local problem's sensitivity k
/// (|d lambda| <= k |d y|, given per case), plus 4 eps L for the local
/// arithmetic (a division and a product per entry) and the rounding of
/// decimal data (eps/2 of each input, carried through k).
void expect_lambda(const Solved& s, const Eigen::MatrixXd& w, const Eigen::VectorXd& q, int d,
                   const Eigen::VectorXd& expected, double k) {
  ASSERT_TRUE(s.report.converged()) << s.report.message;
  const double l = expected.cwiseAbs().maxCoeff();
  const double bound =
      k * (gap_bound(w, q, s.lambda, d, s.report.last_change) + eps * q.cwiseAbs().maxCoeff()) +
      4.0 * eps * l;
  const double error = (s.lambda - expected).cwiseAbs().maxCoeff();
  std::printf("  |lambda - closed form| = %.3e (bound %.3e)\n", error, bound);
  EXPECT_LE(error, bound);
}

// --- Single contacts: closed forms -------------------------------------------

// W = [2 0.5; 0.5 1], r = (-1, 0.1). Stick: lambda = -W^-1 r
// = -[1 -0.5; -0.5 2] (-1, 0.1) / 1.75 = (1.05, -0.7) / 1.75 = (0.6, -0.4),
// in the cone when 0.4 <= 0.6 mu, i.e. mu >= 2/3. No slip solution at
// mu = 0.8: e = +1 gives lambda_n = 1/1.6, lambda_t = -0.5, s = 0.1 +
// 0.3125 - 0.5 < 0; e = -1 gives lambda_n = 1/2.4, lambda_t = 1/3, s > 0:
// neither consistent, so the stick solution is the only one.
TEST(CoulombGaussSeidel, SingleContact2dStick) {
  Eigen::MatrixXd w(2, 2);
  w << 2.0, 0.5, 0.5, 1.0;
  const Eigen::VectorXd q = (Eigen::VectorXd(2) << -1.0, 0.1).finished();
  const Solved s = solve(w, q, 1, 0.8, "2D stick, mu 0.8");
  ASSERT_EQ(s.state.size(), 1u);
  EXPECT_EQ(s.state[0], ReducedContactState::stick);
  // Hand derivation above; sensitivity k = ||W^-1||_inf = 2.5 / 1.75.
  expect_lambda(s, w, q, 1, (Eigen::VectorXd(2) << 0.6, -0.4).finished(), 2.5 / 1.75);
}

// Same W, r, mu = 0.5 < 2/3: slip. With e = sign(s), lambda_t = -mu lambda_n e
// and g = 0: lambda_n = 1 / (2 - 0.25 e). e = +1: lambda_n = 4/7,
// lambda_t = -2/7, s = 0.1 + 0.5 (4/7) - 2/7 = 0.1 > 0, consistent.
// e = -1: lambda_n = 4/9, lambda_t = 2/9, s = 0.1 + 2/9 + 2/9 > 0, not
// consistent. So the solution is (4/7, -2/7), s = 0.1.
TEST(CoulombGaussSeidel, SingleContact2dSlip) {
  Eigen::MatrixXd w(2, 2);
  w << 2.0, 0.5, 0.5, 1.0;
  const Eigen::VectorXd q = (Eigen::VectorXd(2) << -1.0, 0.1).finished();
  const Solved s = solve(w, q, 1, 0.5, "2D slip, mu 0.5");
  ASSERT_EQ(s.state.size(), 1u);
  EXPECT_EQ(s.state[0], ReducedContactState::slip);
  // Hand derivation above; lambda_n = rho / 1.75 and lambda_t = -0.5 lambda_n:
  // sensitivity k = 1 / 1.75 to the gap.
  expect_lambda(s, w, q, 1, (Eigen::VectorXd(2) << 4.0 / 7.0, -2.0 / 7.0).finished(), 1.0 / 1.75);
  // The slip s = 0.1 (derivation above) to delta_y.
  const Eigen::VectorXd y = q + w * s.lambda;
  const double bound = gap_bound(w, q, s.lambda, 1, s.report.last_change);
  std::printf("  |s - 0.1| = %.3e (bound %.3e)\n", std::abs(y(1) - 0.1), bound);
  EXPECT_LE(std::abs(y(1) - 0.1), bound);
}

/// The coupled 3D block of the 3D cases (dyadic entries, SPD: its leading
/// minors 2, 1.9375, 2.53... are positive).
Eigen::MatrixXd block_3d() {
  Eigen::MatrixXd w(3, 3);
  w << 2.0, 0.25, -0.125, 0.25, 1.0, 0.5, -0.125, 0.5, 1.5;
  return w;
}

int count_local_solutions_3d(const Eigen::MatrixXd& w, const Eigen::Vector3d& r, double mu);

// Manufactured stick: lambda* = (1, 0.25, -0.125), r = -W lambda* (exact in
// binary: dyadic products), |lambda_t*| = 0.2795 < mu = 0.5: y = 0 with
// lambda* in the cone solves the problem; the scan of
// count_local_solutions_3d (below) finds no other.
TEST(CoulombGaussSeidel, SingleContact3dStick) {
  const Eigen::MatrixXd w = block_3d();
  const Eigen::Vector3d star(1.0, 0.25, -0.125);
  const Eigen::VectorXd q = -(w * star);
  EXPECT_EQ(count_local_solutions_3d(w, q, 0.5), 1) << "the stick solution must be the only one";
  const Solved s = solve(w, q, 2, 0.5, "3D stick, mu 0.5");
  EXPECT_EQ(s.state[0], ReducedContactState::stick);
  // Manufactured above; sensitivity k = ||W^-1||_inf.
  expect_lambda(s, w, q, 2, star, inf_norm(w.inverse()));
}

/// The data of a manufactured slip: lambda_n, direction e (unit), slip
/// sigma > 0: lambda_t = -mu lambda_n e, r_n = -(w_nn lambda_n + w_nt
/// lambda_t), r_t = sigma e - w_tn lambda_n - W_tt lambda_t.
Eigen::VectorXd manufactured_slip(const Eigen::MatrixXd& w, double mu, double ln,
                                  const Eigen::Vector2d& e, double sigma, Eigen::VectorXd& lambda) {
  lambda = Eigen::VectorXd(3);
  lambda << ln, -mu * ln * e(0), -mu * ln * e(1);
  Eigen::VectorXd y(3);
  y << 0.0, sigma * e(0), sigma * e(1);
  return y - w * lambda;
}

/// First-order sensitivity k = ||d lambda / d r||_inf of a d = 2 slip
/// solution (lambda_n, direction th, slip sigma), by the implicit function
/// theorem on its equations (local_coulomb_solution.hpp), x = (lambda_n, th):
///   F1 = r_n + lambda_n (w_nn - mu w_nt . e) = 0,
///   F2 = e x (r_t + lambda_n (w_tn - mu W_tt e)) = 0,  e = (cos th, sin th),
/// d lambda = (d lambda / dx) (-J_x^-1 J_r) dr, lambda = (lambda_n,
/// -mu lambda_n e). At the solution r_t + ... = sigma e, so dF2/dth =
/// e' x (sigma e) + e x (-mu lambda_n W_tt e') = -sigma - mu lambda_n e x W_tt e'.
/// First order suffices: the perturbations are of order eps.
double slip_sensitivity(const Eigen::MatrixXd& w, double mu, double ln, double th, double sigma) {
  const Eigen::Vector2d e(std::cos(th), std::sin(th)), de(-std::sin(th), std::cos(th));
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a(0) * b(1) - a(1) * b(0);
  };
  const Eigen::RowVector2d wnt = w.block(0, 1, 1, 2);
  const Eigen::Vector2d wtn = w.block(1, 0, 2, 1);
  const Eigen::Matrix2d wtt = w.block(1, 1, 2, 2);
  Eigen::Matrix2d jx;
  jx << w(0, 0) - mu * wnt.dot(e), -mu * ln * wnt.dot(de), cross(e, wtn - mu * wtt * e),
      -sigma - mu * ln * cross(e, wtt * de);
  Eigen::Matrix<double, 2, 3> jr;
  jr << 1.0, 0.0, 0.0, 0.0, -e(1), e(0);
  Eigen::Matrix<double, 3, 2> dl;
  dl << 1.0, 0.0, -mu * e(0), mu * ln * std::sin(th), -mu * e(1), -mu * ln * std::cos(th);
  const Eigen::Matrix3d k = dl * jx.inverse() * jr;
  return k.cwiseAbs().rowwise().sum().maxCoeff();
}

/// Number of solutions of one d = 2 contact's problem with r_n < 0, found by
/// a method apart from the solver's: stick from W^-1 r (at most one), slip
/// from the sign changes of f(th) = e x H(e) on a grid of 20000 angles,
/// refined by bisection, kept when lambda_n > 0 and s . e > 0.
int count_local_solutions_3d(const Eigen::MatrixXd& w, const Eigen::Vector3d& r, double mu) {
  int n = 0;
  const Eigen::Vector3d stick = -w.inverse() * r;
  if (stick(0) >= 0.0 && stick.tail<2>().norm() <= mu * stick(0)) ++n;
  const auto slip = [&](double th, double& ln, Eigen::Vector2d& s) {
    const Eigen::Vector2d e(std::cos(th), std::sin(th));
    const double den = w(0, 0) - mu * (w(0, 1) * e(0) + w(0, 2) * e(1));
    ln = -r(0) / den;
    s = r.tail<2>() + w.block(1, 0, 2, 1) * ln - mu * ln * w.block(1, 1, 2, 2) * e;
    return e(0) * s(1) - e(1) * s(0); // s parallel to e where this vanishes
  };
  const int grid = 20000;
  double ln = 0.0;
  Eigen::Vector2d s;
  for (int i = 0; i < grid; ++i) {
    double a = 2.0 * M_PI * i / grid, b = 2.0 * M_PI * (i + 1) / grid;
    double fa = slip(a, ln, s);
    if (fa * slip(b, ln, s) > 0.0) continue;
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b);
      const double fm = slip(m, ln, s);
      if (fa * fm <= 0.0)
        b = m;
      else
        a = m, fa = fm;
    }
    slip(0.5 * (a + b), ln, s);
    const Eigen::Vector2d e(std::cos(0.5 * (a + b)), std::sin(0.5 * (a + b)));
    if (ln > 0.0 && s.dot(e) > 0.0) ++n;
  }
  return n;
}

// Manufactured slip with the normal decoupled (w_nt = 0): lambda_n = rho/w_nn
// is fixed, the tangential problem is Tresca's, a strictly convex program
// (W_tt SPD): the solution is unique, so it is the manufactured one.
// lambda_n = 1, e = (0.6, 0.8), sigma = 0.5, mu = 0.3.
TEST(CoulombGaussSeidel, SingleContact3dSlipDecoupled) {
  Eigen::MatrixXd w(3, 3);
  w << 2.0, 0.0, 0.0, 0.0, 1.0, 0.25, 0.0, 0.25, 0.75;
  Eigen::VectorXd star;
  const Eigen::VectorXd q = manufactured_slip(w, 0.3, 1.0, Eigen::Vector2d(0.6, 0.8), 0.5, star);
  EXPECT_EQ(count_local_solutions_3d(w, q, 0.3), 1) << "Tresca: unique";
  const Solved s = solve(w, q, 2, 0.3, "3D slip (w_nt = 0), mu 0.3");
  EXPECT_EQ(s.state[0], ReducedContactState::slip);
  // Manufactured above; k from the implicit function theorem.
  const double k = slip_sensitivity(w, 0.3, 1.0, std::atan2(0.8, 0.6), 0.5);
  std::printf("  sensitivity k = %.3f\n", k);
  expect_lambda(s, w, q, 2, star, k);
}

// Manufactured slip on the coupled block (w_nt != 0): lambda_n = 1,
// e = (0.6, 0.8), sigma = 0.5, mu = 0.3. Its uniqueness (which the
// comparison with the manufactured solution needs) is checked by the scan
// of count_local_solutions_3d.
TEST(CoulombGaussSeidel, SingleContact3dSlipCoupled) {
  const Eigen::MatrixXd w = block_3d();
  Eigen::VectorXd star;
  const Eigen::VectorXd q = manufactured_slip(w, 0.3, 1.0, Eigen::Vector2d(0.6, 0.8), 0.5, star);
  ASSERT_EQ(count_local_solutions_3d(w, q, 0.3), 1) << "the manufactured solution must be unique";
  const Solved s = solve(w, q, 2, 0.3, "3D slip (coupled), mu 0.3");
  EXPECT_EQ(s.state[0], ReducedContactState::slip);
  // Manufactured above; k from the implicit function theorem.
  const double k = slip_sensitivity(w, 0.3, 1.0, std::atan2(0.8, 0.6), 0.5);
  std::printf("  sensitivity k = %.3f\n", k);
  expect_lambda(s, w, q, 2, star, k);
}

// Radial return (3D, W = diag(a, b, b)): lambda_n = rho / a, and if
// |r_t| > b mu lambda_n, lambda_t = -mu lambda_n r_t / |r_t| and s =
// r_t (1 - b mu lambda_n / |r_t|) (parallel to r_t, so consistent).
// a = 2, b = 0.5, r = (-3, 0.6, -0.8), mu = 0.5: lambda_n = 1.5, b mu lambda_n
// = 0.375 < |r_t| = 1: slip, lambda_t = -0.75 (0.6, -0.8) = (-0.45, 0.6),
// |s| = 0.625.
TEST(CoulombGaussSeidel, SingleContact3dRadialReturn) {
  const Eigen::MatrixXd w = Eigen::Vector3d(2.0, 0.5, 0.5).asDiagonal();
  const Eigen::VectorXd q = Eigen::Vector3d(-3.0, 0.6, -0.8);
  EXPECT_EQ(count_local_solutions_3d(w, q, 0.5), 1) << "the radial return must be the only one";
  const Solved s = solve(w, q, 2, 0.5, "3D radial return, mu 0.5");
  EXPECT_EQ(s.state[0], ReducedContactState::slip);
  // Derivation above; k from the implicit function theorem.
  const double k = slip_sensitivity(w, 0.5, 1.5, std::atan2(-0.8, 0.6), 0.625);
  std::printf("  sensitivity k = %.3f\n", k);
  expect_lambda(s, w, q, 2, Eigen::Vector3d(1.5, -0.45, 0.6), k);
}

// --- Frictionless --------------------------------------------------------------

// W diagonal, mu = 0: the contacts decouple and lambda_n,c =
// max(-g~_c / w_c, 0), lambda_t = 0 (Signorini for one scalar unknown).
TEST(CoulombGaussSeidel, FrictionlessDiagonal) {
  for (int d : {1, 2}) {
    const int nc = 6;
    const int m = (1 + d) * nc;
    std::mt19937 rng(7 + d);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Eigen::VectorXd diag(m), q(m);
    for (int i = 0; i < m; ++i)
      diag(i) = 1.5 + unit(rng), q(i) = unit(rng);
    const Eigen::MatrixXd w = diag.asDiagonal();
    const Solved s =
        solve(w, q, d, 0.0, d == 1 ? "frictionless diagonal d=1" : "frictionless diagonal d=2");
    ASSERT_TRUE(s.report.converged()) << s.report.message;
    // One sweep solves decoupled contacts, the second sees no change beyond
    // round-off (below 1e-14 relative: see below), so it stops at 2.
    EXPECT_EQ(s.report.sweeps, 2);
    for (int c = 0; c < nc; ++c) {
      const int o = (1 + d) * c;
      const double exact = std::max(-q(o) / diag(o), 0.0);
      // The second sweep's r = (q + w l) - w l: two roundings of terms of
      // size |q|, 2 eps |q| relative, then the division eps/2: 2.5 eps
      // relative, asserted as 3 eps.
      EXPECT_LE(std::abs(s.lambda(o) - exact), 3.0 * eps * exact) << "contact " << c;
      for (int i = 1; i <= d; ++i)
        EXPECT_EQ(s.lambda(o + i), 0.0) << "mu = 0: no tangential force";
      EXPECT_EQ(s.state[c], exact > 0.0 ? ReducedContactState::slip : ReducedContactState::open);
    }
  }
}

/// Random W = dt^2 B M^-1 B^T: M = A A^T + n I (SPD, condition <= ~5), B
/// standard normal, dt = 5e-7 s (SPEC §2), M in kg: W ~ 1e-13 m/N.
Eigen::MatrixXd random_w(int n, int rows, std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd a(n, n), b(rows, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      a(i, j) = normal(rng);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < n; ++j)
      b(i, j) = normal(rng);
  const Eigen::MatrixXd mass = a * a.transpose() / n + Eigen::MatrixXd::Identity(n, n);
  const Eigen::LLT<Eigen::MatrixXd> llt(mass);
  EXPECT_EQ(llt.info(), Eigen::Success);
  const double dt = 5e-7;
  const Eigen::MatrixXd x = llt.solve(b.transpose());
  Eigen::MatrixXd w = dt * dt * (b * x);
  return 0.5 * (w + w.transpose());
}

/// Predicted gaps and slips uniform in [-1, 1] um, a quarter of the gaps
/// shifted up (open), the slips of every third contact scaled by 1e-2 (so
/// that some closing contacts stick).
Eigen::VectorXd random_prediction(int nc, int d, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd q((1 + d) * nc);
  for (int i = 0; i < q.size(); ++i)
    q(i) = 1e-6 * unit(rng);
  for (int c = 0; c < nc; c += 4)
    q((1 + d) * c) += 1e-6;
  for (int c = 0; c < nc; c += 3)
    q.segment((1 + d) * c + 1, d) *= 1e-2;
  return q;
}

// Frictionless coupled: the normal problem is the LCP 0 <= lambda_n _|_
// g~_n + W_nn lambda_n >= 0 with W_nn SPD, whose solution is unique;
// enumerate every active set A (2^nc), solve W_AA lambda_A = -g~_A by
// Cholesky and keep the one with lambda_A >= 0 and g_I >= 0.
TEST(CoulombGaussSeidel, FrictionlessCoupledAgainstEnumeration) {
  const int nc = 6, d = 1, n = 20;
  for (int seed = 0; seed < 10; ++seed) {
    std::mt19937 rng(100 + seed);
    const Eigen::MatrixXd w = random_w(n, (1 + d) * nc, rng);
    const Eigen::VectorXd q = random_prediction(nc, d, rng);
    const Solved s = solve(w, q, d, 0.0, "frictionless coupled");
    ASSERT_TRUE(s.report.converged()) << s.report.message;
    // Normal subproblem.
    Eigen::MatrixXd wn(nc, nc);
    Eigen::VectorXd qn(nc);
    for (int i = 0; i < nc; ++i) {
      qn(i) = q(2 * i);
      for (int j = 0; j < nc; ++j)
        wn(i, j) = w(2 * i, 2 * j);
    }
    Eigen::VectorXd found;
    int n_found = 0;
    double residual_tol = 0.0;
    for (int mask = 0; mask < (1 << nc); ++mask) {
      std::vector<int> act;
      for (int i = 0; i < nc; ++i)
        if (mask & (1 << i)) act.push_back(i);
      Eigen::VectorXd l = Eigen::VectorXd::Zero(nc);
      if (!act.empty()) {
        Eigen::MatrixXd waa(act.size(), act.size());
        Eigen::VectorXd qa(act.size());
        for (size_t i = 0; i < act.size(); ++i) {
          qa(i) = q(2 * act[i]);
          for (size_t j = 0; j < act.size(); ++j)
            waa(i, j) = wn(act[i], act[j]);
        }
        const Eigen::LLT<Eigen::MatrixXd> llt(waa);
        ASSERT_EQ(llt.info(), Eigen::Success);
        const Eigen::VectorXd la = llt.solve(-qa);
        for (size_t i = 0; i < act.size(); ++i)
          l(act[i]) = la(i);
      }
      const Eigen::VectorXd g = qn + wn * l;
      // Accept within the round-off of g (nc + 1 terms of size S): this is
      // a selection, and the LCP's unique solution passes it by a margin.
      const double sz = qn.cwiseAbs().maxCoeff() + inf_norm(wn) * l.cwiseAbs().maxCoeff();
      const double tol = 4.0 * (nc + 1) * eps * sz;
      if (l.minCoeff() >= 0.0 && g.minCoeff() >= -tol) found = l, ++n_found, residual_tol = tol;
    }
    ASSERT_EQ(n_found, 1) << "seed " << seed << ": the LCP solution is unique (W_nn SPD)";
    // |lambda_gs - lambda_bf| <= ||W_nn^-1||_inf (delta_y + the enumeration's
    // own residual bound): both satisfy the LCP on the same active set to
    // those gap residuals.
    const double bound = inf_norm(wn.inverse()) *
                         (gap_bound(w, q, s.lambda, d, s.report.last_change) + residual_tol);
    double error = 0.0;
    for (int i = 0; i < nc; ++i)
      error = std::max(error, std::abs(s.lambda(2 * i) - found(i)));
    std::printf("  seed %d: |lambda - enumeration| = %.3e N (bound %.3e N, |lambda| %.3e N)\n",
                seed, error, bound, found.cwiseAbs().maxCoeff());
    EXPECT_LE(error, bound) << "seed " << seed;
  }
}

// --- Random well-posed problems: the certificate ---------------------------------

struct Worst {
  int max_sweeps = 0;
  double ratio = 0.0; ///< worst measured / bound over all certificate entries
};

/// The certificate of one solve against its derived bounds (header comment):
///   penetration, stick residual <= delta_y;
///   |g lambda_n| <= delta_y L (open contacts carry lambda_n = 0 exactly);
///   lambda_n >= 0 exactly (each local solution has lambda_n = 0, rho / w_nn,
///   a stick solution checked >= 0 or rho / a positive denominator);
///   cone violation <= (d + 3) eps max(1, mu) L: stick is taken only when its
///   cone test passes as computed (the certificate's norm may round
///   differently by (d + 1) eps |lambda_t|), slip has |lambda_t| =
///   mu lambda_n |e| with |e| = 1 within 2 eps;
///   slip residual <= max over slip contacts of mu lambda_n,c min(2,
///   4 delta_y / |s_c|) + (d + 3) eps mu L: the solver's and the
///   certificate's slips differ by delta_y each, which turns s/|s| by at most
///   2 delta_y / |s_c| each (and |e - s/|s|| <= 2 always);
///   open residual = 0 exactly (open contacts are given lambda = 0).
void check_certificate(const Eigen::MatrixXd& w, const Eigen::VectorXd& q, int d, double mu,
                       const Solved& s, Worst& worst) {
  ASSERT_TRUE(s.report.converged()) << s.report.message;
  const int nc = static_cast<int>(w.rows()) / (1 + d);
  const double l = s.lambda.cwiseAbs().maxCoeff();
  const double dy = gap_bound(w, q, s.lambda, d, s.report.last_change);
  const ReducedCoulombCertificate& c = s.certificate;
  const Eigen::VectorXd y = q + w * s.lambda;
  double slip_bound = 0.0;
  double least_slip = std::numeric_limits<double>::infinity();
  for (int k = 0; k < nc; ++k) {
    if (s.state[k] != ReducedContactState::slip) continue;
    const int o = (1 + d) * k;
    const double slip = y.segment(o + 1, d).norm();
    least_slip = std::min(least_slip, slip);
    slip_bound = std::max(slip_bound, mu * s.lambda(o) * std::min(2.0, 4.0 * dy / slip));
  }
  slip_bound += (d + 3) * eps * mu * l;
  const double cone_bound = (d + 3) * eps * std::max(1.0, mu) * l;
  EXPECT_LE(c.max_penetration, dy);
  EXPECT_GE(c.min_normal, 0.0);
  EXPECT_LE(c.max_complementarity, dy * l);
  EXPECT_LE(c.max_cone_violation, cone_bound);
  EXPECT_LE(c.max_stick_residual, dy);
  EXPECT_LE(c.max_slip_residual, slip_bound);
  EXPECT_EQ(c.max_open_residual, 0.0);
  worst.max_sweeps = std::max(worst.max_sweeps, s.report.sweeps);
  worst.ratio = std::max({worst.ratio, c.max_penetration / dy, c.max_complementarity / (dy * l),
                          c.max_stick_residual / dy,
                          cone_bound > 0.0 ? c.max_cone_violation / cone_bound : 0.0,
                          slip_bound > 0.0 ? c.max_slip_residual / slip_bound : 0.0});
  if (c.n_slip > 0 && mu > 0.0 && least_slip < 1e6 * dy)
    std::printf("  delta_y %.3e m; least |s| of a slip contact %.3e m (%.1e delta_y)\n", dy,
                least_slip, least_slip / dy);
}

/// `seeds` random problems (n dofs, nc contacts) per d and mu: the
/// certificate within its bounds; both stick and slip seen when mu > 0.
void random_well_posed(int n, int nc, const std::vector<int>& ds, const std::vector<double>& mus,
                       int seeds) {
  for (int d : ds) {
    for (double mu : mus) {
      Worst worst;
      int open = 0, stick = 0, slip = 0;
      for (int seed = 0; seed < seeds; ++seed) {
        std::mt19937 rng(1000 * d + 100 * nc + seed);
        const Eigen::MatrixXd w = random_w(n, (1 + d) * nc, rng);
        const Eigen::VectorXd q = random_prediction(nc, d, rng);
        const std::string name = "random nc=" + std::to_string(nc) + " d=" + std::to_string(d) +
                                 " mu=" + std::to_string(mu) + " seed " + std::to_string(seed);
        const Solved s = solve(w, q, d, mu, name.c_str());
        check_certificate(w, q, d, mu, s, worst);
        open += s.certificate.n_open, stick += s.certificate.n_stick, slip += s.certificate.n_slip;
      }
      std::printf("nc=%d d=%d mu=%.2f: at most %d sweeps; worst certificate / bound %.3f; states "
                  "open %d stick %d slip %d\n",
                  nc, d, mu, worst.max_sweeps, worst.ratio, open, stick, slip);
      // The cases exercise what they are for: with friction both stick and
      // slip occur over the seeds (else the certificate checks half the law).
      if (mu > 0.0) {
        EXPECT_GT(stick, 0);
        EXPECT_GT(slip, 0);
      }
    }
  }
}

TEST(CoulombGaussSeidel, RandomWellPosed) {
  random_well_posed(30, 8, {1, 2}, {0.0, 0.15, 0.5}, 20);
}

// At the sizes of the laws: the 2D default case's 22 tips (d = 1) and the
// Rotor 37 case's 16 contact nodes (d = 2).
TEST(CoulombGaussSeidel, RandomAtTheLawsSizes) {
  random_well_posed(60, 22, {1}, {0.15, 0.5}, 10);
  random_well_posed(100, 16, {2}, {0.15, 0.5}, 10);
}

// Near the stick/slip boundary, where s/|s| is ill-conditioned: single
// contacts manufactured to slip with sigma = 10^-k |r| (k = 1 .. 16) and to
// stick with |lambda_t| = mu lambda_n (1 - 10^-k), d = 1 and 2, mu = 0.3.
// The solver must neither fail nor leave the certificate's bounds (the slip
// residual's bound grows as 4 delta_y / |s|, capped at 2 mu lambda_n).
TEST(CoulombGaussSeidel, NearStickSlipBoundary) {
  const double mu = 0.3;
  Worst worst;
  for (int d : {1, 2}) {
    Eigen::MatrixXd w = block_3d().topLeftCorner(1 + d, 1 + d);
    Eigen::VectorXd e(d);
    if (d == 1)
      e << 1.0;
    else
      e << 0.6, 0.8;
    for (int k = 1; k <= 16; ++k) {
      const double small = std::pow(10.0, -k);
      // Slip: lambda = (1, -mu e), y = (0, sigma e).
      Eigen::VectorXd lambda(1 + d), y = Eigen::VectorXd::Zero(1 + d);
      lambda << 1.0, -mu * e;
      y.tail(d) = small * e;
      Eigen::VectorXd q = y - w * lambda;
      const std::string slip_name =
          "slip d=" + std::to_string(d) + " sigma 1e-" + std::to_string(k);
      const Solved slip = solve(w, q, d, mu, slip_name.c_str());
      check_certificate(w, q, d, mu, slip, worst);
      // Stick just inside the cone: lambda = (1, -mu (1 - small) e), y = 0.
      lambda.tail(d) = -mu * (1.0 - small) * e;
      q = -(w * lambda);
      const std::string stick_name =
          "stick d=" + std::to_string(d) + " 1 - 1e-" + std::to_string(k);
      const Solved stick = solve(w, q, d, mu, stick_name.c_str());
      check_certificate(w, q, d, mu, stick, worst);
    }
  }
  std::printf("near the boundary: worst certificate / bound %.3f\n", worst.ratio);
}

// A warm start at the solution: the first sweep changes nothing beyond
// round-off, so the solver stops after one sweep.
TEST(CoulombGaussSeidel, WarmStartAtSolutionStopsAtOnce) {
  std::mt19937 rng(42);
  const int d = 2, nc = 8;
  const Eigen::MatrixXd w = random_w(30, (1 + d) * nc, rng);
  const Eigen::VectorXd q = random_prediction(nc, d, rng);
  CoulombGaussSeidel solver(d, 0.15);
  Eigen::VectorXd lambda;
  const CoulombGaussSeidelReport first = solver.solve(w, q, lambda);
  ASSERT_TRUE(first.converged()) << first.message;
  const CoulombGaussSeidelReport again = solver.solve(w, q, lambda);
  std::printf("cold start %d sweeps, warm start %d sweeps\n", first.sweeps, again.sweeps);
  ASSERT_TRUE(again.converged()) << again.message;
  EXPECT_EQ(again.sweeps, 1);
}

// --- The default 2D case's W ----------------------------------------------------

/// W = dt^2 (B_q M^-1 B_q^T + B_c M_c^-1 B_c^T) of the default case (SPEC §2:
/// CB-10 bladed disk, full casing) at rest, t = 0, for the 22 tips, ordered
/// (n, t) per tip: the normal row is -e(u_k) on q and the Hermite values N
/// on the casing's (u, u_s); the tangential row +e(v_k) on q and -N on the
/// casing's (v, v_s) (the sliding of reduced_contact.hpp).
Eigen::MatrixXd default_case_w(double& dt) {
  const Case c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
  const BladedDisk disk = assemble_bladed_disk(c);
  const ReducedBasis basis = reduce_bladed_disk(disk, "cb", 10);
  const Casing casing = assemble_casing(c);
  const ReducedTipContact contact(basis, casing, c);
  std::vector<TipContact> tips;
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(basis.n_reduced());
  const Eigen::VectorXd c0 = Eigen::VectorXd::Zero(casing.n_dofs());
  dt = c.time.step;
  contact.evaluate(q0, q0, c0, c0, dt, 0.0, tips);
  const int nc = contact.n_tips();
  Eigen::MatrixXd bq = Eigen::MatrixXd::Zero(2 * nc, basis.n_reduced());
  Eigen::MatrixXd bc = Eigen::MatrixXd::Zero(2 * nc, casing.n_dofs());
  for (int k = 0; k < nc; ++k) {
    bq(2 * k, tips[k].q_u) = -1.0;
    bq(2 * k + 1, tips[k].q_v) = 1.0;
    for (int a = 0; a < 4; ++a) {
      if (tips[k].c_u[a] >= 0) bc(2 * k, tips[k].c_u[a]) = tips[k].shape[a];
      if (tips[k].c_v[a] >= 0) bc(2 * k + 1, tips[k].c_v[a]) = -tips[k].shape[a];
    }
  }
  const Eigen::LLT<Eigen::MatrixXd> mq(basis.mass);
  const Eigen::LLT<Eigen::MatrixXd> mc{Eigen::MatrixXd(casing.mass)};
  EXPECT_EQ(mq.info(), Eigen::Success);
  EXPECT_EQ(mc.info(), Eigen::Success);
  const Eigen::MatrixXd xq = mq.solve(bq.transpose());
  const Eigen::MatrixXd xc = mc.solve(bc.transpose());
  const Eigen::MatrixXd w = dt * dt * (bq * xq + bc * xc);
  return 0.5 * (w + w.transpose());
}

// All 22 tips closing at once (predicted gaps -0.1 .. -1 um), sliding as at
// the operating point (s~ = Omega R_t dt = 7.7e-5 m per step, +-10 %) and as
// at rest (s~ within +-10 nm: sticking): converged, the certificate within
// its bounds (check_certificate), sweeps printed. Not a run: one step's
// problem, with the model's own coupling between the tips.
TEST(CoulombGaussSeidel, DefaultCaseW) {
  double dt = 0.0;
  const Eigen::MatrixXd w = default_case_w(dt);
  const int nc = static_cast<int>(w.rows()) / 2;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(w);
  double coupling = 0.0; // largest off-diagonal |W_ij| / sqrt(W_ii W_jj) between tips' normals
  for (int i = 0; i < nc; ++i)
    for (int j = 0; j < nc; ++j)
      if (i != j)
        coupling = std::max(coupling, std::abs(w(2 * i, 2 * j)) /
                                          std::sqrt(w(2 * i, 2 * i) * w(2 * j, 2 * j)));
  std::printf(
      "default case W: %d tips, eigenvalues %.3e .. %.3e m/N, largest normal coupling %.3f\n", nc,
      spectrum.eigenvalues().minCoeff(), spectrum.eigenvalues().maxCoeff(), coupling);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double omega = 310.0, tip_radius = 0.5;
  for (const double sliding : {omega * tip_radius * dt, 0.0}) {
    for (double mu : {0.15, 0.5}) {
      Eigen::VectorXd q(2 * nc);
      for (int k = 0; k < nc; ++k) {
        q(2 * k) = -1e-6 * (0.1 + 0.9 * unit(rng));
        q(2 * k + 1) = sliding * (0.9 + 0.2 * unit(rng)) + 1e-8 * (2.0 * unit(rng) - 1.0);
      }
      const std::string name =
          std::string(sliding > 0.0 ? "sliding" : "at rest") + ", mu " + std::to_string(mu);
      const Solved s = solve(w, q, 1, mu, name.c_str());
      Worst worst;
      check_certificate(w, q, 1, mu, s, worst);
      std::printf("  worst certificate / bound %.3f\n", worst.ratio);
    }
  }
}

// --- Failures reported ---------------------------------------------------------

/// Random W whose contact `zero`'s normal row of B is zero: W's row and
/// column of that normal vanish, W_cc is singular.
Eigen::MatrixXd w_with_zero_normal(int d, int nc, int zero, std::mt19937& rng) {
  Eigen::MatrixXd w = random_w(20, (1 + d) * nc, rng);
  const int o = (1 + d) * zero;
  w.row(o).setZero();
  w.col(o).setZero();
  return w;
}

TEST(CoulombGaussSeidel, SingularBlockReportedWhenClosing) {
  for (int d : {1, 2}) {
    for (double mu : {0.0, 0.15}) {
      std::mt19937 rng(5);
      const int nc = 3;
      const Eigen::MatrixXd w = w_with_zero_normal(d, nc, 1, rng);
      Eigen::VectorXd q = random_prediction(nc, d, rng);
      q((1 + d) * 1) = -1e-6; // contact 1 closes: nothing in W can open it
      CoulombGaussSeidel solver(d, mu);
      Eigen::VectorXd lambda;
      const CoulombGaussSeidelReport r = solver.solve(w, q, lambda);
      std::printf("d=%d mu=%.2f: %s\n", d, mu, r.message.c_str());
      EXPECT_EQ(r.status, CoulombSweepStatus::singular_block);
      EXPECT_EQ(r.failed_contact, 1);
      EXPECT_NE(r.message.find("contact 1"), std::string::npos);
      EXPECT_NE(r.message.find("singular"), std::string::npos);
    }
  }
}

// A contact whose TANGENTIAL rows of W are zero (d = 1): frictionless, only
// w_nn matters and the step is solved; with friction its stick multiplier is
// not determined (W_cc singular), reported when it closes.
TEST(CoulombGaussSeidel, ZeroTangentialRow) {
  std::mt19937 rng(9);
  const int d = 1, nc = 3;
  Eigen::MatrixXd w = random_w(20, (1 + d) * nc, rng);
  w.row(3).setZero(); // contact 1's tangential row and column
  w.col(3).setZero();
  Eigen::VectorXd q = random_prediction(nc, d, rng);
  q(2) = -1e-6; // contact 1 closes
  const Solved frictionless = solve(w, q, d, 0.0, "zero tangential row, mu 0");
  Worst worst;
  check_certificate(w, q, d, 0.0, frictionless, worst);
  EXPECT_GT(frictionless.lambda(2), 0.0) << "contact 1 closed";
  CoulombGaussSeidel solver(d, 0.15);
  Eigen::VectorXd lambda;
  const CoulombGaussSeidelReport r = solver.solve(w, q, lambda);
  std::printf("mu 0.15: %s\n", r.message.c_str());
  EXPECT_EQ(r.status, CoulombSweepStatus::singular_block);
  EXPECT_EQ(r.failed_contact, 1);
}

// The same W with contact 1 open (g~ > 0; its normal row of W is zero, so no
// other contact can close it): solved, contact 1 open with lambda = 0.
TEST(CoulombGaussSeidel, SingularBlockHarmlessWhenOpen) {
  for (int d : {1, 2}) {
    std::mt19937 rng(5);
    const int nc = 3;
    const Eigen::MatrixXd w = w_with_zero_normal(d, nc, 1, rng);
    Eigen::VectorXd q = random_prediction(nc, d, rng);
    q((1 + d) * 1) = 1e-6;
    q(0) = q((1 + d) * 2) = -1e-6; // the others close: contact 1 must stay open among them
    const Solved s = solve(w, q, d, 0.15, "zero normal row, open");
    ASSERT_TRUE(s.report.converged()) << s.report.message;
    EXPECT_EQ(s.state[1], ReducedContactState::open);
    EXPECT_EQ(s.lambda.segment(1 + d, 1 + d).cwiseAbs().maxCoeff(), 0.0);
    Worst worst;
    check_certificate(w, q, d, 0.15, s, worst);
  }
}

// One sweep is not enough on a coupled problem (the first sweep moves every
// closing contact from 0): reported as max_sweeps, with a message.
TEST(CoulombGaussSeidel, NonConvergenceReported) {
  std::mt19937 rng(3);
  const int d = 1, nc = 8;
  const Eigen::MatrixXd w = random_w(30, (1 + d) * nc, rng);
  const Eigen::VectorXd q = random_prediction(nc, d, rng);
  CoulombGaussSeidelOptions options;
  options.max_sweeps = 1;
  CoulombGaussSeidel solver(d, 0.15, options);
  Eigen::VectorXd lambda;
  const CoulombGaussSeidelReport r = solver.solve(w, q, lambda);
  std::printf("%s\n", r.message.c_str());
  EXPECT_EQ(r.status, CoulombSweepStatus::max_sweeps);
  EXPECT_NE(r.message.find("no convergence in 1 sweeps"), std::string::npos);
}

// --- Bad arguments ---------------------------------------------------------------

/// `call` throws std::invalid_argument whose message names `parameter`.
template <class F> void expect_rejected(F call, const std::string& parameter) {
  try {
    call();
    ADD_FAILURE() << "no exception for a bad " << parameter;
  } catch (const std::invalid_argument& e) {
    std::printf("rejected: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos) << e.what();
  }
}

TEST(CoulombGaussSeidel, BadArgumentsRejected) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_rejected([] { CoulombGaussSeidel(0, 0.1); },
                  "d (tangential directions) = 0, allowed 1 or 2");
  expect_rejected([] { CoulombGaussSeidel(3, 0.1); }, "d (tangential directions) = 3");
  expect_rejected([] { CoulombGaussSeidel(1, -0.1); }, "mu = -0.1, allowed a finite value >= 0");
  expect_rejected([nan] { CoulombGaussSeidel(1, nan); }, "mu = ");
  expect_rejected([] { CoulombGaussSeidel(1, std::numeric_limits<double>::infinity()); }, "mu = ");
  CoulombGaussSeidelOptions o;
  o.max_sweeps = 0;
  expect_rejected([o] { CoulombGaussSeidel(1, 0.1, o); }, "max_sweeps = 0, allowed >= 1");
  o = {};
  o.relative_change = 1.0;
  expect_rejected([o] { CoulombGaussSeidel(1, 0.1, o); }, "relative_change = 1, allowed [0, 1)");
  o = {};
  o.singular_tolerance = 0.0;
  expect_rejected([o] { CoulombGaussSeidel(1, 0.1, o); }, "singular_tolerance = 0, allowed (0, 1)");
  o = {};
  o.local_violation = 2.0;
  expect_rejected([o] { CoulombGaussSeidel(1, 0.1, o); }, "local_violation = 2, allowed (0, 1)");

  CoulombGaussSeidel solver(1, 0.1);
  Eigen::VectorXd lambda;
  expect_rejected(
      [&] { solver.solve(Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Zero(3), lambda); },
      "W is 3 x 3, allowed square of size (1+d) nc");
  expect_rejected(
      [&] { solver.solve(Eigen::MatrixXd::Identity(4, 2), Eigen::VectorXd::Zero(4), lambda); },
      "W is 4 x 2");
  expect_rejected(
      [&] { solver.solve(Eigen::MatrixXd::Identity(4, 4), Eigen::VectorXd::Zero(2), lambda); },
      "predicted has 2 entries, allowed W's size 4");
  Eigen::MatrixXd bad = Eigen::MatrixXd::Identity(2, 2);
  bad(0, 1) = nan;
  expect_rejected([&] { solver.solve(bad, Eigen::VectorXd::Zero(2), lambda); },
                  "W: entries must be finite");
  expect_rejected(
      [&] { solver.solve(Eigen::MatrixXd::Identity(2, 2), Eigen::Vector2d(nan, 0.0), lambda); },
      "predicted: entries must be finite");
  expect_rejected(
      [&] {
        reduced_coulomb_certificate(Eigen::MatrixXd::Identity(2, 2), Eigen::VectorXd::Zero(2), 1,
                                    0.1, Eigen::VectorXd::Zero(2), {});
      },
      "state must have one entry per contact (1), got 0");
}

// --- The certificate on its own ----------------------------------------------------

// Hand-made: W = I (d = 1, two contacts), predicted (g~, s~) and lambda
// chosen so that every entry has a known value:
//   contact 0, stick claimed: lambda = (1, 0.75), mu = 0.5: cone violation
//   0.75 - 0.5 = 0.25; y = (-0.5 + 1, 0.25 + 0.75) = (0.5, 1): g lambda_n = 0.5,
//   stick residual |s| = 1;
//   contact 1, slip claimed: lambda = (2, 0.5), predicted (-2.25, 1.5):
//   y = (-0.25, 2): penetration 0.25, |g lambda_n| = 0.5, slip residual
//   |0.5 + 0.5 * 2 * 1| = 1.5, cone 0.5 - 1 < 0.
// All values dyadic: exact in binary, compared with ==.
TEST(ReducedCoulombCertificate, HandMadeValues) {
  const Eigen::MatrixXd w = Eigen::MatrixXd::Identity(4, 4);
  const Eigen::VectorXd q = (Eigen::VectorXd(4) << -0.5, 0.25, -2.25, 1.5).finished();
  const Eigen::VectorXd l = (Eigen::VectorXd(4) << 1.0, 0.75, 2.0, 0.5).finished();
  const ReducedCoulombCertificate c = reduced_coulomb_certificate(
      w, q, 1, 0.5, l, {ReducedContactState::stick, ReducedContactState::slip});
  EXPECT_EQ(c.max_penetration, 0.25);
  EXPECT_EQ(c.min_normal, 1.0);
  EXPECT_EQ(c.max_complementarity, 0.5);
  EXPECT_EQ(c.max_cone_violation, 0.25);
  EXPECT_EQ(c.max_stick_residual, 1.0);
  EXPECT_EQ(c.max_slip_residual, 1.5);
  EXPECT_EQ(c.max_open_residual, 0.0);
  EXPECT_EQ(c.n_stick, 1);
  EXPECT_EQ(c.n_slip, 1);
  EXPECT_EQ(c.n_open, 0);
}

} // namespace
} // namespace rsi

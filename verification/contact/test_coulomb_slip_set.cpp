// V5 (issue 26): CoulombSlipSet, the direct solve of a contact step whose
// closed contacts all slip (coulomb_slip_set.hpp), d = 2 (n, t1, t2):
//   - a single decoupled contact against its closed form;
//   - random sliding problems: accepted, the certificate within bounds derived
//     from the header's acceptance conditions, lambda and the states equal to
//     CoulombGaussSeidel's within a perturbation bound (derived below);
//   - a sticking contact declined (lambda untouched), a warm start, all open,
//     bad arguments.
//
// Comparing two solutions (expect_equal_solutions). Both have the same states and
// lambda = 0 on the open contacts. On S (the slipping contacts) write
// x = lambda_n, t = lambda_t, E(lambda) the 2k x k block diagonal of the
// directions e_c = s_c/|s_c|, and the exact residuals r_g = g_S,
// r_t = t + mu E x. With delta = a - b: t_a - t_b = -mu E_a dx - mu (E_a -
// E_b) x_b + dr_t and W_nS,: dlambda = dr_g, so with A_S = W_nn - mu W_nt E_a
// (the header's (1)): A_S dx = dr_g - W_nt dr_t + mu W_nt (E_a - E_b) x_b.
// |e_a - e_b| <= 2 |ds_c| / |s_c| <= 2 ||W|| |dlambda| / s_min, so with
// eta = 2 mu ||W|| |x_b| / s_min, a = 1/sigma_min(A_S) (2-norms throughout):
//   |dx| <= a (|dr_g| + ||W|| |dr_t| + ||W|| eta |dlambda|),
//   |dt| <= mu |dx| + eta |dlambda| + |dr_t|, |dlambda| <= |dx| + |dt|:
//   |dlambda| <= ((1+mu) a (|dr_g| + ||W|| |dr_t|) + |dr_t|)
//                / (1 - eta ((1+mu) a ||W|| + 1)),
// required: the denominator >= 1/2. The residuals are each solution's own,
// evaluated in long double (64-bit mantissa) plus that evaluation's rounding
// ((m+1) eps_ld of the row's terms, m = 3 nc; 2 sqrt(2) of it over |s| for a
// direction, 10 eps_ld for the residual's arithmetic). A_S is formed from
// a's directions rounded to double: sigma_min moves by about eps ||A_S||.

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "coulomb_gauss_seidel.hpp"
#include "coulomb_slip_set.hpp"
#include "random_delassus.hpp"
#include "reduced_coulomb_certificate.hpp"

namespace rsi {
namespace {

using State = ReducedContactState;
using VectorL = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr long double eps_ld = std::numeric_limits<long double>::epsilon();
static_assert(std::numeric_limits<long double>::digits >= 64,
              "the residuals need extended precision");

/// W = dt^2 B M^-1 B^T (as test_coulomb_gauss_seidel.cpp), dt = 5e-7:
/// random SPD M (n dofs), random B (rows x n): W SPD (random_delassus.hpp).
Eigen::MatrixXd random_w(int n, int rows, std::mt19937& rng) {
  return random_delassus(n, rows, 5e-7 * 5e-7, rng);
}

/// Gaps uniform in [-1, 1] um, every fourth shifted up 1 um (some open, some
/// closing); slips of random direction, |s~| uniform in [5, 10] mm, thousands
/// of times W's tangential response |(W lambda)_t| (printed), so that eta of
/// the header comment stays about 1e-3.
Eigen::VectorXd sliding_prediction(int nc, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Eigen::VectorXd q(3 * nc);
  for (int c = 0; c < nc; ++c) {
    const double angle = 2.0 * M_PI * unit(rng), size = 5e-3 * (1.0 + unit(rng));
    q.segment<3>(3 * c) << 1e-6 * (2.0 * unit(rng) - 1.0 + (c % 4 == 0 ? 1.0 : 0.0)),
        size * std::cos(angle), size * std::sin(angle);
  }
  return q;
}

/// Exact residuals (long double) of lambda on its slipping contacts, 2-norms
/// over S plus the evaluation's rounding (header); x norm, least |s|, e.
struct Residual {
  double gap = 0.0, slip = 0.0, x = 0.0, s_min = INFINITY;
  Eigen::Matrix2Xd e;
};

Residual residual(const Eigen::MatrixXd& w, const Eigen::VectorXd& q, double mu,
                  const Eigen::VectorXd& lambda, const std::vector<int>& set) {
  const int m = static_cast<int>(w.rows());
  const VectorL l = lambda.cast<long double>();
  const VectorL y = q.cast<long double>() + w.cast<long double>() * l;
  const Eigen::VectorXd terms = q.cwiseAbs() + w.cwiseAbs() * lambda.cwiseAbs();
  Residual r;
  r.e.resize(2, set.size());
  long double gap = 0, slip = 0, x = 0;
  for (size_t i = 0; i < set.size(); ++i) {
    const int o = 3 * set[i];
    const long double ln = l(o), s = std::sqrt(y(o + 1) * y(o + 1) + y(o + 2) * y(o + 2));
    const long double rt =
        std::hypot(l(o + 1) + mu * ln * y(o + 1) / s, l(o + 2) + mu * ln * y(o + 2) / s);
    const double sigma = std::max(terms(o + 1), terms(o + 2));
    const long double g = std::abs(y(o)) + (m + 1) * eps_ld * terms(o);
    const long double t =
        rt + mu * ln * eps_ld * (2.0L * std::sqrt(2.0L) * (m + 1) * sigma / s + 10);
    gap += g * g, slip += t * t, x += ln * ln;
    r.e.col(i) << static_cast<double>(y(o + 1) / s), static_cast<double>(y(o + 2) / s);
    r.s_min = std::min(r.s_min, static_cast<double>(s));
  }
  r.gap = std::sqrt(static_cast<double>(gap)), r.slip = std::sqrt(static_cast<double>(slip));
  r.x = std::sqrt(static_cast<double>(x));
  return r;
}

std::vector<int> slipping(const std::vector<State>& state) {
  std::vector<int> set;
  for (size_t c = 0; c < state.size(); ++c)
    if (state[c] == State::slip) set.push_back(static_cast<int>(c));
  return set;
}

/// |a - b|_2 against the bound of the header comment (same states assumed).
void expect_equal_solutions(const Eigen::MatrixXd& w, const Eigen::VectorXd& q, double mu,
                            const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                            const std::vector<State>& state) {
  const std::vector<int> set = slipping(state);
  const int k = static_cast<int>(set.size());
  ASSERT_GT(k, 0);
  const Residual ra = residual(w, q, mu, a, set), rb = residual(w, q, mu, b, set);
  Eigen::MatrixXd as(k, k);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const int ni = 3 * set[i], nj = 3 * set[j];
      as(i, j) = w(ni, nj) - mu * (w(ni, nj + 1) * ra.e(0, j) + w(ni, nj + 2) * ra.e(1, j));
    }
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(as).singularValues();
  const double wn = Eigen::JacobiSVD<Eigen::MatrixXd>(w).singularValues()(0);
  const double ainv = 1.0 / sv(k - 1), eta = 2.0 * mu * wn * rb.x / ra.s_min;
  const double denominator = 1.0 - eta * ((1.0 + mu) * ainv * wn + 1.0);
  ASSERT_GE(denominator, 0.5);
  const double dg = ra.gap + rb.gap, dt = ra.slip + rb.slip;
  const double bound = ((1.0 + mu) * ainv * (dg + wn * dt) + dt) / denominator;
  const double error = (a - b).norm();
  std::printf("  k %d, cond(A_S) %.3e, eta %.2e, residuals |r_g| %.2e + %.2e m, |r_t| %.2e + "
              "%.2e N; |difference| %.3e N (bound %.3e, |lambda| %.3e N)\n",
              k, sv(0) * ainv, eta, ra.gap, rb.gap, ra.slip, rb.slip, error, bound, a.norm());
  EXPECT_LE(error, bound);
  double open = 0.0; // lambda on the open contacts, both solutions: 0 exactly
  for (int c = 0; c < static_cast<int>(state.size()); ++c)
    if (state[c] == State::open) open += a.segment<3>(3 * c).norm() + b.segment<3>(3 * c).norm();
  EXPECT_EQ(open, 0.0);
}

/// The slip set's certificate against the header's acceptance conditions:
/// its checked gap |y_c| <= (6k+10) eps size_c (size_c = |g~_c| + the row's
/// |W||lambda|), and the certificate's y differs from the solver's by both
/// sums' rounding, (3k+1) eps size_c: penetration <= (9k+11) eps size_c and
/// |g lambda_n| <= that times lambda_n (1 + eps). Slip: lambda_t + mu lambda_n
/// e = mu lambda_n (e - e') <= 8 sqrt(2) eps mu lambda_n in norm; per entry
/// e against the exact direction of the solver's s 3 eps/2, lambda_t's
/// product eps, the certificate's arithmetic 3 eps (|s|, mu lambda_n, the
/// division, the product, the sum): 5.5 sqrt(2) < 9 eps in norm; the two s differ by (3k+1) eps
/// sigma_c per entry (sigma_c the slip rows' terms), 2 sqrt(2) (3k+1) eps sigma_c/|s_c| on the
/// direction. Cone <= 5 eps mu lambda_n (|e'| 1 + 3 eps/2, the product eps, the certificate's norm
/// and mu lambda_n 3 eps/2). Open: lambda = 0.
void expect_certificate(const Eigen::MatrixXd& w, const Eigen::VectorXd& q, double mu,
                        const Eigen::VectorXd& lambda, const std::vector<State>& state) {
  const ReducedCoulombCertificate c = reduced_coulomb_certificate(w, q, 2, mu, lambda, state);
  const int k = static_cast<int>(slipping(state).size());
  const Eigen::VectorXd terms = q.cwiseAbs() + w.cwiseAbs() * lambda.cwiseAbs();
  const Eigen::VectorXd y = q + w * lambda;
  double pen = 0.0, comp = 0.0, cone = 0.0, slip = 0.0;
  for (int o = 0; o < q.size(); o += 3) {
    const double gap = (9.0 * k + 11.0) * eps * terms(o), ln = lambda(o);
    pen = std::max(pen, gap), comp = std::max(comp, gap * ln * (1.0 + eps));
    if (state[o / 3] != State::slip) continue;
    const double sigma = std::max(terms(o + 1), terms(o + 2)), s = y.segment<2>(o + 1).norm();
    cone = std::max(cone, 5.0 * eps * mu * ln);
    slip = std::max(
        slip, mu * ln * eps *
                  (8.0 * std::sqrt(2.0) + 9.0 + 2.0 * std::sqrt(2.0) * (3 * k + 1) * sigma / s));
  }
  std::printf("  certificate / bound: penetration %.3f, complementarity %.3f, cone %.3f, slip "
              "%.3f; min lambda_n %.3e, open residual %.1e\n",
              c.max_penetration / pen, c.max_complementarity / comp,
              cone > 0 ? c.max_cone_violation / cone : 0.0,
              slip > 0 ? c.max_slip_residual / slip : 0.0, c.min_normal, c.max_open_residual);
  EXPECT_LE(c.max_penetration, pen);
  EXPECT_LE(c.max_complementarity, comp);
  EXPECT_LE(c.max_cone_violation, cone);
  EXPECT_LE(c.max_slip_residual, slip);
  EXPECT_GE(c.min_normal, 0.0);
  EXPECT_EQ(c.max_open_residual, 0.0);
  EXPECT_EQ(c.n_stick, 0);
}

// W = diag(w_n, w_t, w_t), g~ < 0, s~ = (a, b). Closed: g = g~ + w_n
// lambda_n = 0, lambda_n = -g~/w_n (no coupling: (1) is w_n lambda_n = -g~).
// Slip: lambda_t = -mu lambda_n e, s = s~ + w_t lambda_t = s~ - mu lambda_n
// w_t e, parallel to s~ with the factor 1 - mu lambda_n w_t / |s~| > 0 when
// |s~| > mu lambda_n w_t; then e = s~/|s~|. Here lambda_n = 52 N,
// mu lambda_n w_t = 0.62 um against |s~| = 38 um (stick would need
// |lambda_t| = |s~|/w_t = 950 N > mu lambda_n = 15.6 N).
TEST(CoulombSlipSet, SingleContactClosedForm) {
  const double wn = 2.5e-8, wt = 4e-8, g = -1.3e-6, a = 3.1e-5, b = -2.2e-5, mu = 0.3;
  const Eigen::MatrixXd w = Eigen::Vector3d(wn, wt, wt).asDiagonal();
  const Eigen::VectorXd q = Eigen::Vector3d(g, a, b);
  CoulombSlipSet solver(mu);
  Eigen::VectorXd lambda;
  ASSERT_TRUE(solver.solve(w, q, lambda));
  ASSERT_EQ(solver.states().size(), 1u);
  EXPECT_EQ(solver.states()[0], State::slip);
  // The closed form in long double (its own rounding ~1e-3 eps, negligible).
  const long double ln = -static_cast<long double>(g) / wn,
                    ns = std::hypot((long double)a, (long double)b);
  const long double lt1 = -mu * ln * a / ns, lt2 = -mu * ln * b / ns;
  // lambda_n: one division (eps/2), bound eps relative. lambda_t,i =
  // (-mu lambda_n) e'_i, e' = s~/|s~|: lambda_n eps/2, the products 2 eps/2,
  // |s~| 2 eps/2 (squares, sum, sqrt), the division eps/2: 3 eps; bound 4 eps.
  const double en = std::abs(lambda(0) - ln) / ln;
  const double et = std::max(std::abs(lambda(1) - lt1), std::abs(lambda(2) - lt2)) / (mu * ln);
  std::printf("%d solve(s); |lambda_n - closed| / lambda_n = %.2e eps, max |lambda_t - closed| / "
              "(mu lambda_n) = %.2e eps\n",
              solver.iterations(), en / eps, et / eps);
  EXPECT_LE(en, eps);
  EXPECT_LE(et, 4.0 * eps);
  expect_certificate(w, q, mu, lambda, solver.states());
}

// 16 contacts, mu 0.15 and 0.5, 10 seeds each: accepted (sliding by
// construction: |s~| >= 5 mm against |(W lambda)_t| of about 1 um, the ratio
// printed and asserted >= 100, and the Gauss-Seidel finds no stick), the
// certificate within its bounds, and the Gauss-Seidel's lambda and states.
TEST(CoulombSlipSet, RandomSlidingAgainstCertificateAndGaussSeidel) {
  const int nc = 16;
  for (double mu : {0.15, 0.5}) {
    for (int seed = 0; seed < 10; ++seed) {
      std::mt19937 rng(700 + seed);
      const Eigen::MatrixXd w = random_w(100, 3 * nc, rng);
      const Eigen::VectorXd q = sliding_prediction(nc, rng);
      CoulombSlipSet solver(mu);
      Eigen::VectorXd lambda;
      ASSERT_TRUE(solver.solve(w, q, lambda)) << "mu " << mu << " seed " << seed;
      const Eigen::VectorXd response = w * lambda;
      double ratio = INFINITY;
      for (int c = 0; c < nc; ++c)
        ratio =
            std::min(ratio, q.segment<2>(3 * c + 1).norm() / response.segment<2>(3 * c + 1).norm());
      const std::vector<int> set = slipping(solver.states());
      std::printf("mu %.2f seed %d: %d solves, %zu slip, min |s~| / |(W lambda)_t| %.0f\n", mu,
                  seed, solver.iterations(), set.size(), ratio);
      EXPECT_GE(ratio, 100.0);
      expect_certificate(w, q, mu, lambda, solver.states());
      CoulombGaussSeidel gs(2, mu);
      Eigen::VectorXd lambda_gs;
      const CoulombGaussSeidelReport report = gs.solve(w, q, lambda_gs);
      ASSERT_TRUE(report.converged()) << report.message;
      ASSERT_EQ(gs.states(), solver.states()) << "mu " << mu << " seed " << seed;
      // The Gauss-Seidel's own residuals (rb in expect_equal_solutions) small:
      // its gaps within delta_y of test_coulomb_gauss_seidel.cpp's header,
      // ||W||_inf Delta + (3m + nc + 2 + 8 (1+d)) eps S, m = 3 nc, d = 2.
      const ReducedCoulombCertificate gc =
          reduced_coulomb_certificate(w, q, 2, mu, lambda_gs, gs.states());
      const double l_gs = lambda_gs.cwiseAbs().maxCoeff();
      const double w_inf = w.cwiseAbs().rowwise().sum().maxCoeff();
      const double delta_y =
          w_inf * report.last_change +
          (3.0 * 3 * nc + nc + 2 + 8.0 * 3) * eps * (q.cwiseAbs().maxCoeff() + w_inf * l_gs);
      EXPECT_LE(gc.max_penetration, delta_y);
      EXPECT_LE(gc.max_complementarity, delta_y * l_gs);
      expect_equal_solutions(w, q, mu, lambda, lambda_gs, solver.states());
    }
  }
}

// Contact 2 sticks: tiny s~ (1e-10 m) against the response of its own
// force; W's blocks between contacts scaled by 0.05 (0.05 W + 0.95
// blockdiag(W), SPD as a convex combination of SPD matrices) so that its
// neighbours' friction does not drag it. Checked with the Gauss-Seidel:
// stick, |lambda_t| < mu lambda_n. Declined, lambda bitwise unchanged, for
// no warm start (empty, or a vector of another size) and for the
// Gauss-Seidel's solution as warm start.
TEST(CoulombSlipSet, StickingContactDeclined) {
  const int nc = 4;
  const double mu = 0.5;
  std::mt19937 rng(31);
  const Eigen::MatrixXd full = random_w(40, 3 * nc, rng);
  Eigen::MatrixXd w = 0.05 * full;
  for (int c = 0; c < nc; ++c)
    w.block<3, 3>(3 * c, 3 * c) = full.block<3, 3>(3 * c, 3 * c);
  Eigen::VectorXd q = sliding_prediction(nc, rng);
  for (int c = 0; c < nc; ++c)
    q(3 * c) = -1e-6 * (0.5 + 0.1 * c);
  q.segment<2>(7) *= 1e-10 / q.segment<2>(7).norm();
  CoulombGaussSeidel gs(2, mu);
  Eigen::VectorXd lambda_gs;
  ASSERT_TRUE(gs.solve(w, q, lambda_gs).converged());
  const double cone = lambda_gs.segment<2>(7).norm() / (mu * lambda_gs(6));
  std::printf("Gauss-Seidel: contact 2 %s, |lambda_t| / (mu lambda_n) = %.3f\n",
              to_string(gs.states()[2]), cone);
  ASSERT_EQ(gs.states()[2], State::stick);
  ASSERT_LT(cone, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Eigen::VectorXd& start :
       {Eigen::VectorXd(), Eigen::VectorXd(Eigen::Vector4d(1.0, -2.0, nan, 3.5)), lambda_gs}) {
    CoulombSlipSet solver(mu);
    Eigen::VectorXd lambda = start;
    const bool accepted = solver.solve(w, q, lambda);
    std::printf("  start of size %td: %s after %d solves\n", start.size(),
                accepted ? "accepted" : "declined", solver.iterations());
    EXPECT_FALSE(accepted);
    ASSERT_EQ(lambda.size(), start.size());
    if (start.size() > 0) { // memcmp of null pointers is undefined
      EXPECT_EQ(std::memcmp(lambda.data(), start.data(), sizeof(double) * start.size()), 0);
    }
  }
}

// The sliding problem of seed 3, mu 0.15, solved; predicted perturbed by
// 1e-3 relative per entry; solved again cold and warm (from the first
// lambda): both accepted with the same states, equal within the bound of
// the header comment.
TEST(CoulombSlipSet, WarmStartEqualsColdSolve) {
  const int nc = 16;
  const double mu = 0.15;
  std::mt19937 rng(703);
  const Eigen::MatrixXd w = random_w(100, 3 * nc, rng);
  const Eigen::VectorXd q = sliding_prediction(nc, rng);
  CoulombSlipSet solver(mu);
  Eigen::VectorXd first;
  ASSERT_TRUE(solver.solve(w, q, first));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd perturbed = q;
  for (int i = 0; i < q.size(); ++i)
    perturbed(i) *= 1.0 + 1e-3 * unit(rng);
  Eigen::VectorXd cold, warm = first;
  ASSERT_TRUE(solver.solve(w, perturbed, cold));
  const std::vector<State> cold_states = solver.states();
  const int cold_solves = solver.iterations();
  ASSERT_TRUE(solver.solve(w, perturbed, warm));
  std::printf("cold %d solves, warm %d solves; |warm - first| %.3e N\n", cold_solves,
              solver.iterations(), (warm - first).norm());
  ASSERT_EQ(solver.states(), cold_states);
  expect_certificate(w, perturbed, mu, cold, cold_states);
  expect_certificate(w, perturbed, mu, warm, cold_states);
  expect_equal_solutions(w, perturbed, mu, warm, cold, cold_states);
}

// A contact that the other's force closes joins the set. Two contacts, W =
// 1e-8 [1 0 0 -0.5 0 0; 0 1 0 0 0 0; 0 0 1 0 0 0; -0.5 0 0 1 0 0; 0 0 0 0 1
// 0; 0 0 0 0 0 1] (eigenvalues 0.5e-8, 1e-8, 1.5e-8: SPD), g~ = (-1e-6,
// 1e-7), s~_A = (3e-3, 0), s~_B = (0, 3e-3): only A closes at the
// prediction; alone it takes lambda_n = 1e-6 / 1e-8 = 100 N, which puts B's
// gap at 1e-7 - 0.5e-8 100 = -4e-7 < 0. W_nt = 0, so (1) is W_nn's
// block: 1e-8 [1 -0.5; -0.5 1] lambda_n = (1e-6, -1e-7), lambda_n =
// (0.95e-6, 0.4e-6) / 0.75e-8 = (126.666..., 53.333...) N, both > 0; W_tt =
// 1e-8 I keeps each slip along its s~ (s_A = (3e-3 - 1e-8 mu lambda_A, 0)),
// so lambda_t = -mu lambda_n e with e = s~/|s~|.
TEST(CoulombSlipSet, ContactClosedByTheOthersJoins) {
  const double mu = 0.3;
  Eigen::MatrixXd w = Eigen::MatrixXd::Identity(6, 6);
  w(0, 3) = w(3, 0) = -0.5;
  w *= 1e-8;
  Eigen::VectorXd q(6);
  q << -1e-6, 3e-3, 0.0, 1e-7, 0.0, 3e-3;
  CoulombSlipSet solver(mu);
  Eigen::VectorXd lambda;
  ASSERT_TRUE(solver.solve(w, q, lambda));
  ASSERT_EQ(solver.states(), std::vector<State>(2, State::slip));
  Eigen::VectorXd expected(6);
  const double la = 0.95e-6 / 0.75e-8, lb = 0.4e-6 / 0.75e-8;
  expected << la, -mu * la, 0.0, lb, 0.0, -mu * lb;
  // The 2 x 2 solve: LU's backward error about 3 * 2 eps on terms of the
  // solution's size, cond 3 (eigenvalues 0.5 and 1.5 of the block), plus
  // the decimal data's rounding (eps/2 each): within 40 eps of max |lambda|.
  const double error = (lambda - expected).cwiseAbs().maxCoeff();
  std::printf("joined: %d solves, |lambda - closed form| %.3e N of %.3e\n", solver.iterations(),
              error, la);
  EXPECT_LE(error, 40.0 * eps * la);
  expect_certificate(w, q, mu, lambda, solver.states());
}

// mu <= 0, NaN or infinite; W not square, not of size 3 nc; predicted of
// another size than W: std::invalid_argument (its message printed).
TEST(CoulombSlipSet, BadArgumentsRejected) {
  const auto rejected = [](auto call) {
    try {
      call();
      ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& e) {
      std::printf("rejected: %s\n", e.what());
    }
  };
  for (double mu : {0.0, -0.1, std::nan(""), HUGE_VAL})
    rejected([mu] { CoulombSlipSet{mu}; });
  CoulombSlipSet solver(0.3);
  Eigen::VectorXd lambda;
  for (const Eigen::Vector3i& size : {Eigen::Vector3i(6, 3, 6), {4, 4, 4}, {6, 6, 3}})
    rejected([&] {
      solver.solve(Eigen::MatrixXd::Identity(size(0), size(1)), Eigen::VectorXd::Zero(size(2)),
                   lambda);
    });
}

// Every g~ >= 0 (0.1 .. 1 um), slips as in the sliding cases: accepted with
// lambda = 0 exactly and every contact open, from no warm start and from
// the solution of the same W with closing gaps.
TEST(CoulombSlipSet, AllOpen) {
  const int nc = 16;
  std::mt19937 rng(77);
  const Eigen::MatrixXd w = random_w(100, 3 * nc, rng);
  Eigen::VectorXd q = sliding_prediction(nc, rng);
  CoulombSlipSet solver(0.15);
  Eigen::VectorXd closing;
  ASSERT_TRUE(solver.solve(w, q, closing));
  std::uniform_real_distribution<double> unit(0.1, 1.0);
  for (int c = 0; c < nc; ++c)
    q(3 * c) = 1e-6 * unit(rng);
  for (const Eigen::VectorXd& start : {Eigen::VectorXd(), closing}) {
    Eigen::VectorXd lambda = start;
    ASSERT_TRUE(solver.solve(w, q, lambda));
    std::printf("start of size %td: %d solves\n", start.size(), solver.iterations());
    ASSERT_EQ(lambda.size(), 3 * nc);
    EXPECT_EQ(lambda.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(solver.states(), std::vector<State>(nc, State::open));
  }
}

} // namespace
} // namespace rsi

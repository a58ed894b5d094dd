// The per-step frictional contact problem (SPEC §3, §8; issue 12 item 2):
// the reference solver (Alart-Curnier, semismooth Newton) against exact
// solutions derived by hand, against an independent frictionless active-set
// solve, and its certificate on random well-posed problems.
//
// Conventions: q = q~ + W lambda, per contact (g, s); eps = 2^-52; m =
// (1 + d) nc; eta = 4 (m + 1) eps, the solver's stopping level
// (frictional_contact_solver.hpp).

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gtest/gtest.h>

#include "frictional_contact_problem.hpp"
#include "frictional_contact_solver.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

double eta(int m) {
  return 4.0 * (m + 1) * eps;
}

FrictionalContactSolution solve_ok(const FrictionalContactProblem& p) {
  const FrictionalContactSolution s = FrictionalContactSolver().solve(p);
  EXPECT_TRUE(s.ok()) << s.message;
  return s;
}

/// The bounds of frictional_contact_solver.hpp that a converged solution
/// meets, by construction of its stopping test (same q and delta as the
/// certificate, bit for bit).
void expect_certified(const FrictionalContactProblem& p, const FrictionalContactCertificate& c) {
  const int m = p.n_unknowns();
  const double e = eta(m);
  const double mu = p.friction();
  const double root_d = std::sqrt(double(p.n_tangents()));
  std::printf("  certificate: %s\n", c.summary().c_str());
  // Solver stopping test, closed: |g| <= eta delta_n; open: g >= -eta delta_n.
  EXPECT_LE(c.penetration, e);
  // Stopping test: lambda_n >= -eta Lambda (closed), |lambda_n| <= eta Lambda (open).
  EXPECT_LE(c.negative_normal, e);
  // |g lambda_n| / (delta_n Lambda): closed |g| <= eta delta_n, lambda_n <= Lambda;
  // open |lambda_n| <= eta Lambda, |g| <= delta_n.
  EXPECT_LE(c.complementarity, e);
  // Stick/slip: |lambda_t| <= mu lambda_n + eta Lambda; open: |lambda_t| <= eta
  // Lambda with mu lambda_n >= -mu eta Lambda.
  EXPECT_LE(c.cone_violation, (1.0 + mu) * e);
  // Stick: each |s_k| <= eta delta_k, Euclidean over d components.
  EXPECT_LE(c.stick_residual, root_d * e);
  // Slip: eta for the solver's slip contacts, sqrt(d) (2 mu + eta) eta for its
  // stick contacts on the cone's edge, sqrt(d) eta at mu = 0.
  EXPECT_LE(c.slip_residual, root_d * std::max(1.0, 2.0 * mu + e) * e);
}

// ---------------------------------------------------------------------------
// Argument checks.

TEST(FrictionalContact, RejectsBadArguments) {
  const Eigen::MatrixXd w = Eigen::MatrixXd::Identity(2, 2);
  const Eigen::VectorXd g = Eigen::VectorXd::Constant(1, -1.0);
  const Eigen::VectorXd s = Eigen::VectorXd::Zero(1);
  EXPECT_THROW(FrictionalContactProblem(3, 0.1, w, g, s), std::invalid_argument);
  EXPECT_THROW(FrictionalContactProblem(1, -0.1, w, g, s), std::invalid_argument);
  EXPECT_THROW(FrictionalContactProblem(1, NAN, w, g, s), std::invalid_argument);
  EXPECT_THROW(FrictionalContactProblem(2, 0.1, w, g, s), std::invalid_argument); // sizes
  EXPECT_THROW(FrictionalContactProblem(1, 0.1, w, Eigen::VectorXd(0), Eigen::VectorXd(0)),
               std::invalid_argument);
  Eigen::MatrixXd bad = w;
  bad(0, 1) = 0.5; // not symmetric
  EXPECT_THROW(FrictionalContactProblem(1, 0.1, bad, g, s), std::invalid_argument);
  bad = w;
  bad(1, 1) = 0.0; // zero row of B
  EXPECT_THROW(FrictionalContactProblem(1, 0.1, bad, g, s), std::invalid_argument);
  bad = w;
  bad(0, 0) = INFINITY;
  EXPECT_THROW(FrictionalContactProblem(1, 0.1, bad, g, s), std::invalid_argument);
  try {
    FrictionalContactProblem(1, -2.0, w, g, s);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mu"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[0, inf)"), std::string::npos) << e.what();
  }
  const FrictionalContactProblem p(1, 0.1, w, g, s);
  EXPECT_THROW(certify(p, Eigen::VectorXd::Zero(3)), std::invalid_argument);
  EXPECT_THROW(certify(p, Eigen::VectorXd::Zero(2), 0.0), std::invalid_argument);
  EXPECT_THROW(certify(p, Eigen::VectorXd::Constant(2, NAN)), std::invalid_argument);
  EXPECT_THROW(FrictionalContactSolver({0}), std::invalid_argument);
  EXPECT_THROW(FrictionalContactSolver().solve(p, Eigen::VectorXd::Zero(1)), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// Frictionless: diagonal W has the exact solution lambda_n = max(0, -g~/w_n).

TEST(FrictionalContact, FrictionlessDiagonalExact) {
  for (int d = 1; d <= 2; ++d) {
    const int nc = 6;
    const int b = 1 + d;
    Eigen::VectorXd diag(b * nc), g(nc), s(d * nc);
    for (int i = 0; i < b * nc; ++i)
      diag(i) = 1e-9 * (1.0 + 0.37 * i);                             // [m/N]
    const double gaps[6] = {-1e-6, 2e-6, -3.3e-7, 0.0, -7e-6, 5e-8}; // [m]
    for (int c = 0; c < nc; ++c) {
      g(c) = gaps[c];
      for (int k = 0; k < d; ++k)
        s(d * c + k) = 1e-6 * (k + 1) * (c % 2 ? 1.0 : -1.0);
    }
    const Eigen::MatrixXd w = diag.asDiagonal();
    const FrictionalContactProblem p(d, 0.0, w, g, s);
    const FrictionalContactSolution sol = solve_ok(p);
    std::printf("d = %d: %d Newton steps\n", d, sol.iterations);
    for (int c = 0; c < nc; ++c) {
      const double exact = std::max(0.0, -g(c) / diag(b * c));
      // Exact: -g~/w, one rounding. The solver's one Newton step from 0 on a
      // closed contact (frictional_contact_solver.cpp): F = r g~ and J = r w
      // (r cancels), equilibrated S J S^-1 (s J, then times 1/s: 3 roundings
      // that do not cancel), right-hand side s F, the pivot division and
      // its product, step / s: 9 roundings; 9 + 1 = 10 eps relative.
      std::printf("  contact %d: lambda_n %.17g exact %.17g\n", c, sol.lambda(b * c), exact);
      EXPECT_LE(std::abs(sol.lambda(b * c) - exact), 10 * eps * exact);
      for (int k = 0; k < d; ++k) {
        // mu = 0: lambda_t = 0 exactly (identity rows of the Newton matrix), and
        // the slip is the predicted one (W diagonal): s = s~ exactly.
        EXPECT_EQ(sol.lambda(b * c + 1 + k), 0.0);
        EXPECT_EQ(sol.q(b * c + 1 + k), s(d * c + k));
      }
    }
    const FrictionalContactCertificate cert = certify(p, sol.lambda);
    expect_certified(p, cert);
    // Open: gaps 2e-6, 0, 5e-8 (lambda_n = 0); the others are closed and,
    // with mu = 0, on the (degenerate) cone's edge: slip.
    EXPECT_EQ(cert.n_open, 3);
    EXPECT_EQ(cert.n_slip, 3);
  }
}

// ---------------------------------------------------------------------------
// Frictionless, full W: against an independent solve of Signorini's
// problem by the active-set iteration of the reference integrator
// (central_difference.cpp: solve on {g~ < 0}, drop the most negative
// multiplier, add any constraint the correction closes), written here on
// the normal rows of W.

Eigen::VectorXd signorini_active_set(const Eigen::MatrixXd& wn, const Eigen::VectorXd& g) {
  const int nc = static_cast<int>(g.size());
  std::vector<char> active(nc);
  for (int k = 0; k < nc; ++k)
    active[k] = g(k) < 0.0;
  for (int iteration = 0; iteration <= 4 * nc + 4; ++iteration) {
    std::vector<int> idx;
    for (int k = 0; k < nc; ++k)
      if (active[k]) idx.push_back(k);
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(nc);
    if (!idx.empty()) {
      const int na = static_cast<int>(idx.size());
      Eigen::MatrixXd a(na, na);
      Eigen::VectorXd rhs(na);
      for (int i = 0; i < na; ++i) {
        rhs(i) = -g(idx[i]);
        for (int j = 0; j < na; ++j)
          a(i, j) = wn(idx[i], idx[j]);
      }
      const Eigen::VectorXd la = a.ldlt().solve(rhs);
      Eigen::Index most_negative = 0;
      if (la.minCoeff(&most_negative) < 0.0) {
        active[idx[most_negative]] = false;
        continue;
      }
      for (int i = 0; i < na; ++i)
        lambda(idx[i]) = la(i);
    }
    const Eigen::VectorXd gap = g + wn * lambda;
    bool added = false;
    for (int k = 0; k < nc; ++k)
      if (!active[k] && gap(k) < 0.0) active[k] = added = true;
    if (!added) return lambda;
  }
  ADD_FAILURE() << "the reference active set did not settle";
  return Eigen::VectorXd::Zero(nc);
}

/// W = dt^2 B M^-1 B^T from a random SPD M (n x n) and a random B (m x n).
Eigen::MatrixXd random_w(int m, int n, double dt, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd a(n, n), b(m, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      a(i, j) = u(rng);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j)
      b(i, j) = u(rng);
  const Eigen::MatrixXd mass = a * a.transpose() + n * Eigen::MatrixXd::Identity(n, n); // [kg]
  const Eigen::LLT<Eigen::MatrixXd> llt(mass);
  EXPECT_EQ(llt.info(), Eigen::Success);
  const Eigen::MatrixXd x = llt.matrixL().solve(b.transpose());
  Eigen::MatrixXd w = dt * dt * (x.transpose() * x);
  return 0.5 * (w + w.transpose());
}

TEST(FrictionalContact, FrictionlessAgainstActiveSet) {
  std::mt19937 rng(20070904);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int d = 1; d <= 2; ++d)
    for (int trial = 0; trial < 5; ++trial) {
      const int nc = d == 1 ? 22 : 16;
      const int b = 1 + d;
      const int m = b * nc;
      const Eigen::MatrixXd w = random_w(m, m + 10, 5e-7, rng);
      Eigen::VectorXd g(nc), s(d * nc);
      for (int c = 0; c < nc; ++c)
        g(c) = 1e-6 * u(rng);
      for (int i = 0; i < d * nc; ++i)
        s(i) = 1e-6 * u(rng);
      const FrictionalContactProblem p(d, 0.0, w, g, s);
      const FrictionalContactSolution sol = solve_ok(p);
      Eigen::MatrixXd wn(nc, nc);
      for (int i = 0; i < nc; ++i)
        for (int j = 0; j < nc; ++j)
          wn(i, j) = w(b * i, b * j);
      const Eigen::VectorXd expected = signorini_active_set(wn, g);
      Eigen::VectorXd normal(nc);
      for (int c = 0; c < nc; ++c)
        normal(c) = sol.lambda(b * c);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(wn);
      const double cond = spectrum.eigenvalues().maxCoeff() / spectrum.eigenvalues().minCoeff();
      const double error = (normal - expected).cwiseAbs().maxCoeff();
      const double scale = expected.cwiseAbs().maxCoeff();
      std::printf("d = %d trial %d: %d Newton steps, |lambda_n - active set| = %.3e of %.3e "
                  "(cond W_nn %.2e)\n",
                  d, trial, sol.iterations, error, scale, cond);
      // Both solve W_AA lambda_A = -g~_A on the same active set (Signorini's
      // solution is unique: W_nn is SPD), each with a backward error of about
      // eta relative (the solver's stopping level; LDL^T is backward stable):
      // forward error <= 2 cond(W_nn) eta |lambda|.
      EXPECT_LE(error, 2.0 * cond * eta(m) * scale);
      for (int c = 0; c < nc; ++c)
        for (int k = 0; k < d; ++k)
          EXPECT_EQ(sol.lambda(b * c + 1 + k), 0.0); // mu = 0: exact zero rows
      expect_certified(p, certify(p, sol.lambda));
    }
}

// ---------------------------------------------------------------------------
// One contact, W diagonal (w_n, w_t[, w_t]): closed form.
//   g~ >= 0: open, lambda = 0.
//   g~ < 0: lambda_n = -g~/w_n (the gap closes whatever lambda_t: W has no
//   coupling); stick trial lambda_t = -s~/w_t (s = 0); if |lambda_t| <=
//   mu lambda_n stick, else slip: lambda_t = -mu lambda_n s~/|s~| and
//   s = s~ (1 - w_t mu lambda_n / |s~|), same direction, shorter.

struct Single {
  double lambda_n;
  Eigen::VectorXd lambda_t;
  ContactClass cls;
};

Single single_diagonal(double wn, double wt, double mu, double g, const Eigen::VectorXd& s) {
  Single r{0.0, Eigen::VectorXd::Zero(s.size()), ContactClass::open};
  if (g >= 0.0) return r;
  r.lambda_n = -g / wn;
  const Eigen::VectorXd trial = -s / wt;
  if (trial.norm() <= mu * r.lambda_n) {
    r.lambda_t = trial;
    r.cls = ContactClass::stick;
  } else {
    r.lambda_t = -mu * r.lambda_n * s / s.norm();
    r.cls = ContactClass::slip;
  }
  return r;
}

void check_single(int d, double mu, double g, const Eigen::VectorXd& s, ContactClass expected) {
  const double wn = 2e-9, wt = 3e-9; // [m/N]
  Eigen::VectorXd diag(1 + d);
  diag(0) = wn;
  diag.tail(d).setConstant(wt);
  const FrictionalContactProblem p(d, mu, diag.asDiagonal().toDenseMatrix(),
                                   Eigen::VectorXd::Constant(1, g), s);
  const FrictionalContactSolution sol = solve_ok(p);
  const Single exact = single_diagonal(wn, wt, mu, g, s);
  ASSERT_EQ(exact.cls, expected) << "the case does not test what it says";
  const FrictionalContactCertificate cert = certify(p, sol.lambda);
  std::printf("d = %d mu = %.2f g~ = %.2e |s~| = %.2e: %s in %d steps; lambda_n %.17g (exact "
              "%.17g), |lambda_t - exact| = %.3e\n",
              d, mu, g, s.norm(), to_string(cert.classes[0]), sol.iterations, sol.lambda(0),
              exact.lambda_n, (sol.lambda.tail(d) - exact.lambda_t).norm());
  EXPECT_EQ(cert.classes[0], expected);
  // Exact lambda_n = -g~/w_n: 10 eps relative, as in FrictionlessDiagonalExact
  // (the rows do not couple).
  EXPECT_LE(std::abs(sol.lambda(0) - exact.lambda_n), 10 * eps * exact.lambda_n);
  // lambda_t: stick -s~/w_t by the same 10 roundings (per component, so
  // 10 eps |lambda_t| in norm); slip -mu lambda_n s~/|s~|: lambda_n to 10
  // eps, the product with mu and the normalisation (a norm of d <= 2
  // squares, a square root, a division: 4 more roundings) and, in 3D, the
  // semismooth Newton's last step, stopped at eta = 4 (m + 1) eps relative
  // to Lambda (m = 3: 16 eps): 10 + 4 + 16 = 30 eps relative to Lambda.
  const double lambda_scale = std::max(exact.lambda_n, exact.lambda_t.norm());
  EXPECT_LE((sol.lambda.tail(d) - exact.lambda_t).norm(), 30 * eps * lambda_scale);
  expect_certified(p, cert);
}

TEST(FrictionalContact, SingleContact2D) {
  // Stick: |s~|/w_t = 1e-7/3e-9 = 33.3 N <= mu g~/w_n = 0.3 * 1e-6/2e-9 = 150 N.
  check_single(1, 0.3, -1e-6, Eigen::VectorXd::Constant(1, 1e-7), ContactClass::stick);
  // Slip: |s~|/w_t = 2e-6/3e-9 = 667 N > 150 N, both signs.
  check_single(1, 0.3, -1e-6, Eigen::VectorXd::Constant(1, 2e-6), ContactClass::slip);
  check_single(1, 0.3, -1e-6, Eigen::VectorXd::Constant(1, -2e-6), ContactClass::slip);
  // Open.
  check_single(1, 0.3, 1e-6, Eigen::VectorXd::Constant(1, 2e-6), ContactClass::open);
}

TEST(FrictionalContact, SingleContact3DIsotropic) {
  Eigen::VectorXd s(2);
  s << 6e-8, -8e-8; // |s~| = 1e-7: stick (33.3 N <= 150 N)
  check_single(2, 0.3, -1e-6, s, ContactClass::stick);
  s << 1.2e-6, -1.6e-6; // |s~| = 2e-6: slip (667 N > 150 N), direction -s~/|s~|
  check_single(2, 0.3, -1e-6, s, ContactClass::slip);
  check_single(2, 0.3, 3e-7, s, ContactClass::open);
}

// Anisotropic tangential flexibility W = diag(w_n, c_1, c_2) in slip: the
// slip direction is not that of s~. With k = mu lambda_n and rho = |s|,
// s = s~ - k C s/rho gives s_i = s~_i rho/(rho + k c_i), and |s| = rho is
// f(rho) = sum_i s~_i^2/(rho + k c_i)^2 - 1 = 0, decreasing in rho > 0,
// with a root iff f(0+) = |C^-1 s~|^2/k^2 - 1 > 0 (the stick trial leaves
// the cone). Solved here by GSL's Brent root finder, independently.
TEST(FrictionalContact, SingleContact3DAnisotropicSlip) {
  const double wn = 2e-9, c1 = 1e-9, c2 = 5e-9, mu = 0.3, g = -1e-6;
  Eigen::VectorXd s(2);
  s << 1e-6, 1e-6;
  const double k = mu * (-g / wn); // 150 N; |C^-1 s~| = |(1000, 200)| N > 150 N: slip
  struct Data {
    double s1, s2, k, c1, c2;
  } data{s(0), s(1), k, c1, c2};
  gsl_function f;
  f.function = [](double rho, void* p) {
    const Data& q = *static_cast<Data*>(p);
    const double a = q.s1 / (rho + q.k * q.c1), b = q.s2 / (rho + q.k * q.c2);
    return a * a + b * b - 1.0;
  };
  f.params = &data;
  gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  double lo = 1e-30, hi = s.norm(); // f(hi) < 0: |s| < |s~|
  ASSERT_GT(f.function(lo, &data), 0.0);
  ASSERT_LT(f.function(hi, &data), 0.0);
  gsl_root_fsolver_set(solver, &f, lo, hi);
  int status = GSL_CONTINUE;
  for (int it = 0; it < 200 && status == GSL_CONTINUE; ++it) {
    gsl_root_fsolver_iterate(solver);
    lo = gsl_root_fsolver_x_lower(solver);
    hi = gsl_root_fsolver_x_upper(solver);
    status = gsl_root_test_interval(lo, hi, 0.0, 2 * eps);
  }
  const double rho = gsl_root_fsolver_root(solver);
  gsl_root_fsolver_free(solver);
  ASSERT_EQ(status, GSL_SUCCESS);
  Eigen::Vector2d slip(s(0) * rho / (rho + k * c1), s(1) * rho / (rho + k * c2));
  const Eigen::Vector2d lambda_t = -k * slip / rho;

  Eigen::Vector3d diag(wn, c1, c2);
  const FrictionalContactProblem p(2, mu, diag.asDiagonal().toDenseMatrix(),
                                   Eigen::VectorXd::Constant(1, g), s);
  const FrictionalContactSolution sol = solve_ok(p);
  const FrictionalContactCertificate cert = certify(p, sol.lambda);
  std::printf("anisotropic slip: %d Newton steps, lambda_t (%.17g, %.17g), exact (%.17g, "
              "%.17g); slip direction %.6f rad off s~\n",
              sol.iterations, sol.lambda(1), sol.lambda(2), lambda_t(0), lambda_t(1),
              std::acos(slip.normalized().dot(s.normalized())));
  EXPECT_EQ(cert.classes[0], ContactClass::slip);
  // GSL brackets rho to 2 eps relative; lambda_t = -k s/rho with s_i =
  // s~_i rho/(rho + k c_i): d(lambda_t)/d(rho) relative <= 1, so 2 eps, plus
  // about 8 roundings in the formulas; the solver stops at eta = 16 eps
  // relative to Lambda: 2 + 8 + 16 = 26 eps relative to Lambda.
  const double scale = std::max(-g / wn, lambda_t.norm());
  EXPECT_LE((sol.lambda.tail(2) - lambda_t).norm(), 26 * eps * scale);
  EXPECT_LE(std::abs(sol.lambda(0) + g / wn), 10 * eps * (-g / wn)); // as in check_single
  expect_certified(p, cert);
}

// ---------------------------------------------------------------------------
// One 2D contact with coupling W = [[a, b], [b, c]]: enumerate the four
// pieces exactly (open; stick: W lambda = -q~; slip sigma = +-1:
// lambda_t = -mu sigma lambda_n, lambda_n = -g~/(a - mu sigma b), valid if
// lambda_n > 0 and sigma s > 0, s = s~ + (b - mu sigma c) lambda_n). For
// mu |b| < a every (g~, s~) of a grid has exactly one valid piece, and the
// solver finds it.

TEST(FrictionalContact, SingleContact2DCoupledEnumeration) {
  const double a = 2e-9, b = 0.8e-9, c = 1.5e-9, mu = 0.5; // mu |b| = 0.4e-9 < a
  const Eigen::Matrix2d w = (Eigen::Matrix2d() << a, b, b, c).finished();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> spectrum(w);
  const double cond = spectrum.eigenvalues()(1) / spectrum.eigenvalues()(0);
  int cases = 0, n_stick = 0, n_slip = 0, n_open = 0;
  double worst = 0.0;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j) {
      const double g = 0.31e-6 * i + 0.013e-6, s = 0.27e-6 * j + 0.007e-6; // off the piece borders
      std::vector<Eigen::Vector2d> valid;
      std::vector<ContactClass> kinds;
      if (g >= 0.0) {
        valid.push_back(Eigen::Vector2d::Zero());
        kinds.push_back(ContactClass::open);
      }
      const Eigen::Vector2d stick = w.ldlt().solve(-Eigen::Vector2d(g, s));
      if (stick(0) > 0.0 && std::abs(stick(1)) <= mu * stick(0)) {
        valid.push_back(stick);
        kinds.push_back(ContactClass::stick);
      }
      for (double sigma : {-1.0, 1.0}) {
        const double ln = -g / (a - mu * sigma * b);
        const double slip = s + (b - mu * sigma * c) * ln;
        if (ln > 0.0 && sigma * slip > 0.0) {
          valid.push_back(Eigen::Vector2d(ln, -mu * sigma * ln));
          kinds.push_back(ContactClass::slip);
        }
      }
      ASSERT_EQ(valid.size(), 1u) << "g~ " << g << " s~ " << s;
      const FrictionalContactProblem p(1, mu, w, Eigen::VectorXd::Constant(1, g),
                                       Eigen::VectorXd::Constant(1, s));
      const FrictionalContactSolution sol = solve_ok(p);
      const FrictionalContactCertificate cert = certify(p, sol.lambda);
      EXPECT_EQ(cert.classes[0], kinds[0]) << "g~ " << g << " s~ " << s;
      const double error = (sol.lambda - valid[0]).norm();
      const double scale = valid[0].norm();
      worst = std::max(worst, scale > 0.0 ? error / scale : error);
      // Both solve the same 2 x 2 linear piece, backward stable to eta (m = 2:
      // 12 eps) and a few roundings: forward error <= 2 cond(W) eta |lambda|.
      EXPECT_LE(error, 2.0 * cond * eta(2) * scale) << "g~ " << g << " s~ " << s;
      n_open += kinds[0] == ContactClass::open;
      n_stick += kinds[0] == ContactClass::stick;
      n_slip += kinds[0] == ContactClass::slip;
      ++cases;
    }
  std::printf("%d cases (%d open, %d stick, %d slip), worst relative error %.3e "
              "(bound %.3e)\n",
              cases, n_open, n_stick, n_slip, worst, 2.0 * cond * eta(2));
  EXPECT_GT(n_stick, 0);
  EXPECT_GT(n_slip, 0);
  EXPECT_GT(n_open, 0);
}

// The uniqueness caveat (frictional_contact_solver.hpp): a = 1, b = 0.9,
// c = 1, mu = 2 (mu |b| = 1.8 > a), g~ = 0.1 > 0, s~ = 1 (scaled units).
// Open (lambda = 0) is a solution; so is slip in sigma = +1: lambda_n =
// -g~/(a - mu b) = 0.1/0.8 = 0.125, lambda_t = -0.25, s = 1 + (0.9 - 2)
// 0.125 = 0.8625 > 0. Both certify; the solver returns the one its Newton
// path reaches: open from 0, slip from a start next to the slip solution.
TEST(FrictionalContact, NonUniqueWithStrongCoupling) {
  const Eigen::Matrix2d w = (Eigen::Matrix2d() << 1.0, 0.9, 0.9, 1.0).finished();
  const FrictionalContactProblem p(1, 2.0, w, Eigen::VectorXd::Constant(1, 0.1),
                                   Eigen::VectorXd::Constant(1, 1.0));
  const Eigen::Vector2d slip(0.1 / 0.8, -2.0 * (0.1 / 0.8));
  const FrictionalContactCertificate open_cert = certify(p, Eigen::Vector2d::Zero());
  const FrictionalContactCertificate slip_cert = certify(p, slip);
  std::printf("open: %s\nslip: %s\n", open_cert.summary().c_str(), slip_cert.summary().c_str());
  EXPECT_EQ(open_cert.classes[0], ContactClass::open);
  EXPECT_EQ(slip_cert.classes[0], ContactClass::slip);
  // lambda = 0: q = q~ exactly, every residual is exactly zero.
  EXPECT_EQ(open_cert.worst(), 0.0);
  // The hand solution: lambda_n = fl(0.1)/0.8 and lambda_t = -2 lambda_n (1
  // rounding), g = 0.1 + lambda_n + 0.9 lambda_t and s likewise (3 more
  // roundings each): the scaled residuals are <= 4 eps + O(eps^2); 8 eps.
  EXPECT_LE(slip_cert.worst(), 8 * eps);

  const FrictionalContactSolution from_zero = solve_ok(p);
  EXPECT_EQ(certify(p, from_zero.lambda).classes[0], ContactClass::open);
  const FrictionalContactSolution from_slip =
      FrictionalContactSolver().solve(p, Eigen::Vector2d(0.12, -0.24));
  ASSERT_TRUE(from_slip.ok()) << from_slip.message;
  const FrictionalContactCertificate c = certify(p, from_slip.lambda);
  std::printf("from (0.12, -0.24): lambda (%.17g, %.17g), %s\n", from_slip.lambda(0),
              from_slip.lambda(1), to_string(c.classes[0]));
  EXPECT_EQ(c.classes[0], ContactClass::slip);
  // Same piece as the hand solution, 2 x 2, cond(W) = 1.9/0.1 = 19: forward
  // error <= 2 cond eta |lambda| (eta = 12 eps at m = 2).
  EXPECT_LE((from_slip.lambda - slip).norm(), 2.0 * 19.0 * eta(2) * slip.norm());
  expect_certified(p, c);
}

// ---------------------------------------------------------------------------
// Random well-posed problems: 22 contacts in 2D, 16 in 3D (the sizes of the
// project's cases), W = dt^2 B M^-1 B^T from a random SPD M and a random B
// (full row rank: W SPD), mu in {0, 0.15, 0.5, 1}; gaps of both signs and
// slips small enough for stick to occur. The certificate must hold to the
// bounds the solver's stopping test implies (expect_certified).

TEST(FrictionalContact, RandomProblemsCertified) {
  std::mt19937 rng(1991);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int total[3] = {0, 0, 0};
  int max_iterations = 0;
  for (int d = 1; d <= 2; ++d)
    for (double mu : {0.0, 0.15, 0.5, 1.0})
      for (int trial = 0; trial < 4; ++trial) {
        const int nc = d == 1 ? 22 : 16;
        const int m = (1 + d) * nc;
        const Eigen::MatrixXd w = random_w(m, m + 20, 5e-7, rng);
        Eigen::VectorXd g(nc), s(d * nc);
        for (int c = 0; c < nc; ++c)
          g(c) = 1e-6 * u(rng);
        const double slip_scale = trial % 2 ? 1e-7 : 1e-6;
        for (int i = 0; i < d * nc; ++i)
          s(i) = slip_scale * u(rng);
        const FrictionalContactProblem p(d, mu, w, g, s);
        const FrictionalContactSolution sol = solve_ok(p);
        const FrictionalContactCertificate cert = certify(p, sol.lambda);
        std::printf("d = %d mu = %.2f trial %d: %d Newton steps, %d attempt(s)\n", d, mu, trial,
                    sol.iterations, sol.attempts);
        expect_certified(p, cert);
        total[0] += cert.n_open;
        total[1] += cert.n_stick;
        total[2] += cert.n_slip;
        max_iterations = std::max(max_iterations, sol.iterations);
      }
  std::printf("over all: %d open, %d stick, %d slip; at most %d Newton steps\n", total[0], total[1],
              total[2], max_iterations);
  // The set must exercise every class, or it tests less than it says.
  EXPECT_GT(total[0], 0);
  EXPECT_GT(total[1], 0);
  EXPECT_GT(total[2], 0);
}

// Robustness: rows of B scaled over 6 decades (10^[-3, 3]: W's diagonal
// over 12), every contact coupled to every other, 1 to 22 contacts, slips
// from 1e-10 to 1e-6 m. The solver's assumption (frictional_contact_solver.hpp)
// is kappa = max_c mu |W_nt,c| / W_nn,c < 1: there every problem must be
// solved and certified. Outside it a failure is allowed but must be
// reported as one (status and message); the counts are printed.
TEST(FrictionalContact, ScaledCoupledProblems) {
  std::mt19937 rng(2007);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int in_regime = 0, outside = 0, outside_failed = 0, fallback = 0, max_iterations = 0;
  for (int d = 1; d <= 2; ++d)
    for (double mu : {0.0, 0.15, 0.5, 1.0})
      for (int trial = 0; trial < 100; ++trial) {
        const int nc = 1 + trial % 22;
        const int m = (1 + d) * nc, n = m + 5;
        Eigen::MatrixXd a(n, n), b(m, n);
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j)
            a(i, j) = u(rng);
        for (int i = 0; i < m; ++i) {
          const double row_scale = std::pow(10.0, 3.0 * u(rng));
          for (int j = 0; j < n; ++j)
            b(i, j) = row_scale * u(rng);
        }
        const Eigen::MatrixXd mass = a * a.transpose() + n * Eigen::MatrixXd::Identity(n, n);
        const Eigen::LLT<Eigen::MatrixXd> llt(mass);
        ASSERT_EQ(llt.info(), Eigen::Success);
        const Eigen::MatrixXd x = llt.matrixL().solve(b.transpose());
        Eigen::MatrixXd w = 1e-8 * (x.transpose() * x);
        w = 0.5 * (w + w.transpose()).eval();
        Eigen::VectorXd g(nc), s(d * nc);
        for (int c = 0; c < nc; ++c)
          g(c) = 1e-6 * u(rng);
        const double slip_scale = std::pow(10.0, -8.0 + 2.0 * u(rng));
        for (int i = 0; i < d * nc; ++i)
          s(i) = slip_scale * u(rng);
        double kappa = 0.0;
        for (int c = 0; c < nc; ++c) {
          const int k = (1 + d) * c;
          kappa = std::max(kappa, mu * w.block(k, k + 1, 1, d).norm() / w(k, k));
        }
        const FrictionalContactProblem p(d, mu, w, g, s);
        const FrictionalContactSolution sol = FrictionalContactSolver().solve(p);
        if (kappa < 1.0) {
          ++in_regime;
          ASSERT_TRUE(sol.ok()) << "kappa " << kappa << ": " << sol.message;
          const FrictionalContactCertificate cert = certify(p, sol.lambda);
          const double e = eta(m);
          // The bounds of expect_certified (printing each would flood the log).
          EXPECT_LE(cert.penetration, e);
          EXPECT_LE(cert.negative_normal, e);
          EXPECT_LE(cert.complementarity, e);
          EXPECT_LE(cert.cone_violation, (1.0 + mu) * e);
          EXPECT_LE(cert.stick_residual, std::sqrt(double(d)) * e);
          EXPECT_LE(cert.slip_residual, std::sqrt(double(d)) * std::max(1.0, 2.0 * mu + e) * e);
        } else {
          ++outside;
          if (!sol.ok()) {
            ++outside_failed;
            EXPECT_FALSE(sol.message.empty());
          } else {
            // A solution returned as converged is certified whatever kappa.
            EXPECT_LE(certify(p, sol.lambda).complementarity, eta(m));
          }
        }
        fallback += sol.sweeps > 0;
        max_iterations = std::max(max_iterations, sol.iterations);
      }
  std::printf("kappa < 1: %d problems, all solved and certified; kappa >= 1: %d problems, %d "
              "reported unsolved; Gauss-Seidel fallback used %d times; at most %d Newton steps\n",
              in_regime, outside, outside_failed, fallback, max_iterations);
  // The family must put enough problems in the regime it tests (251 of 800
  // with this seed: kappa grows with the row-scale spread).
  EXPECT_GE(in_regime, 200);
}

// ---------------------------------------------------------------------------
// Failures are reported, not carried on.

TEST(FrictionalContact, SingularWReported) {
  // Two identical 2D contacts (the same rows of B twice): W = [[V, V], [V, V]]
  // is singular; both closed, so the Newton matrix has two equal row pairs.
  const Eigen::Matrix2d v = (Eigen::Matrix2d() << 2e-9, 0.5e-9, 0.5e-9, 1e-9).finished();
  Eigen::Matrix4d w;
  w << v, v, v, v;
  const FrictionalContactProblem p(1, 0.3, w, Eigen::Vector2d(-1e-6, -1e-6),
                                   Eigen::Vector2d(1e-8, 1e-8));
  const FrictionalContactSolution sol = FrictionalContactSolver().solve(p);
  std::printf("%s\n", sol.message.c_str());
  EXPECT_FALSE(sol.ok());
  EXPECT_EQ(sol.status, FrictionalContactStatus::singular);
  EXPECT_NE(sol.message.find("singular"), std::string::npos);
}

TEST(FrictionalContact, IterationLimitReported) {
  // Anisotropic 3D slip (as above) needs more than one Newton step from 0
  // (the slip direction is not s~'s); with one step allowed per attempt the
  // solver must say so.
  const Eigen::Vector3d diag(2e-9, 1e-9, 5e-9);
  const FrictionalContactProblem p(2, 0.3, diag.asDiagonal().toDenseMatrix(),
                                   Eigen::VectorXd::Constant(1, -1e-6),
                                   Eigen::Vector2d(1e-6, 1e-6));
  const FrictionalContactSolution sol = FrictionalContactSolver({1}).solve(p);
  std::printf("%s\n", sol.message.c_str());
  EXPECT_FALSE(sol.ok());
  EXPECT_EQ(sol.status, FrictionalContactStatus::no_convergence);
  EXPECT_NE(sol.message.find("no convergence"), std::string::npos);
}

TEST(FrictionalContact, OpeningFromAWarmStartReachesZeroExactly) {
  // The step of the default case (Omega = 310, friction_law coulomb) where
  // blade 1 leaves the casing (step 2949): g~ > 0, the previous step's
  // multipliers as the warm start. Exact solution: open, lambda = 0 (for
  // one 2D contact with kappa = mu |W_nt| / W_nn = 0.047 < 1 the solution is
  // unique, frictional_contact_solver.hpp). The open rows of the Newton
  // matrix are rows of the identity, so the step sets lambda to 0 exactly;
  // before the solver set that step exactly, the equilibrated solve left
  // lambda shrinking by eps a step into the denormals and the stopping test
  // |lambda_n| <= eta max|lambda| never passed.
  Eigen::Matrix2d w;
  w << 8.4041009693343095e-11, -2.6295384009817661e-11, -2.6295384009817661e-11,
      3.1422294411725075e-10;
  const FrictionalContactProblem p(1, 0.15, w, Eigen::VectorXd::Constant(1, 2.1945046890792241e-09),
                                   Eigen::VectorXd::Constant(1, 7.6011619790008949e-05));
  const FrictionalContactSolution sol =
      FrictionalContactSolver().solve(p, Eigen::Vector2d(149.14303541230251, -22.37145531184537));
  std::printf("%s: lambda = (%.3e, %.3e), %d Newton steps\n", sol.ok() ? "converged" : "failed",
              sol.lambda(0), sol.lambda(1), sol.iterations);
  ASSERT_TRUE(sol.ok()) << sol.message;
  EXPECT_EQ(sol.lambda(0), 0.0); // open: exact zero (an identity row's step)
  EXPECT_EQ(sol.lambda(1), 0.0);
}

} // namespace
} // namespace rsi

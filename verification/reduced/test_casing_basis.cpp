// Issue 14, the reduced casing (reduced/casing_basis.hpp): its verification
// rows. (1) Phi^T M_c Phi = I and Phi^T K_c Phi = diag(omega^2); (2) the
// static correction puts the forcing's static response K_c^-1 F in the
// span; (3) with every mode kept the modal casing is the full casing: the
// reduced integrator's runs agree to round-off; (4) the casing's forced
// response (no contact) converges as N_c grows, and the static correction
// does not make it worse; (5) the run at its own step writes its rows at
// the reference's output times and receives the reference's impulse.

#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "casing_basis.hpp"
#include "casing_forcing.hpp"
#include "reduced_contact.hpp"
#include "reduced_integrator.hpp"
#include "reduced_run.hpp"
#include "reduction.hpp"
#include "run_step.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

Case default_case() {
  return load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
}

double norm_inf(const Eigen::SparseMatrix<double>& a) {
  return Eigen::MatrixXd(a).cwiseAbs().rowwise().sum().maxCoeff();
}

TEST(CasingBasis, ModesAndCorrectionAreMassAndStiffnessOrthogonal) {
  const Case c = default_case();
  const Casing casing = assemble_casing(c);
  const Eigen::VectorXd f = casing_forcing(casing, c.forcing);
  for (const int modes : {5, 20, 40}) {
    const CasingBasis b = reduce_casing(casing, modes, f);
    ASSERT_TRUE(b.static_correction) << "the ND-2 forcing's static response is not in "
                                     << modes << " clamped-ring modes";
    ASSERT_EQ(b.size(), modes + 1);
    const int n = casing.n_dofs();
    const Eigen::MatrixXd& phi = b.shapes;
    const double phi_norm2 = phi.colwise().squaredNorm().maxCoeff();
    const Eigen::MatrixXd mass_error =
        phi.transpose() * casing.mass * phi - Eigen::MatrixXd::Identity(b.size(), b.size());
    const Eigen::MatrixXd stiffness_error =
        phi.transpose() * casing.stiffness * phi - Eigen::MatrixXd(b.omega_squared.asDiagonal());
    // As test_orthogonality (dsygvd's backward stability plus the products,
    // n eps ||A|| max|phi|^2), once for the modes and once for the Ritz step
    // on [Phi x] whose (m+1) x (m+1) products carry the same bound: 2x.
    const double mass_bound = 2.0 * n * eps * norm_inf(casing.mass) * phi_norm2;
    const double stiffness_bound = 2.0 * n * eps * norm_inf(casing.stiffness) * phi_norm2;
    std::printf("N_c = %d (+1 static): max|Phi^T M Phi - I| = %.2e (bound %.2e), "
                "max|Phi^T K Phi - Omega^2| = %.2e (bound %.2e), f_max %.0f Hz\n",
                modes, mass_error.cwiseAbs().maxCoeff(), mass_bound,
                stiffness_error.cwiseAbs().maxCoeff(), stiffness_bound,
                std::sqrt(b.omega_squared.maxCoeff()) / (2.0 * M_PI));
    EXPECT_LE(mass_error.cwiseAbs().maxCoeff(), mass_bound);
    EXPECT_LE(stiffness_error.cwiseAbs().maxCoeff(), stiffness_bound);
    EXPECT_TRUE(std::is_sorted(b.omega_squared.data(), b.omega_squared.data() + b.size()));
  }
}

TEST(CasingBasis, StaticResponseToTheForcingLiesInTheSpan) {
  const Case c = default_case();
  const Casing casing = assemble_casing(c);
  const Eigen::VectorXd f = casing_forcing(casing, c.forcing);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> k(casing.stiffness);
  const Eigen::VectorXd x = k.solve(f);
  auto residual = [&](const CasingBasis& b) {
    const Eigen::VectorXd r = x - b.shapes * (b.shapes.transpose() * (casing.mass * x));
    return std::sqrt(r.dot(casing.mass * r) / x.dot(casing.mass * x));
  };
  for (const int modes : {1, 5, 20}) {
    const double with = residual(reduce_casing(casing, modes, f));
    const double without = residual(reduce_casing(casing, modes, Eigen::VectorXd::Zero(f.size())));
    std::printf("N_c = %d: |x - P x|_M / |x|_M = %.2e with the correction, %.2e without\n", modes,
                with, without);
    // reduce_casing keeps the correction only when its M-orthogonal part
    // exceeds sqrt(eps) |x|_M (casing_basis.hpp); kept, x is in the span up
    // to the rounding of the two Gram-Schmidt passes and the Ritz rotation,
    // far below that threshold.
    EXPECT_LE(with, std::sqrt(eps));
    EXPECT_GT(without, std::sqrt(eps)); // the test would see a dropped correction
  }
}

/// Gaps of every tip at every output row of a reduced run.
std::vector<Eigen::VectorXd> gap_rows(const Case& c, const std::string& method, int modes,
                                      const ReducedRunOptions& base) {
  std::vector<Eigen::VectorXd> rows;
  ReducedRunOptions options = base;
  options.run.history_sink = [&](const HistoryRow& h) { rows.push_back(h.gap); };
  const ReducedRunResult r = run_reduced(c, method, modes, options);
  EXPECT_TRUE(r.run.summary.completed) << r.run.summary.status;
  return rows;
}

TEST(CasingBasis, EveryModeKeptIsTheFullCasing) {
  Case c = default_case();
  const int n_c = assemble_casing(c).n_dofs();
  ReducedRunOptions full;
  ReducedRunOptions modal;
  modal.casing_modes = n_c;
  const std::vector<Eigen::VectorXd> a = gap_rows(c, "cb", 44, full);
  const std::vector<Eigen::VectorXd> b = gap_rows(c, "cb", 44, modal);
  ASSERT_EQ(a.size(), b.size());
  double largest = 0.0, difference = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, (a[i] - a[0]).cwiseAbs().maxCoeff());
    difference = std::max(difference, (a[i] - b[i]).cwiseAbs().maxCoeff());
  }
  std::printf("CB-44, full casing vs all %d casing modes: max |gap difference| %.2e m over a "
              "gap variation of %.2e m, %zu rows\n",
              n_c, difference, largest, a.size());
  // The two casings differ by rounding only (the sparse LDL^T of M_c against
  // Phi diag(1/a) Phi^T). Each step forms the gaps R_c + N.u - R_t - u_k
  // from numbers of the size of the radius, so its rounding is eps R_c in
  // absolute terms (not relative to the gap's variation), and a stable
  // explicit scheme (below its critical step) accumulates at most linearly:
  // steps * eps * R_c = 40000 * 2.2e-16 * 0.501 m = 4.4e-12 m. A modal
  // casing that were not the casing would differ by the response itself.
  const double bound = static_cast<double>(a.size() - 1) * c.time.output_every * eps * c.casing.radius;
  std::printf("bound steps * eps * R_c = %.2e m\n", bound);
  EXPECT_LE(difference, bound);
}


TEST(CasingBasis, ForcedResponseConvergesWithTheModeCount) {
  // A clearance of 0.1 m: no tip reaches the casing, the bladed disk stays
  // at rest, and gap_k - gap_k(0) is the casing's radial displacement
  // under the forcing at the tips' angles: the casing's forced response.
  Case c = default_case();
  c.casing.radius = 0.6;
  const std::vector<Eigen::VectorXd> reference = gap_rows(c, "guyan", 0, ReducedRunOptions{});
  double norm = 0.0;
  for (const Eigen::VectorXd& g : reference)
    norm += (g - reference[0]).squaredNorm();
  double previous = std::numeric_limits<double>::infinity();
  for (const int modes : {5, 10, 20, 40, 80}) {
    ReducedRunOptions options;
    options.casing_modes = modes;
    const std::vector<Eigen::VectorXd> rows = gap_rows(c, "guyan", 0, options);
    ASSERT_EQ(rows.size(), reference.size());
    double error = 0.0;
    for (size_t i = 0; i < rows.size(); ++i)
      error += ((rows[i] - rows[0]) - (reference[i] - reference[0])).squaredNorm();
    const double e2 = std::sqrt(error / norm);
    std::printf("casing forced response, N_c = %d (+1 static): e2 = %.3e\n", modes, e2);
    // Galerkin truncation of a linear response: each added mode removes its
    // own share of the response; the norm over the tips' rows need not fall
    // at every count, so the test asks for convergence overall: a steady
    // fall by counts doubling, with at most 10 % back at one of them.
    EXPECT_LT(e2, 1.1 * previous) << "N_c = " << modes;
    previous = std::min(previous, e2);
  }
  EXPECT_LT(previous, 1e-2) << "80 casing modes of 156 leave more than 1 % of the response";
}

TEST(CasingBasis, ForcingScheduleKeepsTheReferenceImpulse) {
  const Case c = default_case();
  // The reference: force on steps 0..N with t_N <= duration, impulse
  // (N + 1/2) time.step (step 0 from rest counts half a step).
  long last = 0;
  while (forcing_active(c.forcing, (last + 1) * c.time.step, c.time.step))
    ++last;
  const double reference = (static_cast<double>(last) + 0.5) * c.time.step;
  for (const long k : {1L, 2L, 3L, 7L, 49L, 50L, 51L, 100L}) {
    const ForcingSchedule schedule(c.forcing, c.time, k);
    const double dt = c.time.step * c.time.output_every / static_cast<double>(k);
    double impulse = 0.5 * dt * schedule.share(0);
    for (long n = 1; n < 100000 && (n == 1 || schedule.share(n - 1) > 0.0); ++n)
      impulse += dt * schedule.share(n);
    // Shares are exact ratios of integers; the sum rounds once a term.
    EXPECT_NEAR(impulse, reference, 1e3 * eps * reference) << "k = " << k;
    if (k == c.time.output_every) {
      for (long n = 0; n <= last + 2; ++n) {
        EXPECT_EQ(schedule.share(n), n <= last ? 1.0 : 0.0) << "n = " << n;
      }
    }
  }
}

TEST(CasingBasis, RunStepRules) {
  const Case c = default_case(); // time.step 5e-7 s, output_every 50: interval 2.5e-5 s
  StepRule own;
  own.kind = StepRule::Kind::own;
  own.safety = 0.9;
  // 0.9 * 2 / omega = 1e-5 s: k = ceil(2.5e-5 / 1e-5) = 3.
  const RunStep a = run_step(own, c.time, 0.9 * 2.0 / 1e-5, "key");
  EXPECT_EQ(a.k, 3);
  EXPECT_DOUBLE_EQ(a.dt, 2.5e-5 / 3.0);
  // A limit above the interval: one step per row.
  EXPECT_EQ(run_step(own, c.time, 100.0, "key").k, 1);
  // The case's step itself whenever k == output_every.
  StepRule given;
  given.kind = StepRule::Kind::given;
  given.step = 5e-7;
  EXPECT_EQ(run_step(given, c.time, 1.0, "key").dt, c.time.step);
  given.step = 4.1666666666666666e-6;
  EXPECT_EQ(run_step(given, c.time, 1.0, "key").k, 6);
  given.step = 4e-6; // 6.25 steps a row
  EXPECT_THROW(run_step(given, c.time, 1.0, "key"), CaseError);
}

TEST(CasingBasis, OwnStepRowsFallOnTheReferenceTimes) {
  const Case c = default_case();
  std::vector<double> reference_times, own_times;
  ReducedRunOptions options;
  options.run.history_sink = [&](const HistoryRow& h) { reference_times.push_back(h.time); };
  run_reduced(c, "cb", 10, options);
  options.run.history_sink = [&](const HistoryRow& h) { own_times.push_back(h.time); };
  options.casing_modes = 20;
  options.step.kind = StepRule::Kind::own;
  const ReducedRunResult r = run_reduced(c, "cb", 10, options);
  EXPECT_GT(r.run.summary.dt, 10.0 * c.time.step);
  ASSERT_EQ(own_times.size(), reference_times.size());
  for (size_t i = 0; i < own_times.size(); ++i)
    // t = n dt against t = m output_every time.step: a few roundings of t.
    EXPECT_NEAR(own_times[i], reference_times[i], 8.0 * eps * c.time.duration) << "row " << i;
}

} // namespace
} // namespace rsi

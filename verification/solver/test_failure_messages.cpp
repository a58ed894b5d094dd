// Numerical failures that no valid case reaches through the CLI, tested on
// the function that reports them (issue 13, class 8: every exit 3 prints one
// `rsi: error:` line saying what failed and what to change). The exit-3
// paths a case does reach are tested end to end by
// verification/cli/numerical_failures.sh; each test below says why its path is
// out of the CLI's reach, and checks that the message names the step (for a
// failure during a run) and what to change.
// Release time: 0.2 s for the whole executable (AddressSanitizer: 0.8 s).

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/SparseCore>
#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "case_file.hpp"
#include "casing.hpp"
#include "central_difference.hpp"
#include "critical_step.hpp"
#include "mass_factor.hpp"
#include "reduced_contact.hpp"
#include "reduced_integrator.hpp"
#include "reduction.hpp"

namespace rsi {
namespace {

Case default_case() {
  return load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The command line option or case key `text` names ("" if none): a
/// kernel's text speaks of its own inputs, and the CLI words which option or
/// key they came from (cli/support/failure_advice.hpp).
std::string option_or_key_in(const std::string& text) {
  for (size_t at = text.find("--"); at != std::string::npos; at = text.find("--", at + 1))
    if (at + 2 < text.size() && text[at + 2] >= 'a' && text[at + 2] <= 'z')
      return text.substr(at, 12);
  for (const char* key : {"time.step", "time.duration", "component.mass", "component.source",
                          "rubbing.", "operating_point.", "casing_modes"})
    if (contains(text, key)) return key;
  return "";
}

/// The message of the exception `run` throws, printed first ("" if none);
/// its advice in `advice` when given. The message must name no option or key.
template <class Error, class Run>
std::string message_of(const Run& run, FailureAdvice* advice = nullptr) {
  try {
    run();
  } catch (const Error& e) {
    std::printf("  reported: %s\n", e.what());
    if (advice != nullptr) *advice = advice_of(e);
    EXPECT_EQ(option_or_key_in(e.what()), "") << e.what();
    return e.what();
  }
  std::printf("  nothing thrown\n");
  return "";
}

/// The remedies the exception `run` throws carries (the CLI words them:
/// cli/support/failure_advice.hpp), empty if none is thrown.
template <class Error, class Run> std::vector<Remedy> remedies_of(const Run& run) {
  try {
    run();
  } catch (const Error& e) {
    return advice_of(e).remedies;
  }
  return {};
}

bool has(const std::vector<Remedy>& remedies, Remedy r) {
  return std::find(remedies.begin(), remedies.end(), r) != remedies.end();
}

// ---- the reduced integrator (simulate --method cb|ccm|guyan, campaign) ----

TEST(ReducedIntegratorFailure, ReducedMassNotPositiveDefiniteSaysWhatToChange) {
  // Out of the CLI's reach: the case's M is positive definite to working
  // precision when it loads (part_definiteness.hpp, exit 2 naming the keys)
  // and the bases have full column rank (CB: [I 0; Psi Phi] with Phi
  // M-orthonormal; ReductionError otherwise), so M^ = T^T M T is positive
  // definite, and A = M^ + dt/2 C^ with C^ >= 0 too. Here M^ is made
  // indefinite by hand.
  const Case c = default_case();
  const Casing casing = assemble_casing(c);
  ReducedBasis basis = reduce_bladed_disk(assemble_bladed_disk(c), "cb", 10);
  basis.mass(0, 0) = -basis.mass(0, 0);
  const ReducedTipContact contact(basis, casing, c);
  const auto build = [&] { ReducedIntegrator integrator(basis, casing, c.time.step, contact); };
  const std::string what = message_of<ReducedIntegrationError>(build);
  EXPECT_TRUE(contains(what, "the reduced mass matrix is not positive definite")) << what;
  EXPECT_TRUE(has(remedies_of<ReducedIntegrationError>(build),
                  Remedy::fewer_modes_campaign_or_another_method));
}

/// The default case's CB-10 integrator at step `dt`, started with tip 1
/// pushed 2 mm outward through the 1 mm clearance: in contact at step 1.
/// Returns the message of the first step's failure, its advice in `advice`.
std::string first_step_failure(Case c, double dt, FailureAdvice& advice) {
  const Casing casing = assemble_casing(c);
  const ReducedBasis basis = reduce_bladed_disk(assemble_bladed_disk(c), "cb", 10);
  const ReducedTipContact contact(basis, casing, c);
  ReducedIntegrator integrator(basis, casing, dt, contact);
  Eigen::VectorXd q0 = Eigen::VectorXd::Zero(basis.n_reduced());
  const double clearance = c.casing.radius - c.bladed_disk.tip_radius;
  for (const double sign : {1.0, -1.0}) { // whichever way u closes the gap
    q0(basis.boundary_position[0]) = sign * 2.0 * clearance;
    integrator.start(Eigen::VectorXd::Zero(casing.n_dofs()), q0);
    if (integrator.gap()(0) < 0.0) break;
  }
  std::printf("tip 1 gap at the start %.3e m (clearance %.3e m)\n", integrator.gap()(0), clearance);
  EXPECT_LT(integrator.gap()(0), 0.0);
  return message_of<ReducedIntegrationError>([&] { integrator.step(); }, &advice);
}

TEST(ReducedIntegratorFailure, SingularContactMatrixNamesTheStepAndWhatToChange) {
  // W_ij = dt^2 (G_i M^-1 D_j^T + the casing's share). Out of the CLI's
  // reach: each tip's normal row reads its own boundary coordinate of q
  // (the reductions keep the tips' u), M^ and M_c are positive definite, so
  // without friction W = dt^2 G M^-1 G^T is positive definite; with the
  // sliding-sign friction W is singular only at isolated values of mu (an
  // eigenvalue crossing 0: the sprag limit), which a case would have to hit
  // to the last digits, since W is refused only when the LU solution
  // misses W lambda = -g by 1e-8 |g| (partial pivoting is backward stable:
  // that needs cond(W) near 1e8 or an exact zero pivot). Here W is made
  // zero by a step whose square underflows: dt = 1e-170, dt^2 = 0 in double
  // (below 4.9e-324); a case with that step could not reach a contact, the
  // 2^31 - 1 steps a run counts covering 2e-161 s.
  Case c = default_case();
  c.operating_point.friction_law = FrictionLaw::sliding_sign; // the path of this message
  FailureAdvice advice;
  const std::string what = first_step_failure(c, 1e-170, advice);
  EXPECT_TRUE(contains(what, "singular contact matrix W at step 1 (1 active tips)")) << what;
  EXPECT_TRUE(has(advice.remedies, Remedy::reduced_friction_or_smaller_step));
}

TEST(ReducedIntegratorFailure, CoulombProblemWithoutFlexibilityNamesTheStep) {
  // The same W = 0 on the Coulomb law's path: the stick/slip solver cannot
  // meet g = g~ + W lambda >= 0 with g~ < 0 (reduced/coulomb_gauss_seidel).
  Case c = default_case();
  c.operating_point.friction_law = FrictionLaw::coulomb;
  FailureAdvice advice;
  const std::string what = first_step_failure(c, 1e-170, advice);
  EXPECT_TRUE(contains(what, "Coulomb contact problem at step 1")) << what;
  EXPECT_TRUE(has(advice.remedies, Remedy::reduced_friction_or_smaller_step));
}

TEST(ReducedIntegratorFailure, FailedReducedEigenproblemSaysWhatToChange) {
  // (K^, M^) has eigenpairs for any basis a case builds (M^ positive
  // definite, above). A NaN in M^ stands in for a basis that lost them.
  const Case c = default_case();
  ReducedBasis basis = reduce_bladed_disk(assemble_bladed_disk(c), "cb", 10);
  basis.mass(0, 0) = std::numeric_limits<double>::quiet_NaN();
  const auto omega_max = [&] { reduced_omega_max(basis); };
  const std::string what = message_of<ReducedIntegrationError>(omega_max);
  EXPECT_TRUE(contains(what, "the generalized eigenproblem (K^, M^) failed")) << what;
  EXPECT_TRUE(
      has(remedies_of<ReducedIntegrationError>(omega_max), Remedy::fewer_modes_or_another_method));
}

// ---- the reference integrator (simulate --method full, campaign, sweep) ----

/// One constraint a row: g = gap + x(0), G = D = e_0 (n_rows rows).
class PushedWall : public ContactLaw {
public:
  PushedWall(int n_rows, double gap)
      : m_rows(n_rows)
      , m_gap(gap) {}
  int n_constraints() const override { return m_rows; }
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& x,
                const Eigen::Ref<const Eigen::VectorXd>&, double,
                ContactState& state) const override {
    state.gap = Eigen::VectorXd::Constant(m_rows, m_gap + x(0));
    state.gradient.assign(m_rows, SparseRow{{0, 1.0}});
    state.direction = state.gradient;
    state.sliding_velocity = Eigen::VectorXd::Zero(m_rows);
    state.friction_sign = Eigen::VectorXd::Zero(m_rows);
  }
  double friction_coefficient() const override { return 0.0; }

private:
  int m_rows;
  double m_gap;
};

Eigen::SparseMatrix<double> diagonal(double a, double b) {
  Eigen::SparseMatrix<double> m(2, 2);
  m.insert(0, 0) = a;
  m.insert(1, 1) = b;
  return m;
}

TEST(CentralDifferenceFailure, TwoContactsOnOneMotionNameTheStepAndWhatToChange) {
  // W = dt^2 G M^-1 D^T is singular when two active constraints read the
  // same motion. Out of the CLI's reach: the paper's contacts are the 22
  // tips, each reading its own dofs (and the casing's under it); with M
  // positive definite W is then singular only at isolated friction
  // coefficients (as in the reduced integrator above). Here two rows of one
  // wall push the same dof, 1 mm into it at the start: W = dt^2 / m [1 1; 1 1].
  const PushedWall wall(2, -1e-3);
  CentralDifference cd(diagonal(100.0, 100.0), diagonal(1.0, 1.0), 1e-3, wall);
  cd.start(Eigen::VectorXd::Zero(2));
  FailureAdvice advice;
  const std::string what = message_of<IntegrationError>([&] { cd.step(); }, &advice);
  EXPECT_TRUE(contains(what, "singular contact matrix W (2 active constraints) at step 1")) << what;
  EXPECT_TRUE(has(advice.remedies, Remedy::friction_or_smaller_step));
}

TEST(CentralDifferenceFailure, IndefiniteMassSaysWhatToChange) {
  // Out of the CLI's reach for the paper's case (its parts' M is checked
  // when it loads) and for a component (simulate --method full computes
  // omega_max first, whose factorization of M refuses it: exit 3 through
  // rsi modes in numerical_failures.sh). The integrator's own factor of M.
  const PushedWall wall(1, 1.0);
  FailureAdvice advice;
  const std::string what = message_of<std::runtime_error>( // MassFactorError or IntegrationError
      [&] { CentralDifference cd(diagonal(100.0, 100.0), diagonal(1.0, -1.0), 1e-3, wall); },
      &advice);
  EXPECT_TRUE(contains(what, "the mass matrix is not positive definite")) << what;
  EXPECT_TRUE(has(advice.remedies, Remedy::component_lumped_mass_or_reduced_method) ||
              has(advice.remedies, Remedy::lumped_mass_or_reduced_method));
}

} // namespace
} // namespace rsi

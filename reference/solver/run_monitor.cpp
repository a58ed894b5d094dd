#include "run_monitor.hpp"

#include "largest_eigenvalue_bound.hpp"
#include "paper_monitor.hpp"

#include <chrono>
#include <cmath>
#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rsi {
namespace {

/// A step at or above the limit: the case's step, unless forced.
FailureAdvice step_advice() {
  FailureAdvice advice = failed_input(FailedInput::time_step_value);
  advice.remedies.push_back(Remedy::smaller_step_or_force);
  return advice;
}
const FailureAdvice kStepAdvice = step_advice();

} // namespace

void check_time_step(double dt, double omega_max, bool force, RunSummary& s) {
  s.dt = dt;
  s.omega_max = omega_max;
  s.critical_dt = 2.0 / omega_max;
  if (dt >= s.critical_dt && !force) {
    std::ostringstream message;
    message.precision(6);
    message << dt << " s is not below the central-difference stability limit 2/omega_max = "
            << s.critical_dt << " s (omega_max = " << omega_max << " rad/s)";
    throw StabilityError(message.str(), kStepAdvice);
  }
}

void check_time_step_bound(double dt, const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, bool force,
                           const std::string& part) {
  if (force) return;
  const LargestEigenvalueBound largest = largest_eigenvalue_lower_bound(stiffness, mass);
  const double bound = 2.0 / std::sqrt(largest.value);
  if (!(dt >= bound)) return;
  std::ostringstream message;
  message.precision(6);
  message << dt << " s is not below the central-difference stability limit of the " << part
          << ": 2/omega_max <= " << bound
          << " s (a Rayleigh quotient x^T K x / x^T M x bounds omega_max^2 from below: "
          << largest.iterations << " power steps, found before the eigensolver)";
  throw StabilityError(message.str(), kStepAdvice);
}

RunMonitor::RunMonitor(const Case& c, const Casing& casing, const RunOptions& options,
                       RunResult& result)
    : RunMonitor(
          MonitorRules{static_cast<int>(std::llround(c.time.duration / c.time.step)),
                       c.time.output_every, c.time.output_every, true, 0.0},
          std::make_unique<PaperMonitor>(c, casing), options, result) {}

RunMonitor::RunMonitor(const MonitorRules& rules, std::unique_ptr<KindMonitor> kind,
                       const RunOptions& options, RunResult& result)
    : m_rules(rules), m_kind(std::move(kind)), m_options(options), m_result(result) {
  if (m_rules.output_every < 1 || m_rules.energy_every < 1)
    throw std::invalid_argument("RunMonitor: output_every and energy_every must be >= 1");
  RunSummary& s = m_result.summary;
  s.steps_requested = m_rules.steps_requested;
  s.completed = true;
  s.status = "completed";
}

void RunMonitor::add_row(const StepState& state, double energy) {
  const bool tips = m_options.tip_displacement && state.tips != nullptr;
  if (tips) (*state.tips)(m_tips);
  const HistoryRow row{state.time,          state.gap,          state.lambda,
                       energy,              state.external_work, state.contact_work,
                       state.damping_work,  state.lambda_tangential,
                       tips ? &m_tips : nullptr, state.liner ? &state.plastic_work : nullptr};
  if (m_options.history_sink) {
    const auto start = std::chrono::steady_clock::now();
    m_options.history_sink(row);
    m_output_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } else
    m_result.history.append(row);
  ++m_n_rows;
  m_last_external_work = state.external_work;
  m_last_contact_work = state.contact_work;
  m_last_damping_work = state.damping_work;
}

bool RunMonitor::stop(const std::string& status) {
  m_result.summary.completed = false;
  m_result.summary.status = status;
  return false;
}

void RunMonitor::start(const StepState& state, double initial_energy) {
  m_result.summary.initial_energy = initial_energy;
  m_result.summary.max_energy = initial_energy;
  add_row(state, initial_energy);
}

bool RunMonitor::after_step(const StepReport& r, const StepState& state,
                            const std::function<double()>& energy) {
  RunSummary& s = m_result.summary;
  s.steps = state.step;
  const KindMonitor::Runaway runaway = m_kind->runaway(state);
  if (!runaway.status.empty() && !runaway.counted) return stop(runaway.status);
  s.max_penetration = std::max(s.max_penetration, r.max_penetration);
  s.min_lambda = std::min(s.min_lambda, r.min_lambda);
  s.max_lambda = std::max(s.max_lambda, state.lambda.maxCoeff());
  s.max_complementarity = std::max(s.max_complementarity, r.max_complementarity);
  s.max_friction_residual = std::max(s.max_friction_residual, r.max_friction_residual);
  s.sliding_reversals += r.sliding_reversals;
  s.max_cone_violation = std::max(s.max_cone_violation, r.max_cone_violation);
  s.max_stick_slip_residual = std::max(s.max_stick_slip_residual, r.max_stick_slip_residual);
  s.stick_slip_transitions += r.stick_slip_transitions;
  s.stick_contact_steps += r.n_stick;
  s.slip_contact_steps += r.n_slip;
  s.max_active = std::max(s.max_active, r.n_active);
  const bool first_contact = s.first_contact_step < 0 && r.n_active > 0;
  m_kind->after_step(r, state, first_contact, m_result);
  if (first_contact) s.first_contact_step = state.step;
  m_largest_external_work = std::max(m_largest_external_work, std::abs(state.external_work));

  if (!runaway.status.empty()) {
    add_row(state, energy());
    return stop(runaway.status);
  }
  if (state.step % 1000 == 0) {
    if (m_options.progress) m_options.progress(double(state.step) / s.steps_requested);
    if (m_options.checkpoint) m_options.checkpoint();
  }
  const bool last = state.step == s.steps_requested;
  const bool row = state.step % m_rules.output_every == 0 || (m_rules.row_at_last_step && last);
  const bool check = state.step % m_rules.energy_every == 0 || last;
  if (!row && !check) return true;

  const double e = check ? energy() : std::numeric_limits<double>::quiet_NaN();
  if (row) add_row(state, e);
  if (!check) return true;
  s.max_energy = std::max(s.max_energy, e);
  s.energy_scale = std::max({s.energy_scale, std::abs(e), std::abs(state.external_work),
                             std::abs(state.contact_work), std::abs(state.damping_work),
                             std::abs(state.plastic_work)});
  // W_plastic is 0 without a liner (x + 0.0 is x).
  const double balance = std::abs(e - s.initial_energy - state.external_work -
                                  state.contact_work + state.damping_work + state.plastic_work);
  s.energy_balance_error = std::max(s.energy_balance_error, balance);
  if (m_rules.balance_tolerance > 0.0 && !(balance <= m_rules.balance_tolerance * s.energy_scale)) {
    std::ostringstream message;
    message.precision(6);
    message << "energy balance broken at step " << state.step << " (t = " << state.time
            << " s): |E - E0 - W_ext - W_contact + W_damp"
            << (state.liner ? " + W_plastic" : "") << "| = " << balance << " > "
            << m_rules.balance_tolerance << " x scale " << s.energy_scale
            << " (instability or solver trouble)";
    return stop(message.str());
  }
  if (!std::isfinite(e))
    return stop("blow-up: non-finite energy at step " + std::to_string(state.step) +
                " (t = " + std::to_string(state.time) + " s)");
  // The energy a run may hold comes from E_0 and the external work (contact
  // can feed some in, SPEC §3). At step 1 the external work is round-off
  // (u_1 = u_-1 exactly from rest: W_ext = F^T (u_1 - u_-1) / 2 = 0), while
  // E_0 = dt^2/8 F^T M^-1 F is not: leaving E_0 out called every run
  // sampled at step 1 a blow-up. Without forcing (E_0 = W_ext = 0) there
  // is no supply to measure against, and no test.
  const double supplied = s.initial_energy + m_largest_external_work;
  if (supplied > 0.0 && e > m_options.blowup_factor * supplied) {
    std::ostringstream message;
    message << "blow-up: energy " << e << " J exceeds " << m_options.blowup_factor
            << " times E_0 + the largest external work " << supplied << " J at step "
            << state.step << " (t = " << state.time << " s); contact work " << state.contact_work
            << " J";
    return stop(message.str());
  }
  return true;
}

void RunMonitor::finish(double integration_seconds, double wall_seconds) {
  RunSummary& s = m_result.summary;
  s.output_seconds = m_output_seconds;
  s.integration_seconds = integration_seconds - m_output_seconds;
  s.wall_seconds = wall_seconds - m_output_seconds;
  if (m_n_rows > 0) {
    s.final_external_work = m_last_external_work;
    s.final_contact_work = m_last_contact_work;
    s.final_damping_work = m_last_damping_work;
  }
}

} // namespace rsi

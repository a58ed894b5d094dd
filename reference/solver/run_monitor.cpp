#include "run_monitor.hpp"

#include "largest_eigenvalue_bound.hpp"

#include <chrono>
#include <cmath>
#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace rsi {

void check_time_step(double dt, double omega_max, bool force, RunSummary& s) {
  s.dt = dt;
  s.omega_max = omega_max;
  s.critical_dt = 2.0 / omega_max;
  if (dt >= s.critical_dt && !force) {
    std::ostringstream message;
    message.precision(6);
    message << "time.step = " << dt
            << " s is not below the central-difference stability limit 2/omega_max = "
            << s.critical_dt << " s (omega_max = " << omega_max
            << " rad/s); use a smaller step or --force";
    throw StabilityError(message.str());
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
  message << "time.step = " << dt
          << " s is not below the central-difference stability limit of the " << part
          << ": 2/omega_max <= " << bound
          << " s (a Rayleigh quotient x^T K x / x^T M x bounds omega_max^2 from below: "
          << largest.iterations
          << " power steps, found before the eigensolver); use a smaller step or --force";
  throw StabilityError(message.str());
}

RunMonitor::RunMonitor(const Case& c, const Casing& casing, const RunOptions& options,
                       RunResult& result)
    : m_casing(casing)
    , m_options(options)
    , m_result(result)
    , m_output_every(c.time.output_every)
    // Tips moved by a thousand clearances: nothing physical, a blow-up.
    , m_runaway_gap(1000.0 * (c.casing.radius - c.bladed_disk.tip_radius)) {
  RunSummary& s = m_result.summary;
  s.steps_requested = static_cast<int>(std::llround(c.time.duration / c.time.step));
  s.completed = true;
  s.status = "completed";
}

void RunMonitor::add_row(const StepState& state, double energy) {
  const bool tips = m_options.tip_displacement && state.tips != nullptr;
  if (tips) (*state.tips)(m_tips);
  const HistoryRow row{state.time,          state.gap,          state.lambda,
                       energy,              state.external_work, state.contact_work,
                       state.damping_work,  state.lambda_tangential,
                       tips ? &m_tips : nullptr};
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
  if (needs_casing(r)) {
    if (state.casing.size() != m_casing.n_dofs())
      throw std::logic_error("RunMonitor: the casing displacement is needed at the first contact");
    s.first_contact_step = state.step;
    const Eigen::VectorXd all = on_all_nodes(m_casing, state.casing);
    const int n = m_casing.n_elements;
    m_result.casing_u_at_first_contact =
        Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<4>>(all.data(), n);
    m_result.casing_v_at_first_contact =
        Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<4>>(all.data() + 2, n);
  }
  m_largest_external_work = std::max(m_largest_external_work, std::abs(state.external_work));

  const bool contact = state.lambda(0) > 0.0;
  if (contact) {
    if (!m_in_contact) s.contact_intervals_blade_1.emplace_back(state.time, state.time);
    s.contact_intervals_blade_1.back().second = state.time;
  }
  m_in_contact = contact;

  // Every step: a blow-up shows first in the gaps; the energy is checked on
  // the output steps.
  if (!state.gap.allFinite() || state.gap.cwiseAbs().maxCoeff() > m_runaway_gap) {
    add_row(state, energy());
    std::ostringstream message;
    message << "blow-up: a blade tip gap is non-finite or beyond " << m_runaway_gap
            << " m (1000 clearances) at step " << state.step << " (t = " << state.time << " s)";
    return stop(message.str());
  }
  if (state.step % 1000 == 0) {
    if (m_options.progress) m_options.progress(double(state.step) / s.steps_requested);
    if (m_options.checkpoint) m_options.checkpoint();
  }
  if (state.step % m_output_every != 0 && state.step != s.steps_requested) return true;

  const double e = energy();
  add_row(state, e);
  s.max_energy = std::max(s.max_energy, e);
  s.energy_scale = std::max({s.energy_scale, std::abs(e), std::abs(state.external_work),
                             std::abs(state.contact_work), std::abs(state.damping_work)});
  s.energy_balance_error =
      std::max(s.energy_balance_error, std::abs(e - s.initial_energy - state.external_work -
                                                state.contact_work + state.damping_work));
  if (!std::isfinite(e))
    return stop("blow-up: non-finite energy at step " + std::to_string(state.step) +
                " (t = " + std::to_string(state.time) + " s)");
  // The energy a run may hold comes from E_0 and the external work (contact
  // can feed some in, SPEC §3). At step 1 the external work is round-off
  // (u_1 = u_-1 exactly from rest: W_ext = F^T (u_1 - u_-1) / 2 = 0), while
  // E_0 = dt^2/8 F^T M^-1 F is not: leaving E_0 out called every run
  // sampled at step 1 a blow-up (issue 13).
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

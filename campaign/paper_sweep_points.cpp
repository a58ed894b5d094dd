#include "paper_sweep_points.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "casing.hpp"
#include "nodal_diameter_map.hpp"
#include "critical_step.hpp"
#include "failure_advice.hpp"
#include "interaction_lines.hpp"
#include "interruption_flag.hpp"
#include "modal_analysis.hpp"
#include "reduced_run.hpp"
#include "reference_run.hpp"
#include "run_monitor.hpp"
#include "run_outputs.hpp"
#include "run_step.hpp"
#include "sweep_indicators.hpp"

namespace rsi {
namespace {

/// One run of the sweep's list, prepared once for every speed: its basis
/// (the rotation enters only through contact) and its expected cost.
struct PreparedRun {
  CampaignRun run;
  std::optional<ReducedBasis> basis; ///< reduced methods
  double basis_seconds = 0.0;
  double cost = 0.0; ///< expected steps x integrated coordinates a speed (the schedule's weight)
};

std::string run_name_of(const CampaignRun& run) {
  return sweep_run_name(run);
}

/// The case of one speed: the sweep's duration and damping.
Case case_at(const Case& c, double speed) {
  Case out = c;
  out.operating_point.rotation_speed = speed;
  out.time.duration = c.sweep.duration;
  out.damping = c.sweep.damping;
  return out;
}

std::string csv_row(double speed, const CampaignRun& run, const std::string& status,
                    const SweepIndicators* ind) {
  std::string row;
  append_csv_number(row, speed);
  row += "," + run_name_of(run) + "," + run.method + "," + std::to_string(run.modes) + "," +
         status + "," + (status == "diverged" ? "1" : "0") + ",";
  if (ind == nullptr) return row + ",,,,,,,,,,,\n";
  row += std::to_string(ind->rows);
  for (double x : {ind->max_tip_radial, ind->max_tip_tangential, ind->max_contact_force,
                   ind->contact_fraction, ind->energy_ratio}) {
    row += ",";
    if (ind->rows > 0) append_csv_number(row, x);
  }
  for (size_t i = 0; i < 3; ++i) {
    row += ",";
    if (i < ind->peaks.size()) append_csv_number(row, ind->peaks[i].frequency_hz);
    row += ",";
    if (i < ind->peaks.size()) append_csv_number(row, ind->peaks[i].amplitude);
  }
  return row + "\n";
}

class PaperSweepPoints : public SweepPoints {
public:
  PaperSweepPoints(Case c, int disk_dofs, RefusedStepMessage refused_step)
      : m_case(std::move(c)), m_disk_dofs(disk_dofs), m_refused_step(std::move(refused_step)) {}

  const std::vector<double>& speeds() const override { return m_case.sweep.speeds; }
  int n_runs() const override { return static_cast<int>(m_case.sweep.runs.size()); }
  std::string run_name(int run) const override {
    return run_name_of(m_case.sweep.runs[static_cast<size_t>(run)]);
  }

  void prepare() override {
    // The bases, once for every speed (on every rank: each needs them).
    const Casing casing = assemble_casing(m_case);
    const double casing_omega = max_angular_frequency(casing.stiffness, casing.mass);
    m_runs.resize(m_case.sweep.runs.size());
    for (size_t j = 0; j < m_runs.size(); ++j) {
      m_runs[j].run = m_case.sweep.runs[j];
      if (m_runs[j].run.method != "full") {
        const Clock::time_point t = Clock::now();
        m_runs[j].basis = build_reduced_basis(m_case, m_runs[j].run.method, m_runs[j].run.modes,
                                              m_runs[j].run.selection);
        m_runs[j].basis_seconds = seconds_since(t);
      }
      m_runs[j].cost = expected_cost(m_runs[j], casing, casing_omega);
    }
  }

  double cost(double, int run) const override { return m_runs[static_cast<size_t>(run)].cost; }

  std::string csv_header() const override {
    return "speed_rad_s,run,method,modes,status,diverged,rows,max_tip_radial_m,"
           "max_tip_tangential_m,max_contact_force_n,contact_fraction,energy_ratio,f1_hz,a1_m,"
           "f2_hz,a2_m,f3_hz,a3_m\n";
  }

  /// One (speed, run): the indicators of its history, or why it failed.
  SweepTaskResult run(double speed, int run, bool inject_failure) const override {
    const Case& c = m_case;
    const PreparedRun& r = m_runs[static_cast<size_t>(run)];
    const Case at = case_at(c, speed);
    SweepIndicatorAccumulator indicators(c.sweep.transient, c.time.step * c.time.output_every);
    ReducedRunOptions options;
    options.step = r.run.step;
    options.step_key = c.source + ": sweep run " + run_name_of(r.run) + ": time_step";
    options.casing_modes = r.run.casing_modes;
    options.selection = r.run.selection;
    options.run.checkpoint = throw_if_interrupted;
    options.run.tip_displacement = true;
    options.run.history_sink = [&](const HistoryRow& row) { indicators.add(row); };
    SweepTaskResult out;
    try {
      if (inject_failure)
        throw std::runtime_error("injected failure (RSI_SWEEP_FAIL_SPEED, for the tests)");
      const RunResult result = r.run.method == "full" ? run_reference(at, options.run)
                                                      : run_reduced(at, *r.basis, options).run;
      const SweepIndicators ind = indicators.finish();
      out.seconds = result.summary.wall_seconds;
      out.row = csv_row(speed, r.run, result.summary.completed ? "completed" : "diverged", &ind);
    } catch (const Interrupted&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw; // out of memory ends the sweep, not one speed
    } catch (const StabilityError& e) {
      // The caller says what sets the step (a sweep has no --force).
      out.row = csv_row(speed, r.run, "failed", nullptr);
      out.error = m_refused_step(r.run, e);
    } catch (const std::exception& e) {
      out.row = csv_row(speed, r.run, "failed", nullptr);
      out.error = failure_message(e);
    }
    return out;
  }

  std::string failed_row(double speed, int run) const override {
    return csv_row(speed, m_case.sweep.runs[static_cast<size_t>(run)], "failed", nullptr);
  }

  std::vector<std::pair<std::string, std::string>> side_files() const override {
    return {{"interaction_lines.csv", interaction_lines_csv(interaction_lines(m_case, 2, 40))}};
  }

  nlohmann::json summary() const override {
    const Case& c = m_case;
    nlohmann::json s;
    s["duration_s"] = c.sweep.duration;
    s["transient_s"] = c.sweep.transient;
    s["window"] = "Hann (periodic), t >= transient, blade 1 radial tip displacement, mean "
                  "removed; resolution 1/(rows x output interval)";
    s["damping"] = {{"rayleigh_alpha", c.sweep.damping.rayleigh.alpha},
                    {"rayleigh_beta", c.sweep.damping.rayleigh.beta},
                    {"modal_ratio", c.sweep.damping.modal_ratio}};
    return s;
  }

  nlohmann::json run_summary(int run) const override {
    const PreparedRun& r = m_runs[static_cast<size_t>(run)];
    return {{"method", r.run.method}, {"modes", r.run.modes}, {"basis_s", r.basis_seconds}};
  }

  std::string report_script() const override { return "make_sweep_report.py"; }

private:
  /// Expected steps x integrated coordinates of one speed: the weight of
  /// the rank schedule (sweep_schedule.hpp), not a measurement.
  double expected_cost(const PreparedRun& r, const Casing& casing, double casing_omega_max) const {
    const Case& c = m_case;
    const double interval = c.time.step * c.time.output_every;
    if (r.run.method == "full")
      return c.sweep.duration / c.time.step * (m_disk_dofs + casing.n_dofs());
    const int casing_coordinates =
        r.run.casing_modes > 0 ? r.run.casing_modes + 1 : casing.n_dofs();
    double dt = c.time.step;
    if (r.run.step.kind == StepRule::Kind::given) dt = r.run.step.step;
    if (r.run.step.kind == StepRule::Kind::own) {
      double omega = reduced_omega_max(*r.basis);
      if (r.run.casing_modes == 0) omega = std::max(omega, casing_omega_max);
      dt = interval / std::ceil(interval / (r.run.step.safety * 2.0 / omega));
    }
    return c.sweep.duration / dt * (r.basis->n_reduced() + casing_coordinates);
  }

  Case m_case;
  int m_disk_dofs = 0;
  RefusedStepMessage m_refused_step;
  std::vector<PreparedRun> m_runs;
};

} // namespace

std::string sweep_run_name(const CampaignRun& run) {
  return run.method == "full" ? "full" : run.name();
}

std::unique_ptr<SweepPoints> paper_sweep_points(Case c, int disk_dofs,
                                                RefusedStepMessage refused_step) {
  return std::make_unique<PaperSweepPoints>(std::move(c), disk_dofs, std::move(refused_step));
}

} // namespace rsi

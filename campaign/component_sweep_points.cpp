#include "component_sweep_points.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "campbell_crossings.hpp"
#include "case_file.hpp"
#include "failure_advice.hpp"
#include "interruption_flag.hpp"
#include "modal_analysis.hpp"
#include "nodal_diameter_map.hpp"
#include "reduction.hpp"
#include "rigid_surface_contact.hpp"
#include "rubbing_indicators.hpp"
#include "rubbing_run.hpp"
#include "run_monitor.hpp"
#include "run_list_checks.hpp"
#include "run_outputs.hpp"
#include "speed_subspace.hpp"

namespace rsi {
namespace {

/// sweep.csv's status of a run that came back: "completed"; "worn_through"
/// when a tip wore a liner cell to its thickness (the liner model ends
/// there, the blade did not blow up: not counted as diverged); else
/// "diverged" (a monitor stopped it).
std::string run_status_word(const RunSummary& s) {
  if (s.completed) return "completed";
  const std::vector<Remedy>& remedies = s.status_advice.remedies;
  if (std::find(remedies.begin(), remedies.end(), Remedy::thicker_liner_or_larger_clearance) !=
      remedies.end())
    return "worn_through";
  return "diverged";
}

/// Lowest natural frequencies written a run (interaction_lines.csv).
constexpr int blade_frequencies = 5;
/// Engine orders of interaction_lines.csv: 1 .. this.
constexpr int engine_orders = 10;
/// With rotation effects, the Campbell grid's speeds at most (the sweep's
/// own when fewer): each is one eigenproblem (campbell_subspace()).
constexpr int campbell_grid = 41;

struct PreparedRun {
  ComponentSweepRun run;
  std::optional<ReducedBasis> basis; ///< reduced methods
  /// Reduced methods against the flexible casing: its modes and static
  /// correction, one basis for every speed and every reduced run.
  std::shared_ptr<const CasingBasis> casing;
  /// Reduced methods with rotation effects: the subspace each speed's basis is reduced in.
  std::shared_ptr<const SpeedSubspace> subspace;
  double basis_seconds = 0.0;
  int coordinates = 0;
  std::vector<double> frequencies_hz; ///< the lowest natural frequencies, ascending
};

std::string run_name_of(const ComponentSweepRun& run) {
  return run.method == "full" ? "full" : run.method + "-" + std::to_string(run.modes);
}

/// The lowest natural frequencies of a run's model, tip free [Hz]: a
/// massless boundary's kept modes (its M^ is singular), else the dense
/// pencil (K^, M^), or the full model's lowest_modes; empty if the full
/// model's mass is singular (no full run can use it either).
std::vector<double> natural_frequencies(const RubbingModel& model, const PreparedRun& r) {
  std::vector<double> hz;
  if (r.basis && r.basis->massless_boundary) {
    for (Eigen::Index i = 0; i < r.basis->mode_omega.size(); ++i)
      hz.push_back(r.basis->mode_omega(i) / (2.0 * M_PI));
  } else if (r.basis) {
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> e(
        r.basis->stiffness, r.basis->mass, Eigen::EigenvaluesOnly);
    if (e.info() == Eigen::Success)
      for (Eigen::Index i = 0; i < e.eigenvalues().size(); ++i)
        hz.push_back(std::sqrt(std::max(0.0, e.eigenvalues()(i))) / (2.0 * M_PI));
  } else {
    try {
      const Modes modes = lowest_modes(model.component().stiffness, model.component().mass,
                                       std::min(blade_frequencies, model.component().n_dofs() - 1));
      for (int i = 0; i < modes.n_modes(); ++i)
        hz.push_back(modes.frequency_hz(i));
    } catch (const ModalError&) {
      hz.clear();
    }
  }
  std::sort(hz.begin(), hz.end());
  if (static_cast<int>(hz.size()) > blade_frequencies) hz.resize(blade_frequencies);
  return hz;
}

class ComponentSweepPoints : public SweepPoints {
public:
  ComponentSweepPoints(RubbingModel model, ComponentSweep sweep, std::vector<PreparedRun> runs,
                       std::shared_ptr<const RotationFit> rotation)
      : m_model(std::move(model)), m_sweep(std::move(sweep)), m_runs(std::move(runs)),
        m_rotation(std::move(rotation)) {
    if (m_rotation) {
      m_frame = m_model;
      Component& component = m_frame->problem.structures.front();
      component.stiffness = Eigen::SparseMatrix<double>();
      component.mass = Eigen::SparseMatrix<double>();
    }
  }

  const std::vector<double>& speeds() const override { return m_sweep.speeds; }
  int n_runs() const override { return static_cast<int>(m_runs.size()); }
  std::string run_name(int run) const override {
    return run_name_of(m_runs[static_cast<size_t>(run)].run);
  }
  void prepare() override {} // the bases were built with the input checks

  /// Samples x coordinates: the steps a sample (more as Omega falls, for
  /// the mass-carrying runs) are left out of this weight.
  double cost(double, int run) const override {
    return m_sweep.revolutions * m_model.setup().steps_per_revolution *
           m_runs[static_cast<size_t>(run)].coordinates;
  }

  /// Against the flexible casing the tip's radial motion is not read from
  /// the gap (the casing moves too): column 8 is the response dof's largest
  /// |u| instead (rubbing_indicators.hpp).
  std::string csv_header() const override {
    return std::string("speed_rad_s,run,method,modes,status,diverged,rows,") +
           (flexible() ? "max_abs_response" : "max_tip_radial") +
           ",max_contact_force,contact_fraction,energy_ratio,balance_residual,f1_hz,"
           "a1,f2_hz,a2,f3_hz,a3" +
           (liner() ? ",max_wear_depth,wear_lobes,plastic_work\n" : "\n");
  }

  SweepTaskResult run(double speed, int run, bool inject_failure) const override {
    const PreparedRun& r = m_runs[static_cast<size_t>(run)];
    const RubbingSetup& setup = m_model.setup();
    const double period = 2.0 * M_PI / std::abs(speed);
    const double interval = period / setup.steps_per_revolution * setup.output_every;
    // The rigid casing's law of this speed, for g0_c(t) (the runs build
    // their own); against the flexible casing the gap is the two bodies'.
    std::optional<RubbingModel> spinning;
    if (m_rotation) spinning = model_at(speed, r.run.method == "full");
    const RubbingModel& model = spinning ? *spinning : m_model;
    std::optional<RigidSurfaceContact> casing;
    if (!flexible()) {
      const ImposedGap gap = setup.oval_gap ? ImposedGap::oval(setup.gap, setup.gap_width)
                                            : ImposedGap::constant(setup.gap);
      // With rotation effects the indicators' radial tip displacement is
      // measured from the static deflected tip (g0_c(t) - growth_c).
      std::vector<RigidSurfaceNode> nodes =
          rigid_surface_nodes(model.component(), model.contact_nodes());
      for (size_t k = 0; k < model.problem.casing.tip_growth.size(); ++k)
        nodes[k].growth = model.problem.casing.tip_growth[k];
      casing.emplace(std::move(nodes), gap, speed, setup.friction_coefficient,
                     setup.sliding_against_rotation ? -speed : speed,
                     m_model.component().rotation_axis);
    }
    const double transient = m_sweep.transient_revolutions * period;
    RubbingIndicatorAccumulator indicators =
        casing ? RubbingIndicatorAccumulator(*casing, transient, interval)
               : RubbingIndicatorAccumulator(transient, interval);
    RubbingRunOptions options;
    options.method = r.run.method;
    options.modes = r.run.method == "cc" ? r.run.fixed_interface_modes : r.run.modes;
    options.boundary_modes = r.run.method == "cc" ? r.run.modes : 0;
    options.revolutions = m_sweep.revolutions;
    options.revolutions_key = "sweep.revolutions";
    options.rotation_speed = speed;
    options.basis = r.basis ? &*r.basis : nullptr;
    options.casing_basis = r.casing.get();
    std::optional<ReducedBasis> at_speed;
    options.checkpoint = throw_if_interrupted;
    SweepTaskResult out;
    try {
      if (inject_failure)
        throw std::runtime_error("injected failure (RSI_SWEEP_FAIL_SPEED, for the tests)");
      if (r.subspace) {
        at_speed = reduce_at_speed(*r.subspace, *m_rotation, speed);
        options.basis = &*at_speed;
      }
      const RubbingRun result =
          run_rubbing(model, options, [&](const HistoryRow& row, double response) {
            indicators.add(row, response);
          });
      out.seconds = result.summary.wall_seconds;
      const double residual = result.summary.energy_scale > 0.0
                                  ? result.summary.energy_balance_error / result.summary.energy_scale
                                  : 0.0;
      out.row = csv_row(speed, r.run, run_status_word(result.summary), indicators.finish(),
                        residual, flexible());
      if (liner()) {
        // The wear the run left (its whole window, the transient included).
        out.row.pop_back();
        out.row += ",";
        append_csv_number(out.row, result.summary.max_wear_depth);
        out.row += "," + std::to_string(result.summary.wear_lobes) + ",";
        append_csv_number(out.row, result.summary.final_plastic_work);
        out.row += "\n";
      }
    } catch (const Interrupted&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw; // out of memory ends the sweep, not one speed
    } catch (const std::exception& e) {
      out.row = failed_row(speed, run);
      out.error = failure_message(e);
    }
    return out;
  }

  std::string failed_row(double speed, int run) const override {
    return row_start(speed, m_runs[static_cast<size_t>(run)].run, "failed") + ",,,,,,,,,,," +
           (liner() ? ",,,\n" : "\n");
  }

  std::vector<std::pair<std::string, std::string>> side_files() const override {
    if (m_rotation) return rotating_side_files();
    if (flexible()) return system_side_files();
    std::string lines = "run,mode,blade_hz,engine_order,casing_harmonic,speed_rad_s\n";
    const bool oval = m_model.setup().oval_gap;
    const double sign = m_sweep.speeds.front() > 0.0 ? 1.0 : -1.0;
    for (const PreparedRun& r : m_runs)
      for (size_t k = 0; k < r.frequencies_hz.size(); ++k)
        for (int eo = 1; eo <= engine_orders; ++eo) {
          lines += run_name_of(r.run) + "," + std::to_string(k + 1) + ",";
          append_csv_number(lines, r.frequencies_hz[k]);
          lines += "," + std::to_string(eo) + "," + (oval && eo % 2 == 0 ? "1" : "0") + ",";
          append_csv_number(lines, sign * 2.0 * M_PI * r.frequencies_hz[k] / eo);
          lines += "\n";
        }
    return {{"interaction_lines.csv", lines}};
  }

  nlohmann::json summary() const override {
    const RubbingSetup& setup = m_model.setup();
    nlohmann::json s;
    s["case_kind"] = "component";
    s["component"] = m_model.component().name;
    s["units"] = m_model.component_case().units;
    s["revolutions"] = m_sweep.revolutions;
    s["transient_revolutions"] = m_sweep.transient_revolutions;
    s["steps_per_revolution"] = setup.steps_per_revolution;
    s["output_every"] = setup.output_every;
    s["contact_nodes"] = m_model.contact_nodes().size();
    s["response"] = m_model.response_name();
    s["gap"] = flexible() ? "the flexible casing's (rubbing.casing)"
               : setup.oval_gap ? "oval, 2 lobes"
                                : "constant";
    if (flexible()) s["casing_modes"] = setup.casing_modes;
    s["tip_sliding"] = setup.sliding_against_rotation ? "against_rotation" : "with_rotation";
    s["friction_coefficient"] = setup.friction_coefficient;
    s["modal_ratio"] = m_model.component_case().damping.modal_ratio;
    if (const std::optional<ProblemLiner>& l = m_model.problem.casing.liner)
      s["liner"] = {{"radius", l->radius},       {"thickness", l->thickness},
                    {"young_modulus", l->young}, {"yield_stress", l->yield},
                    {"hardening_modulus", l->hardening}, {"cells_around", l->n_theta},
                    {"axial_rows", l->n_axial}};
    if (m_rotation) {
      const SpeedSubspace* subspace = campbell_subspace();
      s["campbell_model"] = subspace ? "the " + subspace->method + "-" + std::to_string(subspace->modes) +
                                           " run's speed subspace (" +
                                           std::to_string(subspace->n_subspace()) +
                                           " coordinates, Rayleigh-Ritz)"
                                     : std::string("the full parametric model");
    }
    s["window"] = "Hann (periodic), t >= transient, the response dof " + m_model.response_name() +
                  ", mean removed; resolution 1/(rows x output interval)";
    return s;
  }

  nlohmann::json run_summary(int run) const override {
    const PreparedRun& r = m_runs[static_cast<size_t>(run)];
    nlohmann::json summary = {{"method", r.run.method},
                              {"modes", r.run.modes},
                              {"basis_s", r.basis_seconds},
                              {"coordinates", r.coordinates},
                              {"natural_frequencies_hz", r.frequencies_hz}};
    if (r.run.method == "cc") summary["fixed_interface_modes"] = r.run.fixed_interface_modes;
    if (r.subspace) {
      // The subspace once (basis_s), then a reduction inside it at each speed.
      summary["subspace_coordinates"] = r.subspace->n_subspace();
      summary["subspace_basis_speeds"] = r.subspace->basis_speeds;
    }
    return summary;
  }

  std::string report_script() const override {
    return flexible() ? "make_system_sweep_report.py" : "make_component_sweep_report.py";
  }

private:
  /// The case wears an abradable liner: the rows carry its columns.
  bool liner() const { return m_model.problem.casing.liner.has_value(); }
  /// Against the flexible casing (rubbing.casing), not a rigid one.
  bool flexible() const { return m_model.setup().casing.has_value(); }

  /// A bladed disk against the flexible casing: the nodal-diameter map and
  /// its interaction lines Omega_int = 2 pi (f_b + f_c) / n, as rsi campaign
  /// writes them (nodal_diameter_map.hpp; the full model's, the same for
  /// every run); another rotor: none.
  std::vector<std::pair<std::string, std::string>> system_side_files() const {
    const std::optional<NodalDiameterMap> map = system_nodal_diameter_map(m_model);
    if (!map) return {};
    return {{"nodal_diameters.csv", nodal_diameters_csv(*map)},
            {"interaction_lines.csv", system_interaction_lines_csv(map->lines)}};
  }

  static std::string row_start(double speed, const ComponentSweepRun& run,
                               const std::string& status) {
    std::string row;
    append_csv_number(row, speed);
    return row + "," + run_name_of(run) + "," + run.method + "," + std::to_string(run.modes) +
           "," + status + "," + (status == "diverged" ? "1" : "0");
  }

  static std::string csv_row(double speed, const ComponentSweepRun& run, const std::string& status,
                             const RubbingIndicators& ind, double residual, bool flexible) {
    std::string row = row_start(speed, run, status) + "," + std::to_string(ind.rows);
    for (double x : {flexible ? ind.max_abs_response : ind.max_tip_radial, ind.max_contact_force,
                     ind.contact_fraction,
                     ind.energy_ratio, residual}) {
      row += ",";
      if (ind.rows > 0 && std::isfinite(x)) append_csv_number(row, x);
    }
    for (size_t i = 0; i < 3; ++i) {
      row += ",";
      if (i < ind.peaks.size()) append_csv_number(row, ind.peaks[i].frequency_hz);
      row += ",";
      if (i < ind.peaks.size()) append_csv_number(row, ind.peaks[i].amplitude);
    }
    return row + "\n";
  }

  /// The model at `speed` by the rotation fit: each contact node's static
  /// growth in the gap and, with `matrices` (the full run), K(Omega) and
  /// the mass at rest. A reduced run's basis comes from the subspace and
  /// the run reads only the model's geometry, dofs and contact set-up, so it
  /// gets the frame without K and M: building K(Omega) and copying the
  /// model at every speed was 40 % of the Rotor 37 rotating map's run phase
  /// (perf, session 22).
  RubbingModel model_at(double speed, bool matrices) const {
    RubbingModel at = *m_frame;
    Component& component = at.problem.structures.front();
    RotatingComponent rotating;
    if (matrices) {
      rotating = rotating_component_at(*m_rotation, speed);
      component.stiffness = std::move(rotating.component.stiffness);
      component.mass = std::move(rotating.component.mass);
    } else {
      // rotating_component_at's deflection, without its K(Omega).
      rotating.deflection = speed == 0.0 ? Eigen::VectorXd::Zero(component.n_dofs())
                                         : rotation_fit_deflection(*m_rotation, speed);
    }
    at.problem.contact.rotation_speed = speed;
    // The gap is the clearance at rubbing.clearance_speed: the growth from there.
    const double clearance_speed = m_model.setup().clearance_speed;
    const Eigen::VectorXd reference = rotation_fit_deflection(*m_rotation, clearance_speed);
    at.problem.casing.tip_growth.clear();
    for (int node : at.contact_nodes())
      at.problem.casing.tip_growth.push_back(radial_growth(component, rotating.deflection, node) -
                                             radial_growth(component, reference, node));
    return at;
  }

  /// campbell.csv (campbell_subspace()'s lowest frequencies on a grid over
  /// the sweep's speeds) and interaction_lines.csv (each engine order's
  /// crossings with them, at the crossing speed, the same for every run).
  std::vector<std::pair<std::string, std::string>> rotating_side_files() const {
    std::vector<double> grid;
    const double low = std::abs(m_sweep.speeds.front()), high = std::abs(m_sweep.speeds.back());
    const double sign = m_sweep.speeds.front() > 0.0 ? 1.0 : -1.0;
    if (static_cast<int>(m_sweep.speeds.size()) <= campbell_grid) {
      for (double w : m_sweep.speeds) grid.push_back(std::abs(w));
    } else {
      for (int i = 0; i < campbell_grid; ++i)
        grid.push_back(std::min(low, high) + std::abs(high - low) * i / (campbell_grid - 1));
    }
    std::sort(grid.begin(), grid.end());
    grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
    const int count = std::min(blade_frequencies, m_model.component().n_dofs() - 1);
    Eigen::MatrixXd hz(static_cast<Eigen::Index>(grid.size()), count);
    std::string campbell = "speed_rad_s,mode,frequency_hz\n";
    const SpeedSubspace* subspace = campbell_subspace();
    for (size_t g = 0; g < grid.size(); ++g) {
      Eigen::VectorXd lambda;
      if (subspace) {
        lambda = subspace_eigenvalues(*subspace, *m_rotation, grid[g], count);
      } else {
        const RotatingComponent at = rotating_component_at(*m_rotation, grid[g]);
        lambda = lowest_modes(at.component.stiffness, at.component.mass, count).omega_squared;
      }
      for (int i = 0; i < count; ++i) {
        hz(static_cast<Eigen::Index>(g), i) =
            std::copysign(std::sqrt(std::abs(lambda(i))), lambda(i)) / (2.0 * M_PI);
        append_csv_number(campbell, sign * grid[g]);
        campbell += "," + std::to_string(i + 1) + ",";
        append_csv_number(campbell, hz(static_cast<Eigen::Index>(g), i));
        campbell += "\n";
      }
    }
    std::string lines = "run,mode,blade_hz,engine_order,casing_harmonic,speed_rad_s\n";
    const bool oval = m_model.setup().oval_gap;
    if (grid.size() >= 2)
      for (const PreparedRun& r : m_runs)
        for (const CampbellCrossing& c : campbell_crossings(grid, hz, engine_orders)) {
          lines += run_name_of(r.run) + "," + std::to_string(c.mode) + ",";
          append_csv_number(lines, c.frequency_hz);
          lines += "," + std::to_string(c.engine_order) + "," +
                   (oval && c.engine_order % 2 == 0 ? "1" : "0") + ",";
          append_csv_number(lines, sign * c.speed_rad_s);
          lines += "\n";
        }
    return {{"interaction_lines.csv", lines}, {"campbell.csv", campbell}};
  }

  /// The Campbell diagram's model: the first reduced run's subspace (a
  /// Rayleigh-Ritz model of the fit holding the method's bases at 0 and the
  /// fit speeds: a dense eigenproblem of a few hundred dofs a speed), or
  /// null: the full parametric model (one sparse eigensolve a speed).
  const SpeedSubspace* campbell_subspace() const {
    for (const PreparedRun& r : m_runs)
      if (r.subspace) return r.subspace.get();
    return nullptr;
  }

  RubbingModel m_model;
  ComponentSweep m_sweep;
  std::vector<PreparedRun> m_runs;
  std::shared_ptr<const RotationFit> m_rotation; ///< null: the blade at rest at every speed
  /// With rotation effects: m_model without K and M (model_at's start).
  std::optional<RubbingModel> m_frame;
};

} // namespace

std::vector<double> sweep_rotation_fit_speeds(const ComponentCase& c, const ComponentSweep& sweep) {
  double top = c.rubbing ? c.rubbing->clearance_speed : 0.0;
  for (double w : sweep.speeds) top = std::max(top, std::abs(w));
  if (sweep.rotation_fit_speeds.empty()) {
    std::vector<double> speeds;
    for (double fraction : {0.1, 0.2, 0.4, 0.6, 0.8, 1.0}) speeds.push_back(fraction * top);
    return speeds;
  }
  if (top > sweep.rotation_fit_speeds.back())
    throw CaseError(c.case_path + ": key 'sweep.rotation_fit_speeds': the sweep (or rubbing."
                    "clearance_speed) reaches " +
                    std::to_string(top) + " rad/s, above the highest fit speed " +
                    std::to_string(sweep.rotation_fit_speeds.back()) +
                    " rad/s (the model does not extrapolate)");
  return sweep.rotation_fit_speeds;
}

std::unique_ptr<SweepPoints> component_sweep_points(RubbingModel model, ComponentSweep sweep,
                                                    const std::string& where,
                                                    std::shared_ptr<const RotationFit> rotation,
                                                    int threads) {
  if (model.component_case().rotation_effects && !rotation)
    throw std::logic_error("component_sweep_points: rotation effects need the rotation fit");
  std::vector<PreparedRun> runs(sweep.runs.size());
  std::shared_ptr<const CasingBasis> casing; // built by the first reduced run that needs it
  for (size_t j = 0; j < runs.size(); ++j) {
    PreparedRun& r = runs[j];
    r.run = sweep.runs[j];
    r.coordinates = model.component().n_dofs();
    if (rotation && r.run.method == "cc")
      throw std::invalid_argument(where + "cc has no speed subspace (rotation effects)");
    // A refused mode count of a case's entry named by its key, of a
    // --method run by the option (where).
    const auto refused = [&](const ReductionError& e) {
      const std::optional<ReductionError> keyed =
          r.run.entry < 0
              ? std::nullopt
              : keyed_by_entry(e, "sweep.runs[" + std::to_string(r.run.entry) + "]", r.run.method);
      if (keyed)
        return ReductionError(keyed->what(),
                              in_context(keyed->advice(), model.component_case().case_path + ": "));
      return ReductionError(e.what(), in_context(e.advice(), where + run_name_of(r.run) + ": "));
    };
    if (rotation && r.run.method != "full") {
      // One subspace over the speeds: the method's bases at 0 and the fit
      // speeds; each speed's basis reduced inside it (speed_subspace.hpp).
      const Clock::time_point t = Clock::now();
      std::vector<double> basis_speeds = {0.0};
      basis_speeds.insert(basis_speeds.end(), rotation->fit_speeds.begin(), rotation->fit_speeds.end());
      try {
        r.subspace = std::make_shared<const SpeedSubspace>(
            speed_subspace(*rotation, r.run.method, r.run.modes, basis_speeds, threads));
      } catch (const ReductionError& e) {
        throw refused(e);
      }
      r.basis_seconds = seconds_since(t);
      r.coordinates = static_cast<int>(model.component().boundary.size()) + r.run.modes;
    } else if (r.run.method != "full") {
      const Clock::time_point t = Clock::now();
      // The casing's count checked before the rotor's basis (as run_rubbing).
      if (model.setup().casing && !casing)
        casing = std::make_shared<const CasingBasis>(rubbing_casing_basis(model, 0));
      r.casing = casing;
      try {
        const bool cc = r.run.method == "cc";
        r.basis = reduce(model.component(), r.run.method,
                         cc ? r.run.fixed_interface_modes : r.run.modes, cc ? r.run.modes : 0);
      } catch (const ReductionError& e) {
        throw refused(e);
      }
      r.basis_seconds = seconds_since(t);
      r.coordinates = r.basis->n_reduced() + (r.casing ? r.casing->size() : 0);
    }
    if (!rotation) r.frequencies_hz = natural_frequencies(model, r);
  }
  return std::make_unique<ComponentSweepPoints>(std::move(model), std::move(sweep),
                                                std::move(runs), std::move(rotation));
}

} // namespace rsi

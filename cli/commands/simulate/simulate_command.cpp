// rsi simulate: one contact run -> history.csv, summary.json (history streamed):
// its options, the rules between them, and the run of the paper's case (a
// component case: component_simulation.cpp).

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include "case_json.hpp"
#include "case_kinds.hpp"
#include "command.hpp"
#include "command_options.hpp"
#include "component_case.hpp"
#include "failure_advice.hpp"
#include "interruption.hpp"
#include "output_files.hpp"
#include "output_sets.hpp"
#include "reduced_run.hpp"
#include "reference_run.hpp"
#include "run_outputs.hpp"
#include "simulate_options.hpp"
#include "staged_output.hpp"
#include "terminal_progress.hpp"
#include "usage_error.hpp"

namespace rsi {
namespace {

class SimulateCommand : public Command {
public:
  explicit SimulateCommand(CLI::App& app);
  int run(StagedOutput& output) override;

private:
  /// An option the method does not use is refused, not ignored (cb, ccm
  /// and guyan check theirs when the basis is built).
  void check_option_rules() const;
  /// The paper's case: the reference or a reduced run.
  int simulate(const Case& c, StagedOutput& output) const;
  /// A component case: its rubbing run (component_simulation.cpp).
  int simulate(const ComponentCase& c, StagedOutput& output) const;

  SimulateOptions m_options;
  CLI::Option* m_modes = nullptr;
  CLI::Option* m_step = nullptr;
  CLI::Option* m_safety = nullptr;
  CLI::Option* m_casing = nullptr;
  CLI::Option* m_selection = nullptr;
};

SimulateCommand::SimulateCommand(CLI::App& app)
    : Command(*app.add_subcommand(
          "simulate", "One contact run -> DIR/history.csv, DIR/summary.json (exit 3 on blow-up)")) {
  SimulateOptions& simulate = m_options;
  m_command.add_option("case", simulate.case_path, "case file (JSON)")
      ->required()
      ->check(case_file());
  m_command
      .add_option("--method", simulate.method,
                  "full (reference), cb, ccm or guyan; macneal, or cc (Craig-Bampton with "
                  "the boundary in characteristic constraint modes), for a component case")
      ->capture_default_str()
      ->check(one_of({"full", "cb", "ccm", "guyan", "macneal", "cc"}));
  m_modes = m_command.add_option("--modes", simulate.modes, "modes kept by cb and cc (eta) or ccm, macneal (psi)")
                ->capture_default_str()
                ->check(integer_in(0, 1000000000, modes_allowed));
  m_command
      .add_option("--boundary-modes", simulate.boundary_modes,
                  "cc: the characteristic constraint modes kept of the boundary (n_c, 1 to the "
                  "boundary dofs); --modes: its fixed-interface modes")
      ->capture_default_str()
      ->check(integer_in(0, 1000000000, "the characteristic constraint modes kept"));
  m_command.add_flag(
      "--full-field", simulate.full_field,
      "reduced methods: also write field.csv, every bladed-disk dof (u = T q) per history row");
  m_step = m_command
               .add_option("--time-step", simulate.time_step,
                           "reduced methods: case (time.step), own (the reduced system's stable "
                           "step times --step-safety) or a step in seconds dividing the output "
                           "interval; rows at the case's output times")
               ->capture_default_str();
  m_safety = m_command
                 .add_option("--step-safety", simulate.step_safety,
                             "with --time-step own: the fraction of 2/omega_max, in (0, 1)")
                 ->capture_default_str()
                 ->check(CLI::Range(0.0, 1.0));
  m_casing = m_command
                 .add_option("--casing-modes", simulate.casing_modes,
                             "reduced methods: 0 (the full casing; a component case's "
                             "flexible casing: its rubbing.casing.modes) or N_c, the casing in "
                             "its lowest N_c modes plus a static correction for the forcing")
                 ->capture_default_str()
                 ->check(integer_in(0, 1000000000, "0 (the full casing) or the casing modes kept"));
  m_selection =
      m_command
          .add_option("--selection", simulate.selection,
                      "reduced methods: how the kept modes are chosen: lowest, families "
                      "(whole nodal-diameter families), forced (the forcing's diameters and "
                      "their aliases first) or participation (boundary participation)")
          ->capture_default_str()
          ->check(one_of({"lowest", "families", "forced", "participation"}));
  m_command.add_option("--out", simulate.out, "output directory")
      ->capture_default_str()
      ->check(nonempty_path());
  m_command.add_flag("--force", simulate.force,
                     "integrate even with a time step above the stability limit");
  add_component_options(m_command, simulate.load);
}

void SimulateCommand::check_option_rules() const {
  const SimulateOptions& simulate = m_options;
  if (m_modes->count() > 0 && simulate.method == "full")
    throw UsageError("--modes: only for a reduced method (the full reference keeps "
                     "no modes); drop it");
  for (const CLI::Option* o : {m_step, m_safety, m_casing, m_selection})
    if (o->count() > 0 && simulate.method == "full")
      throw UsageError(o->get_name() +
                       ": only for a reduced method (the full reference runs the whole "
                       "model at time.step); drop it");
  if (m_safety->count() > 0 && simulate.time_step != "own")
    throw UsageError("--step-safety: only with --time-step own; drop it");
}


/// field.csv: one row per history row, t then every bladed-disk dof (u = T q).
std::string field_csv_header(Eigen::Index n_dofs) {
  std::string out = "t";
  for (Eigen::Index i = 0; i < n_dofs; ++i)
    out += ",u_" + std::to_string(i);
  out += "\n";
  return out;
}

void append_field_csv_row(std::string& out, double t, const Eigen::VectorXd& u) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", t);
  out += buffer;
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, ",%.17g", u(i));
    out += buffer;
  }
  out += "\n";
}

} // namespace

int SimulateCommand::run(StagedOutput& output) {
  check_option_rules();
  return visit_case(m_options.case_path, m_options.load,
                    [&](const auto& c) { return simulate(c, output); });
}

int SimulateCommand::simulate(const ComponentCase& c, StagedOutput& output) const {
  const SimulateOptions& options = m_options;
  // A component run takes its step from its rubbing object (each run at
  // its own step already); only the flexible casing has modes to keep.
  if (options.time_step != "case" || options.selection != "lowest")
    throw UsageError("--time-step, --selection: only for the paper's case; a component case "
                     "sets its steps in its rubbing object and keeps the lowest modes");
  if (options.boundary_modes != 0 && options.method != "cc")
    throw UsageError("--boundary-modes: only for --method cc (characteristic constraint modes)");
  if (options.casing_modes != 0 && !(c.rubbing && c.rubbing->casing))
    throw UsageError("--casing-modes: only for the paper's case and a component case with a "
                     "flexible casing (rubbing.casing); this one's casing is rigid");
  return simulate_component_case(options, c, output);
}

int SimulateCommand::simulate(const Case& c, StagedOutput& output) const {
  const SimulateOptions& options = m_options;
  const bool full = options.method == "full";
  if (!full && options.method != "cb" && options.method != "ccm" && options.method != "guyan")
    throw UsageError("--method: must be full, cb, ccm or guyan for the paper's case (macneal, "
                     "cc: component cases), got '" + options.method + "'");
  if (options.boundary_modes != 0)
    throw UsageError("--boundary-modes: only for --method cc on a component case");
  if (full && options.full_field)
    throw UsageError(
        "--full-field: only for the reduced methods (the full run has every dof already)");
  const std::string dir = output.open(options.out, "--out", simulate_output_set());
  ReducedRunOptions run;
  run.run.force = options.force;
  // On a terminal: the preparation (assembly, omega_max, a basis: minutes of
  // Lanczos on a large casing) as a stage line, then the steps' progress.
  const std::function<void(double)> terminal = terminal_progress();
  TerminalStage preparing(std::string("preparing the run (assembly, omega_max") +
                          (full ? ")" : ", the " + options.method + " basis)"));
  run.run.progress = [&preparing, &terminal](double fraction) {
    preparing.done();
    if (terminal) terminal(fraction);
  };
  run.run.checkpoint = throw_if_interrupted;
  run.full_field = options.full_field;
  run.step = parse_step_option(options.time_step, options.step_safety);
  run.step_key = "--time-step";
  run.casing_modes = options.casing_modes;
  run.selection = options.selection;

  // Streamed output: the history rows (and field rows) are formatted and
  // written to temporary files as the run produces them, never kept, so the
  // memory stays flat however long the run; the files are renamed to
  // history.csv (field.csv) when the run returns, completed or stopped by a
  // blow-up. An exception destroys them unrenamed: no half-written output.
  StreamedTextFile history_file(dir + "/history.csv");
  int history_rows = 0;
  std::string line;
  run.run.history_sink = [&](const HistoryRow& row) {
    line.clear();
    if (history_rows++ == 0)
      line = history_csv_header(static_cast<int>(row.gap.size()), history_csv_tangents(row));
    append_history_csv_row(line, row);
    history_file.append(line);
  };
  std::optional<StreamedTextFile> field_file;
  int field_rows = 0;
  if (options.full_field) {
    field_file.emplace(dir + "/field.csv");
    run.field_sink = [&](double t, const Eigen::VectorXd& u) {
      line.clear();
      if (field_rows++ == 0) line = field_csv_header(u.size());
      append_field_csv_row(line, t, u);
      field_file->append(line);
    };
  }

  const RunResult result =
      full ? run_reference(c, run.run) : run_reduced(c, options.method, options.modes, run).run;
  preparing.done();
  finish_terminal_progress(terminal);
  if (history_rows == 0) history_file.append(history_csv_header(0)); // as history_csv(History{})
  history_file.commit();
  write_text_file(dir + "/summary.json", summary_json(result.summary));
  if (result.casing_u_at_first_contact.size() > 0)
    write_text_file(
        dir + "/casing_first_contact.csv",
        casing_snapshot_csv(result.casing_u_at_first_contact, result.casing_v_at_first_contact));
  if (field_file) field_file->commit();
  const RunSummary& s = result.summary;
  std::printf("%s: method %s%s, %d dofs, %d of %d steps in %.3f s (integration %.3f s)\n",
              c.source.c_str(), s.method.c_str(),
              full ? "" : (" " + std::to_string(options.modes) + " modes").c_str(), s.n_dofs,
              s.steps, s.steps_requested, s.wall_seconds, s.integration_seconds);
  std::printf("omega_max %.6e rad/s, critical step %.6e s, step %.3e s\n", s.omega_max,
              s.critical_dt, s.dt);
  std::printf("status: %s\n", run_status(s).c_str());
  std::printf(
      "max penetration %.3e m, min lambda %.3e N, max lambda %.3e N, max |lambda g| %.3e N m, "
      "sliding reversals %d\n",
      s.max_penetration, s.min_lambda, s.max_lambda, s.max_complementarity, s.sliding_reversals);
  if (c.operating_point.friction_law == FrictionLaw::coulomb)
    std::printf("coulomb certificate: max cone violation %.3e N, max stick/slip residual %.3e "
                "(scaled), stick/slip transitions %d, contact-steps stick %ld slip %ld\n",
                s.max_cone_violation, s.max_stick_slip_residual, s.stick_slip_transitions,
                s.stick_contact_steps, s.slip_contact_steps);
  std::printf(
      "energy balance error %.3e J (scale %.3e J); W_ext %.6e J, W_contact %.6e J, W_damp %.6e J\n",
      s.energy_balance_error, s.energy_scale, s.final_external_work, s.final_contact_work,
      s.final_damping_work);
  std::printf("blade 1 contact intervals:");
  for (const auto& [a, b] : s.contact_intervals_blade_1)
    std::printf(" [%.4f, %.4f] ms", 1e3 * a, 1e3 * b);
  std::printf("\n");
  output.announce("wrote " + options.out + "/history.csv, " + options.out + "/summary.json\n");
  if (s.completed) return 0;
  // Exit 3 always says why on stderr, not only in the summary lines above.
  std::fprintf(stderr,
               "rsi: error: numerical failure: the run stopped: %s; %s (--out %s holds the run "
               "up to the stop)\n",
               run_status(s).c_str(), stopped_run_remedy(s).c_str(), options.out.c_str());
  return 3;
}

std::unique_ptr<Command> add_simulate_command(CLI::App& app) {
  return std::make_unique<SimulateCommand>(app);
}

} // namespace rsi

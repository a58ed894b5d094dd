// rsi simulate: one contact run -> history.csv, summary.json (history streamed).

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

#include "case_json.hpp"
#include "commands.hpp"
#include "component_case.hpp"
#include "failure_remedies.hpp"
#include "interruption.hpp"
#include "output_files.hpp"
#include "reduced_run.hpp"
#include "reference_run.hpp"
#include "run_outputs.hpp"
#include "staged_output.hpp"
#include "terminal_progress.hpp"

namespace rsi {
namespace {

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

StepRule parse_step_option(const std::string& text, double safety) {
  StepRule rule;
  rule.safety = safety;
  if (text == "case") return rule;
  if (text == "own") {
    rule.kind = StepRule::Kind::own;
    return rule;
  }
  char* end = nullptr;
  errno = 0;
  const double step = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno != 0 || !std::isfinite(step) ||
      !(step > 0.0))
    throw UsageError("--time-step: must be case, own or a step in seconds > 0, got '" + text + "'");
  rule.kind = StepRule::Kind::given;
  rule.step = step;
  return rule;
}


int run_simulate(const SimulateOptions& options, StagedOutput& output) {
  const nlohmann::json document = read_case_document(options.case_path);
  if (is_component_case(document)) {
    // A component run takes its step from its rubbing object (each run at
    // its own step already) and has no casing to reduce.
    if (options.time_step != "case" || options.casing_modes != 0 || options.selection != "lowest")
      throw UsageError("--time-step, --casing-modes, --selection: only for the paper's case; a "
                       "component case sets its steps in its rubbing object and keeps the lowest "
                       "modes");
    return run_component_simulate(options, parse_component_case(document, options.case_path),
                                  output);
  }
  if (!options.load.source_override.empty())
    throw UsageError("--source: only for a component case; " + options.case_path +
                     " is the paper's case");
  const Case c = parse_case(document, options.case_path);
  const bool full = options.method == "full";
  if (!full && options.method != "cb" && options.method != "ccm" && options.method != "guyan")
    throw UsageError("--method: must be full, cb, ccm or guyan for the paper's case (macneal: "
                     "component cases), got '" + options.method + "'");
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
  std::printf("status: %s\n", s.status.c_str());
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
               s.status.c_str(), stopped_run_remedy(s).c_str(), options.out.c_str());
  return 3;
}

} // namespace rsi

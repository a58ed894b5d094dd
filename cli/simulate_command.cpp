// rsi simulate: one contact run -> history.csv, summary.json.

#include <chrono>
#include <cstdio>
#include <unistd.h>

#include "commands.hpp"
#include "output_files.hpp"
#include "reduced_run.hpp"
#include "reference_run.hpp"
#include "run_outputs.hpp"

namespace rsi {
namespace {

/// Progress on stderr, only when it is a terminal and the run has lasted a second.
std::function<void(double)> terminal_progress() {
  if (!::isatty(STDERR_FILENO)) return {};
  const auto start = std::chrono::steady_clock::now();
  return [start](double fraction) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > 1.0) std::fprintf(stderr, "\r%5.1f%% (%.1f s)", 100.0 * fraction, elapsed);
  };
}

/// One row per history row: t, then every bladed-disk dof (u = T q).
std::string field_csv(const History& history, const Eigen::MatrixXd& field) {
  std::string out = "t";
  for (int i = 0; i < field.cols(); ++i)
    out += ",u_" + std::to_string(i);
  out += "\n";
  char buffer[32];
  for (int r = 0; r < field.rows(); ++r) {
    std::snprintf(buffer, sizeof buffer, "%.17g", history.time[r]);
    out += buffer;
    for (int i = 0; i < field.cols(); ++i) {
      std::snprintf(buffer, sizeof buffer, ",%.17g", field(r, i));
      out += buffer;
    }
    out += "\n";
  }
  return out;
}

} // namespace

int run_simulate(const SimulateOptions& options) {
  const Case c = load_case(options.case_path);
  const bool full = options.method == "full";
  if (!full && options.method != "cb" && options.method != "ccm" && options.method != "guyan")
    throw UsageError("--method: must be full, cb, ccm or guyan, got '" + options.method + "'");
  if (full && options.full_field)
    throw UsageError(
        "--full-field: only for the reduced methods (the full run has every dof already)");
  make_output_directory(options.out, "--out");
  ReducedRunOptions run;
  run.run.force = options.force;
  run.run.progress = terminal_progress();
  run.full_field = options.full_field;
  ReducedRunResult reduced;
  const RunResult result = full
                               ? run_reference(c, run.run)
                               : (reduced = run_reduced(c, options.method, options.modes, run)).run;
  if (run.run.progress) std::fprintf(stderr, "\n");
  write_text_file(options.out + "/history.csv", history_csv(result.history));
  write_text_file(options.out + "/summary.json", summary_json(result.summary));
  if (result.casing_u_at_first_contact.size() > 0)
    write_text_file(
        options.out + "/casing_first_contact.csv",
        casing_snapshot_csv(result.casing_u_at_first_contact, result.casing_v_at_first_contact));
  if (options.full_field)
    write_text_file(options.out + "/field.csv", field_csv(result.history, reduced.field));
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
  std::printf("energy balance error %.3e J (scale %.3e J); W_ext %.6e J, W_contact %.6e J\n",
              s.energy_balance_error, s.energy_scale, s.final_external_work, s.final_contact_work);
  std::printf("blade 1 contact intervals:");
  for (const auto& [a, b] : s.contact_intervals_blade_1)
    std::printf(" [%.4f, %.4f] ms", 1e3 * a, 1e3 * b);
  std::printf("\nwrote %s/history.csv, %s/summary.json\n", options.out.c_str(),
              options.out.c_str());
  return s.completed ? 0 : 3;
}

} // namespace rsi

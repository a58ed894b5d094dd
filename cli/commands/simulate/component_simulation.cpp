// rsi simulate on a component case: the rubbing run of its "rubbing" object
// (campaign/rubbing_run.hpp) -> history.csv, summary.json.

#include <cmath>
#include <cstdio>
#include <string>

#include "component_history_file.hpp"
#include "failure_advice.hpp"
#include "interruption.hpp"
#include "output_files.hpp"
#include "output_sets.hpp"
#include "rubbing_run.hpp"
#include "run_outputs.hpp"
#include "simulate_options.hpp"
#include "staged_output.hpp"
#include "terminal_progress.hpp"
#include "usage_error.hpp"

namespace rsi {

int simulate_component_case(const SimulateOptions& options, const ComponentCase& c,
                            StagedOutput& output) {
  if (options.full_field)
    throw UsageError("--full-field: only for the paper's case (a component case writes the "
                     "response dof of its 'rubbing.response')");
  if (options.method == "full" && options.modes != 0)
    throw UsageError("--modes: only for a reduced method; drop it");
  // On a terminal: loading and the bases as a stage line, then the steps.
  const std::function<void(double)> terminal = terminal_progress(options.method);
  TerminalStage preparing("preparing the run (the component, " + options.method +
                          (options.method == "full" ? " model, omega_max)" : " basis, omega_max)"));
  const RubbingModel model = load_rubbing_model(c, options.load);
  const std::string dir = output.open(options.out, "--out", simulate_output_set());
  const int nc = static_cast<int>(model.contact_nodes().size());
  ComponentHistoryFile history_file(dir + "/history.csv", model.response_name(), nc);
  const ComponentRowSink sink = [&](const HistoryRow& row, double response) {
    history_file.append(row, response);
  };
  RubbingRunOptions run;
  run.method = options.method;
  run.modes = options.modes;
  run.boundary_modes = options.boundary_modes;
  run.casing_modes = options.casing_modes;
  run.force = options.force;
  run.checkpoint = throw_if_interrupted;
  run.progress = [&preparing, &terminal](double fraction) {
    preparing.done();
    if (terminal) terminal(fraction);
  };
  const RubbingRun result = run_rubbing(model, run, sink);
  preparing.done();
  finish_terminal_progress(terminal);
  throw_if_interrupted();
  history_file.commit();
  if (!result.wear.empty())
    write_text_file(dir + "/wear.csv",
                    wear_csv(result.wear, result.wear_n_theta, result.wear_n_axial));
  write_text_file(dir + "/summary.json", summary_json(result.summary));
  const RunSummary& s = result.summary;
  std::printf("%s: method %s%s, %d %s, %d contact nodes, %d of %d steps in %.3f s "
              "(integration %.3f s, basis %.3f s)\n",
              c.case_path.c_str(), s.method.c_str(),
              options.method == "full" ? "" : (" " + std::to_string(options.modes) + " modes").c_str(),
              s.n_dofs, options.method == "full" ? "dofs" : "coordinates", nc, s.steps,
              s.steps_requested, s.wall_seconds, s.integration_seconds, s.basis_seconds);
  std::printf("omega_max %.6e rad/s, critical step %.6e s, step %.6e s (%d a sample, %d samples a "
              "revolution)\n",
              s.omega_max, s.critical_dt, s.dt, result.steps_per_sample,
              model.setup().steps_per_revolution);
  std::printf("status: %s\n", run_status(s).c_str());
  std::printf("max penetration %.3e, min lambda %.3e, max lambda %.3e, max |lambda g| %.3e "
              "(model units)\n",
              s.max_penetration, s.min_lambda, s.max_lambda, s.max_complementarity);
  std::printf("coulomb certificate: max cone violation %.3e, max stick/slip residual %.3e "
              "(scaled), stick/slip transitions %d, contact-steps stick %ld slip %ld\n",
              s.max_cone_violation, s.max_stick_slip_residual, s.stick_slip_transitions,
              s.stick_contact_steps, s.slip_contact_steps);
  std::printf("energy balance error %.3e (scale %.3e); W_contact %.6e, W_damp %.6e\n",
              s.energy_balance_error, s.energy_scale, s.final_contact_work, s.final_damping_work);
  if (s.liner)
    std::printf("liner: W_plastic %.6e, max wear depth %.6e, %d lobes, unmatched work "
                "(bars' work not done by the contact force) %.6e\n",
                s.final_plastic_work, s.max_wear_depth, s.wear_lobes,
                s.liner_unmatched_work);
  output.announce("wrote " + options.out + "/history.csv, " + options.out + "/summary.json" +
                  (s.liner ? ", " + options.out + "/wear.csv" : std::string()) + "\n");
  if (s.completed) return 0;
  // Exit 3 says what to change: the step (above its limit only with
  // --force) or the contact's friction.
  std::fprintf(stderr,
               "rsi: error: numerical failure: the run stopped: %s; %s (--out %s holds "
               "the run up to the stop)\n",
               run_status(s).c_str(),
               s.dt >= s.critical_dt
                   ? "the step is at or above the stability limit (--force): drop --force"
                   : "use a smaller rubbing.step_safety or rubbing.friction_coefficient",
               options.out.c_str());
  return 3;
}

} // namespace rsi

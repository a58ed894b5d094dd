// rsi campaign on a component case: the runs of its rubbing.campaign
// (campaign/rubbing_campaign.hpp: the list, each run, the error norms) ->
// convergence.csv, runs/<name>/{history.csv,summary.json}, rubbing.json and,
// unless --no-report, the report (reports/make_rubbing_report.py).
// Runs one after the other (--jobs 1): their wall times are the cost table.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "campaign_options.hpp"
#include "component_history_file.hpp"
#include "interruption.hpp"
#include "nodal_diameter_map.hpp"
#include "output_files.hpp"
#include "output_sets.hpp"
#include "reduced_basis.hpp"
#include "report_script.hpp"
#include "rubbing_campaign.hpp"
#include "run_outputs.hpp"
#include "stream_text.hpp"
#include "terminal_progress.hpp"
#include "staged_output.hpp"
#include "usage_error.hpp"

namespace rsi {
namespace {

/// The set-up the report reads (rubbing.json).
std::string rubbing_json(const RubbingModel& model) {
  const RubbingSetup& s = model.setup();
  nlohmann::ordered_json j;
  j["case"] = model.component_case().case_path;
  j["component"] = model.component_case().name;
  j["dofs"] = model.component().n_dofs();
  j["mass"] = model.component_case().lumped_mass ? "lumped" : "consistent";
  j["units"] = model.component_case().units;
  j["contact_nodes"] = model.contact_nodes();
  j["gap"] = s.casing ? "flexible" : s.oval_gap ? "oval" : "constant";
  if (s.casing) {
    // The flexible casing (issue 27): its ring and what the reduced runs keep of it.
    j["casing_inner_radius"] = s.casing->inner_radius;
    j["casing_thickness"] = s.casing->thickness;
    j["casing_width"] = s.casing->width;
    j["casing_modes"] = s.casing_modes;
    j["casing_dofs"] = model.problem.structures.at(1).n_dofs();
    if (s.casing_forcing) {
      j["casing_pressure"] = s.casing_forcing->pressure;
      j["casing_nodal_diameters"] = s.casing_forcing->nodal_diameters;
      j["casing_load_duration"] = s.casing_forcing->duration;
    }
  }
  j["gap_value"] = s.gap;
  j["gap_width"] = s.gap_width;
  j["friction_coefficient"] = s.friction_coefficient;
  j["rotation_speed"] = s.rotation_speed;
  j["tip_sliding"] = s.sliding_against_rotation ? "against_rotation" : "with_rotation";
  j["revolutions"] = s.revolutions;
  j["full_revolutions"] = s.full_revolutions;
  j["steps_per_revolution"] = s.steps_per_revolution;
  j["output_every"] = s.output_every;
  j["response"] = model.response_name();
  j["modal_ratio"] = model.component_case().damping.modal_ratio;
  j["rayleigh_alpha"] = model.component_case().damping.rayleigh.alpha;
  j["rayleigh_beta"] = model.component_case().damping.rayleigh.beta;
  return j.dump(2) + "\n";
}

/// Runs one entry into DIR/runs/<name>/ (history streamed, committed at the end).
void run_entry(const RubbingModel& model, RubbingCampaignRun& entry, const std::string& dir,
               StagedOutput& output) {
  output.make(dir);
  ComponentHistoryFile history(dir + "/history.csv", model.response_name(),
                               static_cast<int>(model.contact_nodes().size()));
  const ComponentRowSink sink = [&history](const HistoryRow& row, double response) {
    history.append(row, response);
  };
  const std::function<void(double)> progress =
      terminal_progress(rubbing_campaign_run_name(entry));
  const bool ran = run_rubbing_campaign_entry(model, entry, sink, throw_if_interrupted, progress);
  finish_terminal_progress(progress);
  if (!ran) return; // a refused reduction: nothing written
  throw_if_interrupted();
  history.commit();
  write_text_file(dir + "/summary.json", summary_json(entry.run.summary));
  if (!entry.run.wear.empty())
    write_text_file(dir + "/wear.csv",
                    wear_csv(entry.run.wear, entry.run.wear_n_theta, entry.run.wear_n_axial));
}

/// nodal_diameters.csv and interaction_lines.csv of a bladed disk against
/// the flexible casing (nodal_diameter_map.hpp), nothing for another rotor.
void write_nodal_diameter_map(const RubbingModel& model, const std::string& stage,
                              const std::string& out, StagedOutput& output) {
  const std::optional<NodalDiameterMap> map = system_nodal_diameter_map(model);
  if (!map) return;
  write_text_file(stage + "/nodal_diameters.csv", nodal_diameters_csv(*map));
  write_text_file(stage + "/interaction_lines.csv", system_interaction_lines_csv(map->lines));
  output.announce("wrote " + out + "/nodal_diameters.csv and " + out +
                  "/interaction_lines.csv (" + std::to_string(map->lines.size()) +
                  " interaction lines)\n");
}

} // namespace

int campaign_component_case(const CampaignOptions& options, const ComponentCase& c,
                            StagedOutput& output) {
  if (!c.rubbing || c.rubbing->campaign.empty())
    throw UsageError(c.case_path + ": key 'rubbing.campaign': missing, nothing to run (a "
                                   "component case's campaign lists its reduced runs there)");
  if (options.jobs > 1)
    throw UsageError("--jobs: a component case's campaign runs one run at a time (its wall "
                     "times are the cost table); use --jobs 1");
  if (options.target_e2 > 0.0)
    throw UsageError("--target-e2: only for the paper's case; a component case's convergence.csv "
                     "lists every run's e2");
  const RubbingModel model = load_rubbing_model(c, options.load);
  const RubbingSetup& setup = model.setup();
  const std::string stage = output.open(options.out, "--out", campaign_output_set());
  std::vector<RubbingCampaignRun> runs = rubbing_campaign_runs(setup);
  for (RubbingCampaignRun& r : runs) {
    run_entry(model, r, stage + "/runs/" + rubbing_campaign_run_name(r), output);
    const RunSummary& s = r.run.summary;
    std::printf("%-8s %4d: %s; dt %.4e s (limit %.4e s), %d steps, basis %.2f s, "
                "integration %.3f s\n",
                r.method.c_str(), r.modes, r.error.empty() ? "completed" : r.error.c_str(), s.dt,
                r.run.step_limit, s.steps, s.basis_seconds, s.integration_seconds);
    std::fflush(stdout);
  }
  const RubbingCampaignRun* reference =
      setup.full_revolutions > 0.0 && runs.front().error.empty() ? &runs.front() : nullptr;
  // A liner adds its columns, the flexible casing the gaps' norms (a case
  // with neither keeps its bytes).
  const bool liner = model.problem.casing.liner.has_value();
  const bool flexible = setup.casing.has_value();
  std::ostringstream csv;
  csv.precision(10);
  csv << "method,modes,coordinates,dt,critical_dt,step_limit,steps_per_sample,steps,completed,basis_s,"
         "integration_s,us_per_step,window_revolutions,e2_response,einf_response,e2_lambda,"
         "einf_lambda,stick_slip_transitions,stick_fraction,slip_fraction,max_cone_violation,"
         "max_stick_slip_residual,energy_balance_error,energy_scale,contact_work,damping_work,"
         "first_mode_hz"
      << (liner ? ",plastic_work,max_wear_depth,wear_lobes,e2_wear,einf_wear" : "")
      << (flexible ? ",e2_gap,einf_gap,casing_basis,external_work" : "") << '\n';
  for (const RubbingCampaignRun& r : runs) {
    const RunSummary& s = r.run.summary;
    const RubbingErrorNorms e =
        reference && r.error.empty()
            ? rubbing_error_norms(r, *reference, setup.full_revolutions == setup.revolutions)
            : RubbingErrorNorms{};
    const double contact_steps = static_cast<double>(s.steps) * model.contact_nodes().size();
    csv << r.method << ',' << r.modes << ',' << s.n_dofs << ',' << s.dt << ',' << s.critical_dt
        << ',' << r.run.step_limit << ',' << r.run.steps_per_sample << ',' << s.steps << ',' << (s.completed ? 1 : 0) << ','
        << s.basis_seconds << ',' << s.integration_seconds << ','
        << 1e6 * s.integration_seconds / std::max(s.steps, 1) << ','
        << (reference ? setup.full_revolutions : 0.0) << ',' << e.e2_response << ','
        << e.einf_response << ',' << e.e2_lambda << ',' << e.einf_lambda << ','
        << s.stick_slip_transitions << ',' << s.stick_contact_steps / contact_steps << ','
        << s.slip_contact_steps / contact_steps << ',' << s.max_cone_violation << ','
        << s.max_stick_slip_residual << ',' << s.energy_balance_error << ',' << s.energy_scale
        << ',' << s.final_contact_work << ',' << s.final_damping_work << ','
        << r.run.first_mode_hz;
    if (liner)
      csv << ',' << s.final_plastic_work << ',' << s.max_wear_depth << ',' << s.wear_lobes << ','
          << e.e2_wear << ',' << e.einf_wear;
    if (flexible)
      csv << ',' << e.e2_gap << ',' << e.einf_gap << ',' << s.casing_basis << ','
          << s.final_external_work;
    csv << '\n';
    std::printf("%-8s %4d  e2 response %.4e  einf %.4e  e2 lambda %.4e  einf %.4e\n",
                r.method.c_str(), r.modes, e.e2_response, e.einf_response, e.e2_lambda,
                e.einf_lambda);
    if (flexible)
      std::printf("%-8s %4d  e2 gaps %.4e  einf %.4e  (casing %s)\n", r.method.c_str(), r.modes,
                  e.e2_gap, e.einf_gap, s.casing_basis.c_str());
    if (liner)
      std::printf("%-8s %4d  wear: max depth %.4e, %d lobes, W_plastic %.4e, e2 %.4e, einf %.4e\n",
                  r.method.c_str(), r.modes, s.max_wear_depth, s.wear_lobes, s.final_plastic_work,
                  e.e2_wear, e.einf_wear);
  }
  write_text_file(stage + "/convergence.csv", stream_text(csv));
  write_text_file(stage + "/rubbing.json", rubbing_json(model));
  if (flexible) write_nodal_diameter_map(model, stage, options.out, output);
  output.announce("wrote " + options.out + "/convergence.csv and " + options.out +
                  "/runs/*/{history.csv,summary.json}\n");
  const bool all_ok = std::all_of(runs.begin(), runs.end(),
                                  [](const RubbingCampaignRun& r) { return r.error.empty(); });
  if (options.report) {
    if (!write_report("make_rubbing_report.py", stage, options.out)) return 1;
    output.announce("report: " + options.out + "/report.md\n");
  }
  if (all_ok) return 0;
  // Exit 3: one error line, each failed run on its own line.
  long n_failed = 0;
  for (const RubbingCampaignRun& r : runs)
    if (!r.error.empty()) {
      std::fprintf(stderr, "rsi: campaign run %s failed: %s\n", rubbing_campaign_run_name(r).c_str(),
                   r.error.c_str());
      ++n_failed;
    }
  std::fprintf(stderr,
               "rsi: error: numerical failure: %ld of %zu campaign runs failed (listed above: "
               "a refused reduction names its modes; a stopped run needs a smaller "
               "rubbing.step_safety or rubbing.friction_coefficient); the others are in --out "
               "%s\n",
               n_failed, runs.size(), options.out.c_str());
  return 3;
}

} // namespace rsi

#include "output_sets.hpp"

namespace rsi {

OutputSet modes_output_set() {
  return {"modes.csv"};
}

OutputSet campbell_output_set() {
  return {"campbell.csv", "crossings.csv"};
}

OutputSet export_output_set() {
  // One folder per component, named by the case (bladed-disk, casing, or
  // the component's name): the four files in any folder, the folder
  // removed when it is left empty.
  return {"*/K.mtx", "*/M.mtx", "*/dofs.csv", "*/nodes.csv"};
}

OutputSet reduce_output_set() {
  return {"K.mtx", "M.mtx", "T.mtx", "basis.json"};
}

OutputSet simulate_output_set() {
  return {"history.csv", "field.csv", "casing_first_contact.csv", "summary.json", "wear.csv"};
}

OutputSet campaign_output_set() {
  return {"runs", "modes-bladed-disk.csv", "rubbing.json", "convergence.csv", "nodal_diameters.csv",
          "interaction_lines.csv", "nodal_diameter_map.png",
          // reports/make_campaign_report.py
          "fig3_nodal_diameters.png", "gap_*.png", "error_vs_modes.png", "relative_time.png",
          "kkt_energy.png", "energy.png", "critical_dt.png",
          // reports/make_rubbing_report.py
          "response.png", "response_last.png", "spectrum.png", "contact_energy.png",
          "error_vs_cost.png", "report.md"};
}

OutputSet sweep_output_set() {
  return {"sweep.csv", "interaction_lines.csv", "campbell.csv", "nodal_diameters.csv",
          "sweep_summary.json",
          // reports/make_sweep_report.py, make_component_sweep_report.py,
          // make_system_sweep_report.py
          "sweep_map.png", "sweep_campbell.png", "nodal_diameter_map.png", "sweep_report.md"};
}

OutputSet modal_campaign_output_set() {
  return {"modal_convergence.csv", "modal_errors.csv",   "modal_convergence.png",
          "modal_errors.png",      "modal_summary.json", "modal_report.md"};
}

} // namespace rsi

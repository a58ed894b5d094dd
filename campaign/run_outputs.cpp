#include "run_outputs.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "failure_advice.hpp"

namespace rsi {
namespace {

void append(std::string& out, double x) {
  append_csv_number(out, x);
}

} // namespace

// std::to_chars with chars_format::general and precision 17 is specified
// as printf's "%.17g" (C++17 [charconv.to.chars]): the same bytes, without
// printf's locale and format parsing (a history row is 49 numbers; at
// output_every 1 snprintf was a third of a reduced run's step).
void append_csv_number(std::string& out, double x) {
  char buffer[32];
  const std::to_chars_result r =
      std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, 17);
  out.append(buffer, r.ptr);
}

std::string history_csv_header(int n_blades, int n_tangents) {
  if (n_tangents < 0 || n_tangents > 2)
    throw std::invalid_argument("history_csv_header: n_tangents = " + std::to_string(n_tangents) +
                                ", allowed 0, 1 or 2");
  std::string out = "t";
  for (int k = 1; k <= n_blades; ++k)
    out += ",gap_" + std::to_string(k);
  for (int k = 1; k <= n_blades; ++k)
    out += ",lambda_" + std::to_string(k);
  for (int k = 1; k <= n_blades; ++k) {
    if (n_tangents == 1) out += ",lambda_t_" + std::to_string(k);
    if (n_tangents == 2)
      out += ",lambda_t1_" + std::to_string(k) + ",lambda_t2_" + std::to_string(k);
  }
  out += ",energy,external_work,contact_work,damping_work\n";
  return out;
}

void append_history_csv_row(std::string& out, const HistoryRow& row) {
  append(out, row.time);
  for (Eigen::Index k = 0; k < row.gap.size(); ++k)
    out += ',', append(out, row.gap(k));
  for (Eigen::Index k = 0; k < row.lambda.size(); ++k)
    out += ',', append(out, row.lambda(k));
  if (row.lambda_tangential)
    for (Eigen::Index k = 0; k < row.lambda_tangential->size(); ++k)
      out += ',', append(out, (*row.lambda_tangential)(k));
  for (double x : {row.energy, row.external_work, row.contact_work, row.damping_work})
    out += ',', append(out, x);
  if (row.plastic_work) out += ',', append(out, *row.plastic_work);
  out += '\n';
}

int history_csv_tangents(const HistoryRow& row) {
  if (!row.lambda_tangential || row.gap.size() == 0) return 0;
  return static_cast<int>(row.lambda_tangential->size() / row.gap.size());
}

std::string history_csv(const History& h) {
  const bool tangential = !h.lambda_tangential.empty();
  if (tangential && static_cast<int>(h.lambda_tangential.size()) != h.n_rows())
    throw std::invalid_argument("history_csv: lambda_tangential has " +
                                std::to_string(h.lambda_tangential.size()) + " rows, allowed 0 or " +
                                std::to_string(h.n_rows()));
  std::string out;
  for (int i = 0; i < h.n_rows(); ++i) {
    const HistoryRow row{h.time[i],
                         h.gap[i],
                         h.lambda[i],
                         h.energy[i],
                         h.external_work[i],
                         h.contact_work[i],
                         h.damping_work[i],
                         tangential ? &h.lambda_tangential[i] : nullptr};
    if (i == 0)
      out = history_csv_header(static_cast<int>(h.gap.front().size()), history_csv_tangents(row));
    append_history_csv_row(out, row);
  }
  if (h.n_rows() == 0) out = history_csv_header(0);
  return out;
}

std::string casing_snapshot_csv(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  std::string out = "node,theta,u,v\n";
  for (int j = 0; j < u.size(); ++j) {
    out += std::to_string(j) + ",";
    append(out, 2.0 * M_PI * j / u.size());
    out += ',', append(out, u(j));
    out += ',', append(out, v(j));
    out += '\n';
  }
  return out;
}

std::string summary_json(const RunSummary& s) {
  nlohmann::ordered_json j;
  j["method"] = s.method;
  j["status"] = run_status(s);
  j["completed"] = s.completed;
  j["dofs"] = s.n_dofs;
  j["steps_requested"] = s.steps_requested;
  j["steps"] = s.steps;
  j["dt"] = s.dt;
  j["omega_max"] = s.omega_max;
  j["critical_dt"] = s.critical_dt;
  j["bladed_disk_critical_dt"] = s.bladed_disk_critical_dt;
  j["flops_per_step"] = s.flops_per_step;
  j["casing_flops_per_step"] = s.casing_flops_per_step;
  j["basis_seconds"] = s.basis_seconds;
  j["casing_basis"] = s.casing_basis;
  j["time_step_rule"] = s.time_step_rule;
  if (s.step_safety > 0.0) j["step_safety"] = s.step_safety;
  if (!s.selection.empty()) {
    j["selection"] = s.selection;
    j["modes_kept"] = s.modes_kept;
  }
  j["wall_seconds"] = s.wall_seconds;
  j["integration_seconds"] = s.integration_seconds;
  j["output_seconds"] = s.output_seconds;
  j["max_penetration"] = s.max_penetration;
  j["min_lambda"] = s.min_lambda;
  j["max_lambda"] = s.max_lambda;
  j["max_complementarity"] = s.max_complementarity;
  j["max_friction_residual"] = s.max_friction_residual;
  j["sliding_reversals"] = s.sliding_reversals;
  j["max_cone_violation"] = s.max_cone_violation;
  j["max_stick_slip_residual"] = s.max_stick_slip_residual;
  j["stick_slip_transitions"] = s.stick_slip_transitions;
  j["stick_contact_steps"] = s.stick_contact_steps;
  j["slip_contact_steps"] = s.slip_contact_steps;
  j["max_active_contacts"] = s.max_active;
  j["first_contact_step"] = s.first_contact_step;
  j["initial_energy"] = s.initial_energy;
  j["max_energy"] = s.max_energy;
  j["final_external_work"] = s.final_external_work;
  j["final_contact_work"] = s.final_contact_work;
  j["damping_work"] = s.final_damping_work;
  j["energy_balance_error"] = s.energy_balance_error;
  j["energy_scale"] = s.energy_scale;
  j["contact_intervals_blade_1"] = nlohmann::ordered_json::array();
  for (const auto& [first, last] : s.contact_intervals_blade_1)
    j["contact_intervals_blade_1"].push_back({first, last});
  if (s.liner) {
    nlohmann::ordered_json l;
    l["plastic_work"] = s.final_plastic_work;
    l["unmatched_work"] = s.liner_unmatched_work;
    l["cell_area"] = s.liner_cell_area;
    l["bar_stiffness"] = s.liner_bar_stiffness;
    l["max_wear_depth"] = s.max_wear_depth;
    l["wear_lobes"] = s.wear_lobes;
    j["liner"] = l;
  }
  return j.dump(2) + "\n";
}

std::string wear_csv(const std::vector<double>& wear, int n_theta, int n_axial) {
  std::string out = "angle,row,depth\n";
  const double pitch = 2.0 * M_PI / n_theta;
  char line[96];
  for (int j = 0; j < n_axial; ++j)
    for (int i = 0; i < n_theta; ++i) {
      std::snprintf(line, sizeof line, "%.17g,%d,%.17g\n", (i + 0.5) * pitch, j,
                    wear[static_cast<size_t>(j * n_theta + i)]);
      out += line;
    }
  return out;
}

} // namespace rsi

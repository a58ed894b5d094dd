#pragma once
// history.csv and summary.json of a contact run (SPEC §5).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "history.hpp"

namespace rsi {

/// t,gap_1..gap_N,lambda_1..lambda_N,energy,external_work,contact_work,damping_work; 17
/// significant digits. Coulomb runs (rows with lambda_tangential) have the
/// tangential multipliers after the lambda columns: lambda_t_1..lambda_t_N
/// (one tangent, 2D) or lambda_t1_1,lambda_t2_1,..,lambda_t1_N,lambda_t2_N
/// (two tangents, 3D); sliding_sign runs have none (their bytes unchanged).
/// Made of history_csv_header and one append_history_csv_row per row, the
/// functions a streamed history.csv is written with (the same bytes).
std::string history_csv(const History& history);

/// The header line of history.csv for `n_blades` blades (contacts), with
/// its newline; n_tangents: 0 (no tangential columns), 1 or 2 per contact.
/// Throws std::invalid_argument for another n_tangents.
std::string history_csv_header(int n_blades, int n_tangents = 0);

/// The n_tangents of history_csv_header for a row: 0 without
/// lambda_tangential, else its size / the number of contacts.
int history_csv_tangents(const HistoryRow& row);

/// Appends one line of history.csv (17 significant digits, newline) to `out`.
void append_history_csv_row(std::string& out, const HistoryRow& row);

/// Appends x with 17 significant digits (the bytes of printf's "%.17g").
void append_csv_number(std::string& out, double x);

/// node,theta,u,v: the casing at one instant (node j at theta = 2 pi j / n).
std::string casing_snapshot_csv(const Eigen::VectorXd& u, const Eigen::VectorXd& v);

/// The summary as pretty-printed JSON.
std::string summary_json(const RunSummary& summary);

/// wear.csv of a run with an abradable liner: angle,row,depth per cell (the
/// centre angle of its sector in the casing frame [rad], its axial row from
/// 0, its wear depth), rows in order, sectors in order within a row.
/// `wear`: n_theta x n_axial depths in cell order (row n_theta + sector).
std::string wear_csv(const std::vector<double>& wear, int n_theta, int n_axial);

} // namespace rsi

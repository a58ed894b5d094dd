#pragma once
// history.csv and summary.json of a contact run (SPEC §5).

#include <string>

#include <Eigen/Core>

#include "history.hpp"

namespace rsi {

/// t,gap_1..gap_N,lambda_1..lambda_N,energy,external_work,contact_work,damping_work; 17
/// significant digits.
/// Made of history_csv_header and one append_history_csv_row per row, the
/// functions a streamed history.csv is written with (the same bytes).
std::string history_csv(const History& history);

/// The header line of history.csv for `n_blades` blades, with its newline.
std::string history_csv_header(int n_blades);

/// Appends one line of history.csv (17 significant digits, newline) to `out`.
void append_history_csv_row(std::string& out, const HistoryRow& row);

/// node,theta,u,v: the casing at one instant (node j at theta = 2 pi j / n).
std::string casing_snapshot_csv(const Eigen::VectorXd& u, const Eigen::VectorXd& v);

/// The summary as pretty-printed JSON.
std::string summary_json(const RunSummary& summary);

} // namespace rsi

#pragma once
// history.csv and summary.json of a contact run (SPEC §5).

#include <string>

#include <Eigen/Core>

#include "history.hpp"

namespace rsi {

/// t,gap_1..gap_N,lambda_1..lambda_N,energy,external_work,contact_work; 17 significant digits.
std::string history_csv(const History& history);

/// node,theta,u,v: the casing at one instant (node j at theta = 2 pi j / n).
std::string casing_snapshot_csv(const Eigen::VectorXd& u, const Eigen::VectorXd& v);

/// The summary as pretty-printed JSON.
std::string summary_json(const RunSummary& summary);

} // namespace rsi

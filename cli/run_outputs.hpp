#pragma once
// history.csv and summary.json of a contact run (SPEC §5).

#include <string>

#include "history.hpp"

namespace rsi {

/// t,gap_1..gap_N,lambda_1..lambda_N,energy,external_work,contact_work; 17 significant digits.
std::string history_csv(const History& history);

/// The summary as pretty-printed JSON.
std::string summary_json(const RunSummary& summary);

} // namespace rsi

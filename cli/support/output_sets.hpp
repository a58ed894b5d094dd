#pragma once
// What each command owns in its --out (issue 13, class 4): the names a
// command's run replaces as one set (StagedOutput::publish). An entry is a
// path relative to --out whose components may hold `*` (fnmatch(3), never
// matching a name that starts with a dot); an entry that names a folder
// (`runs`) owns the folder whole. Anything in --out no entry matches (a
// user's notes) is never touched.
//
// Order matters: a new set is moved in entry by entry in this order and an
// old one moved out in the reverse order, so each list puts the data first
// and the files that describe a finished run (summary.json,
// convergence.csv, report.md) last. A run killed half-way through the
// replacement then leaves data without its description, never a
// description of data that is not there.

#include <string>
#include <vector>

namespace rsi {

using OutputSet = std::vector<std::string>;

OutputSet modes_output_set();
OutputSet campbell_output_set(); ///< rsi modes --speeds
OutputSet export_output_set();
OutputSet reduce_output_set();
OutputSet simulate_output_set();
/// The paper's campaign and a component case's (rubbing) campaign, with
/// the figures of either report script.
OutputSet campaign_output_set();
OutputSet modal_campaign_output_set();
OutputSet sweep_output_set();

} // namespace rsi

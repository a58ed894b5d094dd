#pragma once
// The option checks and option groups several commands share.
//
// The validators run in CLI11 on the text of a value, before its
// conversion, so a bad value gets one message naming the option (CLI11
// prefixes its name) and what is allowed, instead of CLI11's bare "Could
// not convert".

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "case_file.hpp"
#include "component_case.hpp"

namespace rsi {

/// An integer in [lo, hi]; `allowed` describes the range in words.
CLI::Validator integer_in(long lo, long hi, const std::string& allowed);

/// A finite number above `lo`.
CLI::Validator number_above(double lo, const std::string& allowed);

/// A finite number strictly between `lo` and `hi`.
CLI::Validator number_between(double lo, double hi, const std::string& allowed);

/// One of `names`.
CLI::Validator one_of(const std::vector<std::string>& names);

/// A path that must not be empty (`--out ""` would put files at the root).
CLI::Validator nonempty_path();

/// The case file argument: an existing file, not a directory (load_case
/// reports a file it cannot read, and everything about its content).
CLI::Validator case_file();

/// --source and --ccx-cache of the commands that take a component case.
void add_component_options(CLI::App& command, ComponentLoadOptions& load);

/// The range of --modes in words (simulate, reduce, sweep).
extern const char* const modes_allowed;

/// --time-step of simulate and sweep: "case", "own" or a step in seconds
/// (> 0, finite); UsageError otherwise.
StepRule parse_step_option(const std::string& text, double safety);

} // namespace rsi

#pragma once
// The one place a command learns which kind of case file it was given
// (SPEC §9: the paper's 2D bladed disk and flexible casing, or a 3D
// component on a rigid casing). visit_case reads the file and calls the
// command's visitor with the case of its kind, a Case or a ComponentCase:
// the command holds one overload per kind and no branch on the kind, and a
// new kind is added here and in the commands' overload sets, where the
// compiler asks for it.

#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "case_file.hpp"
#include "component_case.hpp"
#include "usage_error.hpp"

namespace rsi {

/// `visit(c)` with c the case read from `path` (parse_case or
/// parse_component_case, whichever its keys say). --source
/// (load.source_override) names a deck, which only a component case reads:
/// UsageError for the paper's case, before it is parsed.
template <class Visitor>
auto visit_case(const std::string& path, const ComponentLoadOptions& load, Visitor&& visit)
    -> decltype(visit(std::declval<const Case&>())) {
  const nlohmann::json document = read_case_document(path);
  if (is_component_case(document)) return visit(parse_component_case(document, path));
  if (!load.source_override.empty())
    throw UsageError("--source: only for a component case; " + path + " is the paper's case");
  return visit(parse_case(document, path));
}

} // namespace rsi

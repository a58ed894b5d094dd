#pragma once
// The component a command works on, from either kind of case file: the
// paper's case (its bladed disk or casing, chosen by --part) or a component
// case (SPEC §8: a CalculiX deck or a Matrix Market folder).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "case_file.hpp"
#include "component.hpp"
#include "component_case.hpp"

namespace rsi {

struct ComponentInput {
  Component component;
  std::string case_source;  ///< the case file, for messages
  /// Nodal diameter of a mode shape, for parts with a cyclic structure.
  std::function<std::optional<int>(const Eigen::VectorXd&)> diameter;
  double case_time_step = 0.0;          ///< the paper's case only (0 otherwise)
  std::optional<ComponentCase> component_case; ///< set for a component case
  double speed = 0.0;          ///< Omega [rad/s] of the component's K(Omega)
  Eigen::VectorXd deflection;  ///< its static centrifugal deflection (empty at rest)
};

/// `part`: "bladed-disk" or "casing" for the paper's case; for a component
/// case empty or the component's name. `speed` != 0: the component case's
/// component at that rotation speed (rotating_component.hpp; `speed_option`
/// names it in the message refusing the paper's case). Throws CaseError,
/// UsageError or ImportError (exit 2).
ComponentInput load_component_input(const std::string& case_path, const std::string& part,
                                    const ComponentLoadOptions& load, double speed = 0.0,
                                    const std::string& speed_option = "--speed");

/// Every structure of the case, in the order of its problem (problem.hpp):
/// the paper's bladed disk and casing, or the component. Throws as
/// load_component_input.
std::vector<Component> load_case_structures(const std::string& case_path,
                                            const ComponentLoadOptions& load);

/// The bladed disk ("bladed-disk" or empty) or the casing of the paper's case.
ComponentInput paper_part_input(const Case& c, const std::string& part);

/// Bytes of the process's peak resident memory (getrusage).
long long peak_memory_bytes();

} // namespace rsi

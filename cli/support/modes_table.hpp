#pragma once
// modes.csv of one part: its lowest modes, each with its nodal diameter
// where the part has a cyclic structure (index,frequency_hz,nodal_diameter,
// uncertainty_hz,digits,rigid_body). Written by rsi modes, and by rsi
// campaign for the bladed disk's lowest families (paper Fig. 3).

#include <optional>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "component_input.hpp"
#include "modal_analysis.hpp"

namespace rsi {

struct ModesTable {
  Modes modes;
  std::vector<std::optional<int>> diameters; ///< empty where a part has no cyclic structure
  std::string csv;
  int n_dofs = 0;
};

/// The lowest `count` modes of `input`'s component. Throws UsageError
/// naming --count unless 1 <= count <= its dofs.
ModesTable modes_table(const ComponentInput& input, int count);

/// The same for a part of the paper's case ("bladed-disk" or "casing").
ModesTable modes_table(const Case& c, const std::string& part, int count);

} // namespace rsi

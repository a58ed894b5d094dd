#pragma once
// The reduction of the bladed disk by name, with the 44 tip dofs (u, v of
// every tip, in the tip polar frame) as the boundary (SPEC §3).

#include <string>

#include "bladed_disk.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// method: "cb" (modes = eta), "ccm" (modes = psi), "guyan" (modes = 0) or
/// "macneal" (modes = psi >= 1).
/// Throws ReductionError for an unknown method or a mode count out of range.
ReducedBasis reduce_bladed_disk(const BladedDisk& bladed_disk, const std::string& method,
                                int modes);

} // namespace rsi

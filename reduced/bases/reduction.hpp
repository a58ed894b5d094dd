#pragma once
// A reduction by name (SPEC §3, §8) of any component: the boundary dofs
// (the contact dofs; the 44 tip u, v of the paper's bladed disk) are kept
// as physical coordinates.

#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "bladed_disk.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// method: "cb" (modes = eta), "ccm" (modes = psi), "guyan" (modes = 0) or
/// "macneal" (modes = psi >= 1).
/// Throws ReductionError for an unknown method or a mode count out of range.
ReducedBasis reduce(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, const std::vector<int>& boundary,
                    const std::string& method, int modes);

/// reduce() of the bladed disk with its tip boundary.
ReducedBasis reduce_bladed_disk(const BladedDisk& bladed_disk, const std::string& method,
                                int modes);

} // namespace rsi

#pragma once
// A reduction by name (SPEC §3, §8) of any component: the boundary dofs
// (the contact dofs; the 44 tip u, v of the paper's bladed disk) are kept
// as physical coordinates.

#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "bladed_disk.hpp"
#include "component.hpp"
#include "mode_selection.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// method: "cb" (modes = eta), "ccm" (modes = psi), "guyan" (modes = 0) or
/// "macneal" (modes = psi >= 1).
/// Throws ReductionError for an unknown method or a mode count out of range.
ReducedBasis reduce(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, const std::vector<int>& boundary,
                    const std::string& method, int modes);

/// reduce(), and "cc" (characteristic_constraint.hpp: modes = eta,
/// boundary_modes = n_c): for the component integrator, which reads u_B
/// through a basis's boundary_shapes. std::invalid_argument for
/// boundary_modes != 0 with another method.
ReducedBasis reduce(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, const std::vector<int>& boundary,
                    const std::string& method, int modes, int boundary_modes);

/// reduce() with cc of component c's K, M and boundary; a component with
/// cyclic_bases builds cb, cc and guyan by its turns (CyclicBoundary), ccm
/// and macneal from the turned constraint modes (turned_residual_flexibility;
/// with many modes, few_modes dense, as reduce()). Throws ReductionError as reduce() and
/// cyclic_boundary().
ReducedBasis reduce(const Component& c, const std::string& method, int modes, int boundary_modes);

/// reduce() of the bladed disk with its tip boundary.
ReducedBasis reduce_bladed_disk(const BladedDisk& bladed_disk, const std::string& method,
                                int modes);

/// The same with the modes chosen by a strategy (mode_selection.hpp) out of
/// a pool of the lowest candidate_pool_size(...) modes; `modes` is the count
/// asked for, the basis's n_modes the count kept (families, forced and
/// participation keep whole pairs or families and round down). Records the
/// strategy, the count asked, the pool, and the kept modes' indices, nodal
/// diameters and (participation) measures in the basis. `lowest` gives the
/// count-based basis bit for bit. cb and ccm take every strategy; guyan
/// (modes = 0) and macneal only `lowest` (ReductionError otherwise).
/// Throws ReductionError as reduce(), and for a context that does not
/// describe the disk (check_context) or a spectrum that is not cyclic
/// (cyclic_units).
ReducedBasis reduce_bladed_disk(const BladedDisk& bladed_disk, const std::string& method, int modes,
                                ModeSelection selection, const SelectionContext& context);

} // namespace rsi

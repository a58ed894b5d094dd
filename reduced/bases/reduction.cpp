#include "reduction.hpp"

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "characteristic_constraint.hpp"
#include "craig_bampton.hpp"
#include "craig_chang_martinez.hpp"
#include "guyan.hpp"
#include "macneal.hpp"
#include "participation.hpp"

namespace rsi {

ReducedBasis reduce(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, const std::vector<int>& boundary,
                    const std::string& method, int modes) {
  const Partition p = make_partition(static_cast<int>(stiffness.rows()), boundary);
  if (method == "cb") return craig_bampton(stiffness, mass, p, modes);
  if (method == "ccm") return craig_chang_martinez(stiffness, mass, p, modes);
  if (method == "macneal") return macneal(stiffness, mass, p, modes);
  if (method == "guyan") {
    if (modes != 0)
      throw ReductionError("Guyan reduction keeps no modes (0), got " + std::to_string(modes),
                           failed_input(FailedInput::mode_count));
    return guyan(stiffness, mass, p);
  }
  throw ReductionError("must be full, cb, ccm, guyan or macneal, got '" + method + "'",
                       failed_input(FailedInput::method));
}

ReducedBasis reduce(const Eigen::SparseMatrix<double>& stiffness,
                    const Eigen::SparseMatrix<double>& mass, const std::vector<int>& boundary,
                    const std::string& method, int modes, int boundary_modes) {
  if (method == "cc")
    return characteristic_constraint(stiffness, mass,
                                     make_partition(static_cast<int>(stiffness.rows()), boundary),
                                     modes, boundary_modes);
  if (boundary_modes != 0)
    throw std::invalid_argument("reduce: boundary_modes = " + std::to_string(boundary_modes) +
                                " only for method cc, got '" + method + "'");
  return reduce(stiffness, mass, boundary, method, modes);
}

ReducedBasis reduce(const Component& c, const std::string& method, int modes, int boundary_modes) {
  // Counts out of range and other methods: refused or built as without the turns.
  const bool turned =
      method == "cc" ||
      ((method == "cb" || method == "ccm" || method == "macneal") && boundary_modes == 0) ||
      (method == "guyan" && modes == 0 && boundary_modes == 0);
  if (c.cyclic_bases == 0 || !turned)
    return reduce(c.stiffness, c.mass, c.boundary, method, modes, boundary_modes);
  const Partition p = make_partition(c.n_dofs(), c.boundary);
  const CyclicBoundary cyclic = cyclic_boundary(c, c.cyclic_bases, p);
  if (method == "cc")
    return characteristic_constraint(c.stiffness, c.mass, p, modes, boundary_modes, &cyclic);
  if (method == "cb") return craig_bampton(c.stiffness, c.mass, p, modes, &cyclic);
  if (method == "ccm") return craig_chang_martinez(c.stiffness, c.mass, p, modes, &cyclic);
  if (method == "macneal") return macneal(c.stiffness, c.mass, p, modes, &cyclic);
  return guyan(c.stiffness, c.mass, p, &cyclic);
}

ReducedBasis reduce_bladed_disk(const BladedDisk& bd, const std::string& method, int modes) {
  return reduce(bd.stiffness, bd.mass, bd.boundary, method, modes);
}

namespace {

/// The selection's record in a built basis: the strategy, the count asked
/// and each kept mode's nodal diameter and measure (`candidates` indexed as
/// basis.mode_index).
void record_selection(ModeSelection selection, int modes, const Candidates& candidates,
                      ReducedBasis& basis) {
  basis.selection = to_string(selection);
  basis.requested_modes = modes;
  basis.mode_nodal_diameter.clear();
  for (int i : basis.mode_index)
    basis.mode_nodal_diameter.push_back(candidates.nodal_diameter[i]);
  if (candidates.participation.size() > 0)
    basis.mode_participation = take_entries(candidates.participation, basis.mode_index);
}

ReducedBasis selected_craig_bampton(const BladedDisk& bd, const Partition& p, int modes,
                                    ModeSelection selection, const SelectionContext& context,
                                    std::chrono::steady_clock::time_point start) {
  check_fixed_interface_count(p, modes);
  const int pool_size = candidate_pool_size(selection, modes, p.n_interior(), context.n_sectors);
  const FixedInterfacePool pool = fixed_interface_pool(bd.stiffness, bd.mass, p, pool_size);
  Candidates candidates;
  candidates.omega_squared = pool.modes.omega_squared;
  candidates.nodal_diameter =
      nodal_diameters(place_rows(p.n(), p.interior, pool.modes.shapes), context);
  if (selection == ModeSelection::participation)
    candidates.participation = craig_bampton_participation(
        bd.mass, p, pool.constraint, pool.modes.shapes, pool.modes.omega_squared);
  const std::vector<int> kept = select_modes(selection, modes, candidates, context);
  ReducedBasis basis = craig_bampton(bd.stiffness, bd.mass, p, pool, kept, start);
  record_selection(selection, modes, candidates, basis);
  return basis;
}

ReducedBasis selected_craig_chang_martinez(const BladedDisk& bd, const Partition& p, int modes,
                                           ModeSelection selection, const SelectionContext& context,
                                           std::chrono::steady_clock::time_point start) {
  check_free_interface_count(p, modes);
  const int pool_size =
      candidate_pool_size(selection, modes, p.n() - p.n_boundary(), context.n_sectors);
  const FreeInterfacePool pool =
      free_interface_pool(bd.stiffness, bd.mass, p, pool_size, "Craig-Chang-Martinez");
  const Eigen::MatrixXd shapes = pool.modes.shapes.leftCols(pool_size);
  Candidates candidates;
  candidates.omega_squared = pool.modes.omega_squared.head(pool_size);
  candidates.nodal_diameter = nodal_diameters(shapes, context);
  if (selection == ModeSelection::participation)
    candidates.participation =
        craig_chang_martinez_participation(p, shapes, candidates.omega_squared);
  const std::vector<int> kept = select_modes(selection, modes, candidates, context);
  ReducedBasis basis = craig_chang_martinez(bd.stiffness, bd.mass, p, pool, kept, start);
  record_selection(selection, modes, candidates, basis);
  return basis;
}

} // namespace

ReducedBasis reduce_bladed_disk(const BladedDisk& bd, const std::string& method, int modes,
                                ModeSelection selection, const SelectionContext& context) {
  const auto start = std::chrono::steady_clock::now();
  check_context(context, bd.n_dofs());
  if (method != "cb" && method != "ccm") {
    if (selection != ModeSelection::lowest && method != "guyan")
      throw ReductionError("mode selection: " + to_string(selection) +
                           " applies to cb and ccm (and guyan, which keeps no mode), not '" +
                           method + "'");
    ReducedBasis basis = reduce_bladed_disk(bd, method, modes);
    basis.selection = to_string(selection);
    // MacNeal's modal columns phi_i - R(:, B) R_B^-1 phi_iB have phi_i's
    // nodal diameter: R(:, B) R_B^-1 commutes with the rotation by a sector
    // (K, M and the boundary set are cyclic).
    if (basis.n_modes > 0)
      basis.mode_nodal_diameter =
          nodal_diameters(basis.transformation.rightCols(basis.n_modes), context);
    return basis;
  }
  const Partition p = make_partition(bd.n_dofs(), bd.boundary);
  if (method == "cb") return selected_craig_bampton(bd, p, modes, selection, context, start);
  return selected_craig_chang_martinez(bd, p, modes, selection, context, start);
}

} // namespace rsi

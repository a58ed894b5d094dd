#include "macneal.hpp"

#include <chrono>
#include <numeric>
#include <string>
#include <utility>

#include "craig_chang_martinez.hpp"
#include "guyan.hpp"
#include "turned_residual_flexibility.hpp"

namespace rsi {

namespace {

void check_macneal_count(const Partition& p, int psi) {
  const int n = p.n();
  const int nb = p.n_boundary();
  if (psi < 1 || psi > n - nb)
    throw ReductionError("MacNeal takes 1 to " + std::to_string(n - nb) +
                             " free-interface modes (dofs minus boundary dofs; the boundary is "
                             "massless), got " +
                             std::to_string(psi),
                         failed_input(FailedInput::mode_count));
}

} // namespace

ReducedBasis macneal(const Eigen::SparseMatrix<double>& stiffness,
                     const Eigen::SparseMatrix<double>& mass, const Partition& p,
                     const FreeInterfacePool& pool, const std::vector<int>& kept,
                     std::chrono::steady_clock::time_point start) {
  const int psi = static_cast<int>(kept.size());
  check_macneal_count(p, psi);
  const int nb = p.n_boundary();
  ReducedBasis basis;
  basis.method = "macneal";
  basis.n_modes = psi;
  basis.requested_modes = psi;
  basis.candidate_modes = pool.count;
  basis.mode_index = kept;
  ResidualFlexibilityTransformation t =
      residual_flexibility_transformation(p, pool, kept, "MacNeal");
  basis.transformation = std::move(t.transformation);
  basis.cond_rb = t.cond_rb;
  basis.mode_omega = std::move(t.mode_omega);
  // K^ = T^T K T as CCM; finish_basis also forms CCM's T^T M T, which
  // MacNeal replaces: the kept modes' unit mass, the residual mass dropped.
  finish_basis(stiffness, mass, nb, 0, start, basis);
  basis.mass.setZero();
  basis.mass.bottomRightCorner(psi, psi).setIdentity();
  basis.massless_boundary = true;
  return basis;
}

ReducedBasis macneal(const Eigen::SparseMatrix<double>& stiffness,
                     const Eigen::SparseMatrix<double>& mass, const Partition& p, int psi,
                     const CyclicBoundary* cyclic) {
  check_macneal_count(p, psi);
  const auto start = std::chrono::steady_clock::now();
  if (cyclic != nullptr && few_modes(psi, p.n()) == ModalSolver::sparse) {
    const char* const name = "MacNeal";
    const std::vector<int> representatives = cyclic->orbits.representative_positions();
    ReducedBasis basis = turned_residual_flexibility(
        stiffness, mass, p, free_interface_pool(stiffness, mass, p, psi, name, &representatives),
        *cyclic, name);
    basis.method = "macneal";
    basis.mass.setZero();
    basis.mass.bottomRightCorner(psi, psi).setIdentity();
    basis.massless_boundary = true;
    basis.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return basis;
  }
  const FreeInterfacePool pool = free_interface_pool(stiffness, mass, p, psi, "MacNeal");
  std::vector<int> kept(psi);
  std::iota(kept.begin(), kept.end(), 0);
  return macneal(stiffness, mass, p, pool, kept, start);
}

} // namespace rsi

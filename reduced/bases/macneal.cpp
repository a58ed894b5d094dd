#include "macneal.hpp"

#include <chrono>
#include <numeric>
#include <string>
#include <utility>

#include "craig_chang_martinez.hpp"
#include "guyan.hpp"

namespace rsi {

ReducedBasis macneal(const Eigen::SparseMatrix<double>& stiffness,
                     const Eigen::SparseMatrix<double>& mass, const Partition& p, int psi) {
  const int n = p.n();
  const int nb = p.n_boundary();
  if (psi < 1 || psi > n - nb)
    throw ReductionError("MacNeal takes 1 to " + std::to_string(n - nb) +
                             " free-interface modes (dofs minus boundary dofs; the boundary is "
                             "massless), got " +
                             std::to_string(psi),
                         failed_input(FailedInput::mode_count));
  const auto start = std::chrono::steady_clock::now();
  ReducedBasis basis;
  basis.method = "macneal";
  basis.n_modes = psi;
  basis.requested_modes = psi;
  basis.candidate_modes = psi;
  basis.mode_index.resize(psi);
  std::iota(basis.mode_index.begin(), basis.mode_index.end(), 0);
  ResidualFlexibilityTransformation t =
      residual_flexibility_transformation(stiffness, mass, p, psi, "MacNeal");
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

} // namespace rsi

#include "craig_bampton.hpp"

#include <numeric>
#include <sstream>
#include <string>

#include "guyan.hpp"

namespace rsi {

void check_fixed_interface_count(const Partition& p, int eta) {
  if (eta < 0 || eta > p.n_interior())
    throw ReductionError("Craig-Bampton takes 0 to " + std::to_string(p.n_interior()) +
                             " fixed-interface modes (the interior dofs), got " +
                             std::to_string(eta),
                         failed_input(FailedInput::mode_count));
}

FixedInterfacePool fixed_interface_pool(const Eigen::SparseMatrix<double>& stiffness,
                                        const Eigen::SparseMatrix<double>& mass, const Partition& p,
                                        int count, const CyclicBoundary* cyclic) {
  check_fixed_interface_count(p, count);
  FixedInterfacePool pool;
  if (count == 0) {
    pool.constraint = constraint_modes(stiffness, p, cyclic);
    return pool;
  }
  const Eigen::SparseMatrix<double> k_ii = sparse_block(stiffness, p.interior, p.interior);
  const Eigen::SparseMatrix<double> m_ii = sparse_block(mass, p.interior, p.interior);
  const ModalSolver solver = few_modes(count, p.n_interior());
  if (solver == ModalSolver::sparse && shares_factor(p.n_interior())) {
    const auto factor =
        factor_positive_definite(k_ii, m_ii, interior_stiffness_name(p), interior_stiffness_remedy);
    pool.constraint = constraint_modes(stiffness, p, *factor, k_ii, cyclic);
    pool.modes = lowest_modes(k_ii, m_ii, count, *factor);
  } else {
    pool.constraint = constraint_modes(stiffness, p, cyclic);
    pool.modes = lowest_modes(k_ii, m_ii, count, solver);
    // count >= n_I/4: the dense solver's eigenvalues as they are. K_II passed
    // the definiteness check of its factor above (constraint_modes), so a
    // lowest one under the dense solver's resolution n eps lambda_max
    // (dense_resolution, modal_analysis.hpp) is a stiff model's, which
    // the dense solver cannot place (a blade 1e-7 m thick: 7 % off, or
    // negative), and shift-invert does not reach this many modes.
    if (solver == ModalSolver::dense &&
        !(pool.modes.omega_squared(0) > dense_resolution(pool.modes))) {
      std::ostringstream message;
      message << "Craig-Bampton: with eta = " << count
              << " fixed-interface modes (n_I/4 or more) every mode of K_II comes from the "
                 "dense solver, which does not resolve the lowest eigenvalue "
              << pool.modes.omega_squared(0)
              << " rad^2/s^2 (<= n eps lambda_max = " << dense_resolution(pool.modes)
              << ") of this stiff model; use at most " << (p.n_interior() - 1) / 4
              << " modes (shift-invert resolves them)";
      throw ReductionError(message.str());
    }
  }
  return pool;
}

ReducedBasis craig_bampton(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, const Partition& p,
                           const FixedInterfacePool& pool, const std::vector<int>& kept,
                           std::chrono::steady_clock::time_point start,
                           const CyclicBoundary* cyclic) {
  const int eta = static_cast<int>(kept.size());
  check_fixed_interface_count(p, eta);
  ReducedBasis basis;
  basis.method = "cb";
  basis.n_modes = eta;
  basis.requested_modes = eta;
  basis.candidate_modes = pool.modes.n_modes();
  basis.mode_index = kept;
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(p.n(), eta + p.n_boundary());
  if (eta > 0) {
    t.leftCols(eta) = place_rows(p.n(), p.interior, take_columns(pool.modes.shapes, kept));
    basis.mode_omega = take_entries(pool.modes.omega_squared, kept).cwiseSqrt();
  }
  t.rightCols(p.n_boundary()) =
      place_rows(p.n(), p.interior, pool.constraint) +
      place_rows(p.n(), p.boundary, Eigen::MatrixXd::Identity(p.n_boundary(), p.n_boundary()));
  basis.transformation = t;
  finish_basis(stiffness, mass, p.n_boundary(), eta, start, basis, cyclic);
  return basis;
}

ReducedBasis craig_bampton(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, const Partition& p, int eta,
                           const CyclicBoundary* cyclic) {
  check_fixed_interface_count(p, eta);
  const auto start = std::chrono::steady_clock::now();
  const FixedInterfacePool pool = fixed_interface_pool(stiffness, mass, p, eta, cyclic);
  std::vector<int> kept(eta);
  std::iota(kept.begin(), kept.end(), 0);
  return craig_bampton(stiffness, mass, p, pool, kept, start, cyclic);
}

} // namespace rsi

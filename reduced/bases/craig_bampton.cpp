#include "craig_bampton.hpp"

#include <chrono>
#include <sstream>
#include <string>

#include "guyan.hpp"
#include "modal_analysis.hpp"

namespace rsi {

ReducedBasis craig_bampton(const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, const Partition& p, int eta) {
  if (eta < 0 || eta > p.n_interior())
    throw ReductionError("--modes: Craig-Bampton takes 0 to " + std::to_string(p.n_interior()) +
                         " fixed-interface modes (the interior dofs), got " + std::to_string(eta));
  const auto start = std::chrono::steady_clock::now();
  ReducedBasis basis;
  basis.method = "cb";
  basis.n_modes = eta;
  Eigen::MatrixXd psi;
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(p.n(), eta + p.n_boundary());
  if (eta > 0) {
    const Eigen::SparseMatrix<double> k_ii = sparse_block(stiffness, p.interior, p.interior);
    const Eigen::SparseMatrix<double> m_ii = sparse_block(mass, p.interior, p.interior);
    const ModalSolver solver = few_modes(eta, p.n_interior());
    Modes fixed;
    if (solver == ModalSolver::sparse && shares_factor(p.n_interior())) {
      const auto factor = factor_positive_definite(k_ii, m_ii, interior_stiffness_name(p),
                                                   interior_stiffness_remedy);
      psi = constraint_modes(stiffness, p, *factor, k_ii);
      fixed = lowest_modes(k_ii, m_ii, eta, *factor);
    } else {
      psi = constraint_modes(stiffness, p);
      fixed = lowest_modes(k_ii, m_ii, eta, solver);
      // eta >= n_I/4: the dense solver's eigenvalues as they are. K_II passed
      // the definiteness check of its factor above (constraint_modes), so a
      // lowest one under the dense solver's resolution n eps lambda_max
      // (dense_resolution, modal_analysis.hpp) is a stiff model's, which
      // the dense solver cannot place (a blade 1e-7 m thick: 7 % off, or
      // negative), and shift-invert does not reach this many modes.
      if (solver == ModalSolver::dense && !(fixed.omega_squared(0) > dense_resolution(fixed))) {
        std::ostringstream message;
        message << "Craig-Bampton: with eta = " << eta
                << " fixed-interface modes (n_I/4 or more) every mode of K_II comes from the "
                   "dense solver, which does not resolve the lowest eigenvalue "
                << fixed.omega_squared(0)
                << " rad^2/s^2 (<= n eps lambda_max = " << dense_resolution(fixed)
                << ") of this stiff model; use at most " << (p.n_interior() - 1) / 4
                << " modes (shift-invert resolves them)";
        throw ReductionError(message.str());
      }
    }
    t.leftCols(eta) = place_rows(p.n(), p.interior, fixed.shapes);
    basis.mode_omega = fixed.omega_squared.cwiseSqrt();
  } else {
    psi = constraint_modes(stiffness, p);
  }
  t.rightCols(p.n_boundary()) =
      place_rows(p.n(), p.interior, psi) +
      place_rows(p.n(), p.boundary, Eigen::MatrixXd::Identity(p.n_boundary(), p.n_boundary()));
  basis.transformation = t;
  finish_basis(stiffness, mass, p.n_boundary(), eta, start, basis);
  return basis;
}

} // namespace rsi

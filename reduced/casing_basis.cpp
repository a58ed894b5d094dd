#include "casing_basis.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include "cholmod_factor.hpp"
#include "modal_analysis.hpp"

namespace rsi {

namespace {

/// x made M-orthogonal to the M-orthonormal columns of `phi` (classical
/// Gram-Schmidt, applied twice: "twice is enough").
Eigen::VectorXd orthogonal_part(const Eigen::MatrixXd& phi, const Eigen::SparseMatrix<double>& mass,
                                Eigen::VectorXd x) {
  for (int pass = 0; pass < 2; ++pass) {
    const Eigen::VectorXd mx = mass * x;
    x -= phi * (phi.transpose() * mx);
  }
  return x;
}

double mass_norm(const Eigen::SparseMatrix<double>& mass, const Eigen::VectorXd& x) {
  return std::sqrt(std::max(0.0, x.dot(mass * x)));
}

/// The basis of `modes` modes, before any correction.
CasingBasis modal_basis(const Modes& m, int modes) {
  CasingBasis basis;
  basis.n_modes = modes;
  basis.shapes = m.shapes;
  basis.omega_squared = m.omega_squared;
  return basis;
}

/// The static correction x = K^-1 F added to `basis` (header: kept only
/// when its M-orthogonal part is a direction), by a Rayleigh-Ritz step.
void add_static_correction(CasingBasis& basis, const Eigen::SparseMatrix<double>& stiffness,
                           const Eigen::SparseMatrix<double>& mass, const Eigen::VectorXd& x) {
  const auto n = static_cast<int>(basis.shapes.rows());
  const int modes = basis.size();
  const Eigen::VectorXd y = orthogonal_part(basis.shapes, mass, x);
  const double size = mass_norm(mass, x);
  const double kept = mass_norm(mass, y);
  if (!(kept > std::sqrt(std::numeric_limits<double>::epsilon()) * size)) return;
  // Rayleigh-Ritz on [Phi, y / |y|_M]: the projected mass is I to
  // round-off, the projected stiffness diag(omega^2) bordered by one row.
  Eigen::MatrixXd v(n, modes + 1);
  v << basis.shapes, y / kept;
  const Eigen::MatrixXd kv = stiffness * v;
  const Eigen::MatrixXd mv = mass * v;
  Eigen::MatrixXd k_small = v.transpose() * kv;
  Eigen::MatrixXd m_small = v.transpose() * mv;
  k_small = 0.5 * (k_small + k_small.transpose()).eval();
  m_small = 0.5 * (m_small + m_small.transpose()).eval();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(k_small, m_small);
  if (ritz.info() != Eigen::Success)
    throw ModalError("casing reduction: the Rayleigh-Ritz step of the static correction "
                     "failed",
                     remedied_by({Remedy::fewer_casing_modes}));
  basis.shapes = v * ritz.eigenvectors();
  basis.omega_squared = ritz.eigenvalues();
  basis.static_correction = true;
}

} // namespace

double CasingBasis::critical_time_step() const {
  return 2.0 / std::sqrt(omega_squared.maxCoeff());
}

std::string CasingBasis::name() const {
  return "modal-" + std::to_string(n_modes) + (static_correction ? "+s" : "");
}

CasingBasis reduce_casing(const Casing& casing, int modes, const Eigen::VectorXd& forcing) {
  const int n = casing.n_dofs();
  if (modes < 1 || modes > n)
    throw std::invalid_argument("casing modes: must be in [1, " + std::to_string(n) +
                                "] (the casing's dofs), got " + std::to_string(modes));
  if (forcing.size() != n)
    throw std::invalid_argument("reduce_casing: the forcing has " +
                                std::to_string(forcing.size()) + " entries, the casing " +
                                std::to_string(n) + " dofs");
  const auto start = std::chrono::steady_clock::now();
  CasingBasis basis =
      modal_basis(lowest_modes(casing.stiffness, casing.mass, modes, ModalSolver::dense), modes);
  if (modes < n && forcing.any()) {
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> k(casing.stiffness);
    if (k.info() != Eigen::Success)
      throw ModalError("casing reduction: the clamped casing's stiffness cannot be factorized "
                       "(the case's check of K should have refused it); change "
                       "casing.section.thickness or casing.n_elements");
    add_static_correction(basis, casing.stiffness, casing.mass, k.solve(forcing));
  }
  basis.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return basis;
}

CasingBasis reduce_solid_casing(const Component& casing, int modes,
                                const Eigen::VectorXd& forcing) {
  const int n = casing.n_dofs();
  // The sparse eigensolver needs fewer modes than dofs.
  if (modes < 1 || modes >= n)
    throw std::invalid_argument("casing modes: must be in [1, " + std::to_string(n - 1) +
                                "] (fewer than the casing's " + std::to_string(n) +
                                " dofs), got " + std::to_string(modes));
  if (forcing.size() != 0 && forcing.size() != n)
    throw std::invalid_argument("reduce_solid_casing: the forcing has " +
                                std::to_string(forcing.size()) + " entries, the casing " +
                                std::to_string(n) + " dofs");
  const auto start = std::chrono::steady_clock::now();
  CasingBasis basis = modal_basis(
      lowest_modes(casing.stiffness, casing.mass, modes, ModalSolver::automatic), modes);
  if (forcing.size() == n && forcing.any()) {
    CholmodFactor k;
    const Eigen::SparseMatrix<double> lower = casing.stiffness.triangularView<Eigen::Lower>();
    if (k.factorize(lower) != CholmodFactor::Status::successful)
      throw ModalError("casing reduction: the clamped casing's stiffness cannot be factorized (" +
                       k.message() + "): a free casing has rigid-body motions; clamp it");
    Eigen::VectorXd x(n);
    if (!k.solve(CholmodFactor::System::a, forcing, x))
      throw ModalError("casing reduction: CHOLMOD's solve with the casing's stiffness failed");
    add_static_correction(basis, casing.stiffness, casing.mass, x);
  }
  basis.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return basis;
}

} // namespace rsi

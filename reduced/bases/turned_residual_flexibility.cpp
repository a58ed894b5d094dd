#include "turned_residual_flexibility.hpp"

#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>

#include "guyan.hpp"
#include "transpose_product.hpp"

namespace rsi {
namespace {

/// T^T A T of T = [Psi, 0] + Y W from Psi^T A Psi (`guyan_block`).
Eigen::MatrixXd projection(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& psi,
                           const Eigen::MatrixXd& guyan_block, const Eigen::MatrixXd& y,
                           const Eigen::MatrixXd& w) {
  const Eigen::Index nb = psi.cols();
  // A^T Y as finish_basis forms A^T T (guyan.cpp): equal for a symmetric A.
  const Eigen::MatrixXd ay = transpose_product(a, y);
  const Eigen::MatrixXd xw = (psi.transpose() * ay) * w;
  Eigen::MatrixXd out = w.transpose() * (y.transpose() * ay) * w;
  out.topRows(nb) += xw;
  out.leftCols(nb) += xw.transpose();
  out.topLeftCorner(nb, nb) += guyan_block;
  return 0.5 * (out + out.transpose());
}

} // namespace

ReducedBasis turned_residual_flexibility(const Eigen::SparseMatrix<double>& stiffness,
                                         const Eigen::SparseMatrix<double>& mass,
                                         const Partition& p, const FreeInterfacePool& pool,
                                         const CyclicBoundary& cyclic, const std::string& name,
                                         TurnedResidualPieces* pieces) {
  const int n = p.n();
  const int nb = p.n_boundary();
  const int psi = pool.count;
  if (pool.complete || pool.flexibility.value.cols() != 3 * cyclic.orbits.n_representatives() ||
      pool.flexibility.value.rows() != n)
    throw std::invalid_argument("turned_residual_flexibility: the pool must hold K^-1 on the " +
                                std::to_string(3 * cyclic.orbits.n_representatives()) +
                                " representatives' columns (n x 3 n_r), not a complete pool");
  // Psi (boundary rows the identity), S = Psi^T K Psi and Psi^T M Psi, by the turns.
  ReducedBasis out = guyan(stiffness, mass, p, &cyclic);
  out.n_modes = psi;
  out.requested_modes = psi;
  out.candidate_modes = psi;
  out.mode_index.resize(static_cast<size_t>(psi));
  std::iota(out.mode_index.begin(), out.mode_index.end(), 0);

  // R_B = (K^-1)_BB - Phi_1B Omega_1^-2 Phi_1B^T, (K^-1)_BB turned from the
  // representatives' rows (K^-1 symmetric: their columns' boundary rows).
  const Eigen::MatrixXd g =
      turned_boundary_block(take_rows(pool.flexibility.value, p.boundary).transpose(), cyclic);
  Eigen::MatrixXd r_b = 0.5 * (g + g.transpose());
  Eigen::MatrixXd phi1_b;
  Eigen::MatrixXd scaled; // Phi_1B Omega_1^-2 = D^T
  if (psi > 0) {
    phi1_b = take_rows(pool.modes.shapes, p.boundary);
    scaled = phi1_b * pool.modes.omega_squared.cwiseInverse().asDiagonal();
    r_b -= scaled * phi1_b.transpose();
    out.mode_omega = pool.modes.omega_squared.cwiseSqrt();
  }
  out.cond_rb = residual_flexibility_condition(r_b, n, name);
  if (pieces != nullptr) *pieces = {out.transformation, {}, {}, g};
  if (psi == 0) return out;

  // C = D R_B^-1 (R_B symmetric), Y = Phi_1 - Psi Phi_1B, W = [-C, I + C Phi_1B].
  const Eigen::MatrixXd c = Eigen::LDLT<Eigen::MatrixXd>(r_b).solve(scaled).transpose();
  const Eigen::MatrixXd& psi_modes = out.transformation;
  Eigen::MatrixXd y = pool.modes.shapes - psi_modes * phi1_b;
  for (int b : p.boundary)
    y.row(b).setZero();
  Eigen::MatrixXd w(psi, nb + psi);
  w.leftCols(nb) = -c;
  w.rightCols(psi) = Eigen::MatrixXd::Identity(psi, psi) + c * phi1_b;

  Eigen::MatrixXd t = y * w;
  t.leftCols(nb) += psi_modes;
  out.stiffness = projection(stiffness, psi_modes, out.stiffness, y, w);
  out.mass = projection(mass, psi_modes, out.mass, y, w);
  out.transformation = std::move(t);
  if (pieces != nullptr) {
    pieces->y = std::move(y);
    pieces->w = std::move(w);
  }
  return out;
}

} // namespace rsi

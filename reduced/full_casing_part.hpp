#pragma once
// The full casing (sparse K_c, M_c) as the reduced integrator's casing part
// (casing_part.hpp), written independently of the reference integrator:
//   c~ = 2 c_n - c_{n-1} + dt^2 A_c^-1 (F_n - K_c c_n - C_c (c_n - c_{n-1}) / dt),
//   A_c = M_c + dt/2 C_c (M_c undamped), C_c = alpha M_c + beta K_c.
// The predictor applies the sparse LDL^T factor of A_c, P A_c P^T = L D L^T,
// whose ordering P is applied while the right-hand side is gathered and the
// solution scattered, so a step allocates nothing and permutes nothing in
// place. A_c^-1 (dense, 4 dofs per casing node) is formed once from the
// factor, whose status is checked; it serves the contact rows and the
// correction c_{n+1} = c~ + A_c^-1 R_n. The product K_c c_n uses the full
// run's row kernels (sparse_rows.hpp: a product, no solver state).

#include <vector>

#include <Eigen/SparseCholesky>

#include "casing_part.hpp"
#include "sparse_rows.hpp"

namespace rsi {

class FullCasingPart final : public CasingPart {
public:
  /// Throws ReducedIntegrationError when A_c is not positive definite.
  FullCasingPart(const Casing& casing, double dt, const RayleighDamping& damping);

  void start() override;
  void predict() override;
  void clear_correction() override { m_dc.setZero(); }
  void add_correction(const TipContact& tip, double f_u, double f_v) override;
  void add_sliding_correction(const TipContact& tip, double f, double mu) override;
  void apply_correction() override { m_c_next += m_dc; }
  double energy() const override;
  /// K_c c (2 nnz(K_c)), the LDL^T solve (4 nnz(L_c) + n_c) and 4 n_c of
  /// vector updates: the floor under every reduced run. Damped, also M_c and
  /// K_c times a difference twice (force and W_damp: 4 (nnz(M_c) +
  /// nnz(K_c))) and about 10 n_c.
  double flops_per_step() const override;

private:
  SparseRows m_kc_rows; ///< K_c for the per-step product
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> m_factor; ///< of A_c
  std::vector<int> m_order;    ///< P as an index map: (P x)(m_order[i]) = x(i)
  Eigen::VectorXd m_inverse_d; ///< 1 / D of the factor
  Eigen::VectorXd m_kc_c;      ///< K_c c_n (work)
  Eigen::VectorXd m_dc;        ///< the step's correction
};

} // namespace rsi

#pragma once
// Central differences with forward-increment Lagrange multipliers for the
// reduced bladed disk (dense K^, M^, coordinates q) coupled through contact
// with the full casing (sparse K_c, M_c): SPEC §3, written independently
// of the reference integrator.
//
//   q~ = 2 q_n - q_{n-1} - dt^2 M^-1 K^ q_n           (no external force on the disk)
//   c~ = 2 c_n - c_{n-1} + dt^2 M_c^-1 (F_n - K_c c_n)
//   W_ij = dt^2 (G_i^q M^-1 D_j^qT + G_i^c M_c^-1 D_j^cT), W lambda = -g~ on the
//   active set; every negative lambda dropped at once, constraints closed by
//   the correction added, until both hold;
//   (q, c)_{n+1} = (q~, c~) + dt^2 (M^-1 D^qT, M_c^-1 D^cT) lambda.
// M^-1 (r x r) and M_c^-1 (dense, 4 dofs per casing node) are formed once
// from Cholesky factorizations whose status is checked.
// Energy E_{n+1/2} = sum over both parts of 1/2 v^T M v + 1/2 x_n^T K x_{n+1},
// computed when asked (its dense products would double the cost of a step).

#include <stdexcept>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "history.hpp"
#include "reduced_contact.hpp"

namespace rsi {

class ReducedIntegrationError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class ReducedIntegrator {
public:
  /// `contact` must outlive the integrator (not owned).
  ReducedIntegrator(const ReducedBasis& basis, const Casing& casing, double dt,
                    const ReducedTipContact& contact);

  /// From rest under the casing force f0 at t = 0.
  void start(const Eigen::VectorXd& casing_force);
  StepReport step(const Eigen::VectorXd& casing_force);

  int step_index() const { return m_n; }
  double time() const { return m_n * m_dt; }
  const Eigen::VectorXd& q() const { return m_q; }
  const Eigen::VectorXd& casing() const { return m_c; }
  const Eigen::VectorXd& gap() const { return m_gap; }
  const Eigen::VectorXd& lambda() const { return m_lambda; }
  double energy() const;
  double initial_energy() const { return m_initial_energy; }
  double external_work() const { return m_external_work; }
  double contact_work() const { return m_contact_work; }
  /// Flops of a contact-free step: the dense M^-1 K^ q (2 r^2), about 12 r
  /// of vector updates, and the casing's flops (below).
  double flops_per_step() const;
  /// The full casing's part: K_c c (2 nnz(K_c)), its LDLT solve (4 nnz(L_c)
  /// + n_c) and about 12 n_c of vector updates: the floor under every
  /// reduced run.
  double casing_flops_per_step() const;

private:
  double flexibility(const TipContact& i, const TipContact& j) const;
  /// D_j . (dq, dc): the force direction of tip j applied to a displacement.
  double direction_dot(const TipContact& j, const Eigen::VectorXd& dq,
                       const Eigen::VectorXd& dc) const;
  void solve_contact(const std::vector<TipContact>& tips);

  Eigen::MatrixXd m_kq;
  Eigen::MatrixXd m_mq;
  Eigen::MatrixXd m_mq_inverse;
  Eigen::MatrixXd m_aq; ///< M^-1 K^
  Eigen::SparseMatrix<double, Eigen::RowMajor> m_kc;
  Eigen::SparseMatrix<double, Eigen::RowMajor> m_mc;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> m_mc_factor;
  Eigen::MatrixXd m_mc_inverse;
  double m_dt;
  double m_mu;
  const ReducedTipContact& m_contact;

  int m_n = 0;
  Eigen::VectorXd m_q, m_q_prev, m_c, m_c_prev, m_kc_c;
  Eigen::VectorXd m_q_next, m_c_next, m_dq, m_dc;
  Eigen::VectorXd m_gap, m_lambda;
  std::vector<TipContact> m_tips;
  double m_initial_energy = 0.0;
  double m_external_work = 0.0;
  double m_contact_work = 0.0;
};

} // namespace rsi

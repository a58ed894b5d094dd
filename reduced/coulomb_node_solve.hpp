#pragma once
// The Coulomb contact solve of a reduced component on a rigid casing
// (component_integrator.hpp), stick and slip by CoulombGaussSeidel, after
// CoulombSlipSet's direct solve where every closed contact slips (mu > 0,
// no contact stuck at the previous step; it declines otherwise): per
// contact node three rows (n, t1, t2), the step's problem
//   [g; s] = [g~; s~] + W lambda
// with [g~; s~] the prediction of the casing part (rigid_casing_part.hpp)
// and W (3 nc square, constant over a run; with a flexible casing plus
// its share dt^2 H H^T of each step, set_flexibility) handed by the rotor part: an
// inverse mass times dt^2 for a mass-carrying boundary, a compliance for a
// massless one (mass_carrying_boundary_part.hpp, massless_boundary_part.hpp);
// it is used symmetrised, (W + W^T)/2. lambda = (lambda_n, lambda_t1,
// lambda_t2) per contact [force]. The solve works on the contacts that may
// carry a force: the closing ones (g~ < 0) and those that carried a force at
// the previous step, grown by every contact that the others' forces close
// (g~_c + W_cA lambda_A < 0), until none does (or on the whole W when
// closing_subset is off); the slip set and the Gauss-Seidel are warm-started
// with the previous multipliers, and the step's certificate (reduced_coulomb_certificate) is
// checked on the whole W. A step with a closing contact costs the slip set's
// solve or the Gauss-Seidel's (on the closing contacts only, grown while their
// forces close others). The contact work of a step is lambda_n^T B (x_{n+1} -
// x_{n-1})/2, summed into W_contact. A solve that does not converge throws
// ComponentIntegrationError naming the step.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "component_contact_solve.hpp"
#include "coulomb_gauss_seidel.hpp"
#include "coulomb_slip_set.hpp"
#include "history.hpp"
#include "reduced_coulomb_certificate.hpp"

namespace rsi {

class CoulombNodeSolve final : public ComponentContactSolve {
public:
  /// nc contact nodes; dt [s] (for the messages); mu >= 0 and `options`
  /// checked by CoulombGaussSeidel (std::invalid_argument); closing_subset:
  /// solve on the closing contacts only (false: on the whole W).
  CoulombNodeSolve(int n_contacts, double dt, double mu, const CoulombGaussSeidelOptions& options,
                   bool closing_subset);

  /// W of every step's problem (3 nc square), symmetrised here.
  void set_contact_matrix(const Eigen::MatrixXd& w) override;
  const Eigen::MatrixXd& contact_matrix() const override { return m_w; }
  /// The step's W = W + scale h h^T (the flexible casing's share, h 3 nc x
  /// m, read at the next solve; nullptr: none), never formed whole: the
  /// solve forms W's blocks on its active contacts, the growth test and the
  /// certificate W lambda from the active columns (3 nc x 3 |A| + m terms
  /// instead of the (3 nc)^2 m rank update). The multipliers and states
  /// are kept (the warm start).
  void set_flexibility(const Eigen::MatrixXd* h, double scale);

  /// Before the first step: every multiplier zero, every contact open, no work, no sweeps.
  void start() override;
  /// lambda of the problem of `predicted` ([g~; s~], 3 nc) into
  /// lambda_next(); the contact fields of `report`. `step`: the step the
  /// problem belongs to (n + 1, for the message).
  void solve(const Eigen::VectorXd& predicted, int step, StepReport& report) override;
  /// The last solve's multipliers, 3 nc entries (n, t1, t2 per contact).
  const Eigen::VectorXd& lambda_next() const override { return m_lambda_next; }
  /// Each contact's state after the last solve.
  const std::vector<ReducedContactState>& states() const override { return m_state; }
  /// W_contact += lambda_n^T B_B (u_B^{n+1} - u_B^{n-1}) / 2 (rows: B_B;
  /// increment: u_B^{n+1} - u_B^{n-1}).
  void add_contact_work(const Eigen::VectorXd& lambda_n, const Eigen::MatrixXd& rows,
                        const Eigen::VectorXd& increment) override;
  double contact_work() const override { return m_contact_work; }
  /// Gauss-Seidel sweeps summed since start() (none for a step the slip set solved).
  long sweeps() const override { return m_sweeps; }

private:
  int m_nc;
  double m_dt;
  double m_mu;
  bool m_subset;
  /// y = predicted + W lambda for the certificate with the casing's share
  /// (m_z: h_A^T lambda_A of the final active set).
  Eigen::VectorXd certificate_point(const Eigen::VectorXd& predicted,
                                    const std::vector<int>& active) const;

  Eigen::MatrixXd m_w;                  ///< W, 3 nc square (the rotor's with a flexible casing)
  const Eigen::MatrixXd* m_h = nullptr; ///< the casing's rows h of W's share scale h h^T
  double m_h_scale = 0.0;
  Eigen::MatrixXd m_ha;       ///< h's rows on the active contacts (3 |A| x m)
  Eigen::VectorXd m_z;        ///< h_A^T lambda_A (m)
  Eigen::MatrixXd m_wa;       ///< W on the contacts of the step's active set
  Eigen::VectorXd m_pa, m_la; ///< [g~; s~] and lambda on them
  Eigen::VectorXd m_lambda_next;
  std::vector<ReducedContactState> m_state;
  CoulombGaussSeidel m_solver;
  std::optional<CoulombSlipSet> m_slip; ///< mu > 0: the direct solve tried first
  double m_contact_work = 0.0;
  long m_sweeps = 0;
};

} // namespace rsi

#pragma once
// The contact solve of the reduced integrator (reduced_integrator.hpp): the
// multipliers lambda of a step from the tips at the predicted state, the
// correction dt^2 A^-1 B^T lambda they make in the disk and casing parts
// (disk_part.hpp, casing_part.hpp: A^-1 and A_c^-1 are theirs), and the
// contact work of the step, sum over rows lambda_r B_r (x_{n+1} - x_{n-1}) / 2.
// One solve per friction law, each stating its rows and its problem in its
// header: sliding_sign_solve.hpp (the first version's law, forward-increment
// multipliers on an active set) and coulomb_tip_solve.hpp (Coulomb stick
// and slip by CoulombGaussSeidel). lambda_n pushes the tip inward and the
// casing outward; lambda_t is the tangential force on the tip along +v
// (counter-clockwise), the casing takes -lambda_t at the contact point.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "casing_part.hpp"
#include "disk_part.hpp"
#include "failure_kinds.hpp"
#include "history.hpp"
#include "reduced_contact.hpp"
#include "reduced_coulomb_certificate.hpp"

namespace rsi {

class TipContactSolve {
public:
  virtual ~TipContactSolve() = default;
  TipContactSolve(const TipContactSolve&) = delete;
  TipContactSolve& operator=(const TipContactSolve&) = delete;

  /// Before the first step: every multiplier zero, every tip open.
  virtual void start(int n_tips);
  /// lambda (and lambda_t) of the step to `step` (n + 1, for the messages)
  /// for the tips at the predicted state; the law's fields of `report`.
  /// Throws ReducedIntegrationError naming the step when it cannot.
  virtual void solve(const std::vector<TipContact>& tips, int step, StepReport& report) = 0;
  /// Gathers dt^2 A^-1 B^T lambda in both parts (the caller clears and
  /// applies the corrections).
  virtual void gather_correction(const std::vector<TipContact>& tips, DiskPart& disk,
                                 CasingPart& casing) const = 0;
  /// Adds the step's contact work to `work`, tip by tip, with x_{n+1} and
  /// x_{n-1} the parts' next() and previous(); `corrected`: some lambda of
  /// the step is not zero.
  virtual void add_contact_work(const std::vector<TipContact>& tips, bool corrected,
                                double& work) = 0;
  /// A closed tip's share of the report once the state is advanced (`now`:
  /// at x_{n+1}, `predicted`: at the prediction, `lambda` its multiplier).
  virtual void report_tip(const TipContact& /*now*/, const TipContact& /*predicted*/,
                          double /*lambda*/, StepReport& /*report*/) const {}

  /// Normal multipliers of the last step, one per tip [N].
  const Eigen::VectorXd& lambda() const { return m_lambda; }
  /// Tangential multipliers of the last step, one per tip [N] (zero on open tips).
  const Eigen::VectorXd& tangential_lambda() const { return m_lambda_t; }
  /// Each tip's state after the last step (all open under sliding_sign).
  const std::vector<ReducedContactState>& states() const { return m_state; }
  /// The certificate of the last step's Coulomb problem (zero otherwise).
  const ReducedCoulombCertificate& certificate() const { return m_certificate; }
  /// The tips the last problem was solved on; W over them and the predicted
  /// [g~; s~] (Coulomb); the predicted tips of the last closing step (Coulomb).
  const std::vector<int>& solved_tips() const { return m_set; }
  const Eigen::MatrixXd& w() const { return m_w; }
  const Eigen::VectorXd& predicted_rows() const { return m_rows; }
  const std::vector<TipContact>& predicted_tips() const { return m_predicted_kept; }

protected:
  /// The parts must outlive the solve (not owned).
  TipContactSolve(const DiskPart& disk, const CasingPart& casing, double dt, double mu);
  /// What to change, for the messages of ReducedIntegrationError.
  static FailureAdvice step_remedy();
  static FailureAdvice contact_remedy();

  const DiskPart& m_disk;
  const CasingPart& m_casing;
  double m_dt;
  double m_mu;
  Eigen::VectorXd m_lambda, m_lambda_t;
  std::vector<ReducedContactState> m_state;
  ReducedCoulombCertificate m_certificate;
  std::vector<char> m_active;
  std::vector<int> m_set;
  Eigen::MatrixXd m_w;    ///< W over the solved tips (Coulomb: 2 m square)
  Eigen::VectorXd m_rows; ///< [g~; s~] over the solved tips (Coulomb)
  std::vector<TipContact> m_predicted_kept;
};

} // namespace rsi

#pragma once
// The bladed-disk part of the reduced integrator (reduced_integrator.hpp):
// the reduced disk's share of the central-difference step in the
// coordinates q of a ReducedBasis with a mass-carrying boundary (CB, CCM,
// Guyan; the boundary, the tips' u and v, kept physical in q), whichever
// coordinates it is advanced in (physical_disk_part.hpp: q itself, damped
// or not; modal_disk_part.hpp: the reduced modes, undamped). Both advance
//   M^ (q_{n+1} - 2 q_n + q_{n-1}) / dt^2 + C^ (q_{n+1} - q_{n-1}) / (2 dt) + K^ q_n = B_q^T lambda_n
// (no external force on the disk) from rest, the contact entering as a
// correction of the predicted state, q_{n+1} = q~ + dt^2 A^-1 B_q^T lambda
// (A = M^ + dt/2 C^, M^ undamped). A^-1 (r x r) is formed once from a
// Cholesky factorization whose status is checked; the contact rows read it
// (flexibility()). The contact reads q at the tips' entries only, and
// those are kept in q_{n-1}, q_n, q_{n+1} by both parts.

#include <optional>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "critical_step.hpp"
#include "reduced_basis.hpp"
#include "reduced_contact.hpp"

namespace rsi {

class DiskPart {
public:
  virtual ~DiskPart() = default;
  DiskPart(const DiskPart&) = delete;
  DiskPart& operator=(const DiskPart&) = delete;

  Eigen::Index n_reduced() const { return m_kq.rows(); }
  bool damped() const { return m_damped; }
  /// A^-1: the disk's flexibility in the contact rows.
  const Eigen::MatrixXd& flexibility() const { return m_flexibility; }
  /// q_n, q_{n-1}, q_{n+1} (predicted, then corrected); the modal part keeps
  /// their tip entries only.
  const Eigen::VectorXd& now() const { return m_q; }
  const Eigen::VectorXd& previous() const { return m_q_prev; }
  const Eigen::VectorXd& next() const { return m_q_next; }
  /// The whole q_n.
  virtual Eigen::VectorXd q() const { return m_q; }
  /// The tip entries of q_n, (u_1, v_1, u_2, v_2, ...) [m].
  void tip_displacement(Eigen::VectorXd& out) const;

  /// From rest at q0 (a free vibration: q_{-1} = q0 - dt^2/2 M^-1 K^ q0, with
  /// M^ itself, so (q_1 - q_{-1}) / (2 dt) = 0); q0 = 0: q_{-1} = 0.
  virtual void start(const Eigen::Ref<const Eigen::VectorXd>& q0);
  /// q_{n+1} = q~.
  virtual void predict() = 0;
  /// Zeroes the correction gathered for the step.
  virtual void clear_correction() { m_dq.setZero(); }
  /// Coulomb rows: the correction of f on the tip's -u and ft on its +v
  /// (dt^2 in f and ft; ft == 0 skipped).
  virtual void add_coulomb_correction(const TipContact& tip, double f, double ft) = 0;
  /// sliding_sign rows: the correction of f along -(e(u) + mu s e(v)).
  virtual void add_sliding_correction(const TipContact& tip, double f, double mu) = 0;
  /// q_{n+1} += the gathered correction.
  virtual void apply_correction() = 0;
  /// (q_{n+1} - q_{n-1})^T C^ (q_{n+1} - q_{n-1}) (asked only when damped).
  virtual double step_damping_product() { return 0.0; }
  /// q_{n-1} <- q_n <- q_{n+1}.
  virtual void advance();
  /// E_{n-1/2} of the reduced disk [J].
  virtual double energy() const = 0;
  /// Flops of a contact-free step (reduced_integrator.hpp, flops_per_step).
  virtual double flops_per_step() const = 0;

protected:
  /// A = M^ + dt/2 C^ (`a`, M^ undamped) factorized: throws
  /// ReducedIntegrationError when it is not positive definite.
  DiskPart(const ReducedBasis& basis, double dt, const Eigen::MatrixXd& a, bool damped);

  Eigen::MatrixXd m_kq;
  Eigen::MatrixXd m_mq;
  /// Of A, released (reset) by the derived part once used: an optional, as
  /// assigning a default-constructed LLT would copy its uninitialized members.
  std::optional<Eigen::LLT<Eigen::MatrixXd>> m_factor;
  Eigen::MatrixXd m_flexibility; ///< A^-1 = (M^ + dt/2 C^)^-1 (M^-1 undamped)
  double m_dt;
  bool m_damped;
  std::vector<int> m_tip_position; ///< positions of the boundary (tip) entries in q
  Eigen::VectorXd m_q, m_q_prev, m_q_next, m_dq;
};

} // namespace rsi

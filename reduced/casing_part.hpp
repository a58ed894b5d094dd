#pragma once
// The casing part of the reduced integrator (reduced_integrator.hpp): the
// casing's share of the central-difference step, whichever coordinates it
// runs in (full_casing_part.hpp: the full sparse casing; modal_casing_part.hpp:
// its modes plus a static correction). Both advance
//   M_c (c_{n+1} - 2 c_n + c_{n-1}) / dt^2 + C_c (c_{n+1} - c_{n-1}) / (2 dt) + K_c c_n = F_n + R_n
// with Rayleigh damping C_c = alpha M_c + beta K_c (zero: undamped), the
// casing force F held between set_force calls (piecewise constant, SPEC §2:
// on during the first steps, then zero; a zero force costs nothing per
// step) and the contact reaction R_n entering as a correction of the
// predicted state, c_{n+1} = c~ + A_c^-1 R_n (A_c = M_c + dt/2 C_c). The
// contact rows read A_c^-1 (flexibility()); the part keeps the physical
// c_{n-1}, c_n and c_{n+1}, which the contact evaluation reads at every
// casing dof. Energy E_{n+1/2} = 1/2 v^T M_c v + 1/2 c_n^T K_c c_{n+1}, the
// step's external work F_n^T (c_{n+1} - c_{n-1}) / 2 and its damping term
// (c_{n+1} - c_{n-1})^T C_c (c_{n+1} - c_{n-1}) (divided by 4 dt by the
// integrator, with the disk's) keep their physical formulas in both.

#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "case_file.hpp"
#include "casing.hpp"
#include "reduced_contact.hpp"

namespace rsi {

class CasingPart {
public:
  virtual ~CasingPart() = default;
  CasingPart(const CasingPart&) = delete;
  CasingPart& operator=(const CasingPart&) = delete;

  int n_dofs() const { return static_cast<int>(m_c.size()); }
  bool damped() const { return m_damped; }
  /// Holds F (n_dofs() entries, [N]) as the force of every following step.
  void set_force(const Eigen::Ref<const Eigen::VectorXd>& force);
  /// F == 0 exactly (skipped in the step).
  bool force_zero() const { return m_force_zero; }
  /// c_n, c_{n-1} and c_{n+1} (predicted, then corrected) [m, rad].
  const Eigen::VectorXd& now() const { return m_c; }
  const Eigen::VectorXd& previous() const { return m_c_prev; }
  const Eigen::VectorXd& next() const { return m_c_next; }
  /// A_c^-1, dense: the casing's flexibility in the contact rows.
  const Eigen::MatrixXd& flexibility() const { return m_flexibility; }

  /// From rest under the held force: c_0 = 0, c_{-1} = dt^2/2 M_c^-1 F (with
  /// M_c itself, not A_c, so that c_1 = c_{-1}).
  virtual void start() = 0;
  /// c_{n+1} = c~, the prediction from c_n, c_{n-1} and the held force.
  virtual void predict() = 0;
  /// Zeroes the correction gathered for the step.
  virtual void clear_correction() = 0;
  /// Gathers A_c^-1 (N^T f_u on the tip's c_u + N^T f_v on its c_v), N the
  /// tip's shape values; f already carries dt^2.
  virtual void add_correction(const TipContact& tip, double f_u, double f_v) = 0;
  /// The sliding_sign law's correction f A_c^-1 N^T (e(c_u) + mu s e(c_v)), s
  /// the tip's sliding sign.
  virtual void add_sliding_correction(const TipContact& tip, double f, double mu) = 0;
  /// c_{n+1} += the gathered correction.
  virtual void apply_correction() = 0;
  /// F^T (c_{n+1} - c_{n-1}) / 2, the step's external work (asked only when
  /// the force is not zero).
  double step_external_work();
  /// (c_{n+1} - c_{n-1})^T C_c (c_{n+1} - c_{n-1}) (asked only when damped).
  double step_damping_product();
  /// c_{n-1} <- c_n <- c_{n+1}.
  virtual void advance();
  /// E_{n-1/2} of the casing [J].
  virtual double energy() const = 0;
  /// Flops of a contact-free, force-free step (reduced_integrator.hpp,
  /// casing_flops_per_step).
  virtual double flops_per_step() const = 0;

protected:
  /// Rayleigh alpha, beta checked by the caller (finite, >= 0).
  CasingPart(const Casing& casing, double dt, const RayleighDamping& damping);
  /// After set_force: what the part derives from the held force.
  virtual void force_changed() {}

  double m_dt;
  RayleighDamping m_damping;
  bool m_damped;
  Eigen::SparseMatrix<double, Eigen::RowMajor> m_kc;
  Eigen::SparseMatrix<double, Eigen::RowMajor> m_mc;
  Eigen::MatrixXd m_flexibility; ///< A_c^-1, set by the derived part
  Eigen::VectorXd m_force;       ///< held casing force F [N]
  bool m_force_zero = true;
  Eigen::VectorXd m_c, m_c_prev, m_c_next;
  Eigen::VectorXd m_work; ///< (full casing: the solve in the factor's ordering), c_{n+1} - c_{n-1}
  Eigen::VectorXd m_c_delta, m_c_damping; ///< damped: c difference, C_c times it (work)
};

} // namespace rsi

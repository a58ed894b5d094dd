#pragma once
// Central differences with forward-increment Lagrange multipliers for the
// reduced bladed disk (dense K^, M^, coordinates q) coupled through contact
// with the casing (sparse K_c, M_c): SPEC §3, written independently of the
// reference integrator. It is composed of parts that combine freely, each
// stating its equations in its header: the bladed-disk part (disk_part.hpp:
// physical coordinates, physical_disk_part.hpp, or the reduced modes,
// modal_disk_part.hpp), the casing part (casing_part.hpp: the full casing,
// full_casing_part.hpp, or its modes plus a static correction,
// modal_casing_part.hpp), and the contact solve of the friction law
// (tip_contact_solve.hpp: sliding_sign_solve.hpp, the active-set
// multipliers, or coulomb_tip_solve.hpp, CoulombGaussSeidel). M^-1 and
// M_c^-1 below are the parts' A^-1 and A_c^-1. A step:
//
//   q~ = 2 q_n - q_{n-1} - dt^2 M^-1 K^ q_n           (no external force on the disk)
//   c~ = 2 c_n - c_{n-1} + dt^2 M_c^-1 (F_n - K_c c_n)
//   lambda from the tips at the predicted state (the contact solve),
//   (q, c)_{n+1} = (q~, c~) + dt^2 (M^-1 B^qT, M_c^-1 B^cT) lambda,
// B the solve's force rows.
// The casing force F is held by the casing part (set_force) until changed.
// Energy E_{n+1/2} = sum over both parts of 1/2 v^T M v + 1/2 x_n^T K x_{n+1},
// computed when asked (its dense products would double the cost of a step).
//
// Damping (SPEC §8; ReducedDamping): C^ = diag(c) on q (modal_damping.hpp:
// 2 zeta omega_i on the kept modes, 0 on the boundary) and Rayleigh
// C_c = alpha M_c + beta K_c on the casing, both with the centred velocity
// (x_{n+1} - x_{n-1}) / (2 dt):
//   M (x_{n+1} - 2 x_n + x_{n-1}) / dt^2 + C (x_{n+1} - x_{n-1}) / (2 dt) + K x_n = F + R,
// that is, with A = M + dt/2 C (factorized once in place of M, so the
// contact flexibility W and the correction use A^-1),
//   x~ = 2 x_n - x_{n-1} - dt^2 A^-1 K x_n - dt A^-1 C (x_n - x_{n-1}) + dt^2 A^-1 F.
// Stability: the discrete energy E_{n+1/2} = 1/2 v^T (M - dt^2/4 K) v +
// 1/2 xbar^T K xbar (xbar = (x_n + x_{n+1})/2, v = (x_{n+1} - x_n)/dt) is
// positive definite iff dt < 2/omega_max, and a force-free step changes it
// by -(x_{n+1} - x_{n-1})^T C (x_{n+1} - x_{n-1}) / (4 dt) <= 0: the critical
// step stays 2/omega_max for every C >= 0, proportional or not (C^ is not
// proportional: M^ couples the modes to the boundary). That last term,
// summed step by step from the damping force the scheme applies, is W_damp:
// E = E_0 + W_ext + W_contact - W_damp to round-off. Without damping A = M
// and the step is the undamped one, operation for operation.
//
// Reduced casing (casing_basis.hpp): the modal casing part,
// modal_casing_part.hpp.
//
// Modal bladed disk (undamped runs given the reduced modes): the modal
// disk part, modal_disk_part.hpp; a damped disk, or a caller giving no
// modes, gets the physical one.
//
// Friction law (the case's operating_point.friction_law): the contact solve
// (tip_contact_solve.hpp). "sliding_sign": always sliding, as in the first
// version, operation for operation (sliding_sign_solve.hpp). "coulomb": stick and slip, rows (n, t) per tip
// solved by CoulombGaussSeidel (coulomb_tip_solve.hpp).

#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "case_file.hpp"
#include "casing_basis.hpp"
#include "casing_part.hpp"
#include "disk_part.hpp"
#include "tip_contact_solve.hpp"
#include "coulomb_gauss_seidel.hpp"
#include "critical_step.hpp"
#include "failure_kinds.hpp"
#include "history.hpp"
#include "reduced_contact.hpp"
#include "reduced_coulomb_certificate.hpp"
#include "reduced_stepper.hpp"
#include "sparse_rows.hpp"

namespace rsi {

class ReducedIntegrationError : public NumericalFailure {
public:
  using NumericalFailure::NumericalFailure;
};

/// The damping of a reduced run: empty or zero = undamped.
struct ReducedDamping {
  Eigen::VectorXd bladed_disk; ///< diag(C^), r entries >= 0 (modal_damping), or empty
  /// A full C^ (r x r, symmetric, >= 0) in place of the diagonal: the
  /// projected Rayleigh damping alpha M^ + beta K^ (case_file.hpp); or empty.
  Eigen::MatrixXd bladed_disk_matrix;
  RayleighDamping casing;      ///< alpha, beta >= 0 of the full casing
};

class ReducedIntegrator final : public ReducedStepper {
public:
  /// `contact` must outlive the integrator (not owned). Throws
  /// std::invalid_argument for a damping of the wrong size, negative or not
  /// finite, or a casing basis whose rows are not the casing's dofs,
  /// ReducedIntegrationError when M^ + dt/2 C^ or the casing's
  /// M_c + dt/2 C_c is not positive definite. `casing_basis`, when given,
  /// runs the casing in its modal coordinates (copied; see above).
  ReducedIntegrator(const ReducedBasis& basis, const Casing& casing, double dt,
                    const ReducedTipContact& contact,
                    const ReducedDamping& damping = ReducedDamping{},
                    const CasingBasis* casing_basis = nullptr,
                    const ReducedModes* disk_modes = nullptr);

  /// From rest under the casing force f0 at t = 0; f0 is held for the steps
  /// that follow until set_force changes it.
  void start(const Eigen::Ref<const Eigen::VectorXd>& casing_force);
  /// From rest under the casing force held (set_force; zero unless set).
  void start() override;
  /// The same from rest at the bladed-disk coordinates q0 (a free vibration:
  /// q_{-1} = q0 - dt^2/2 M^-1 K^ q0, so (q_1 - q_{-1}) / (2 dt) = 0).
  void start(const Eigen::Ref<const Eigen::VectorXd>& casing_force,
             const Eigen::Ref<const Eigen::VectorXd>& q0);
  /// Holds F (n_c entries, [N]) as the casing force of every following step.
  void set_force(const Eigen::Ref<const Eigen::VectorXd>& casing_force);
  /// Step n -> n+1 under the held force F_n.
  StepReport step() override;

  int step_index() const override { return m_n; }
  double time() const override { return m_n * m_dt; }
  /// The reduced coordinates q_n (formed from eta on the modal path).
  Eigen::VectorXd q() const { return m_disk->q(); }
  /// The boundary (tip) entries of q_n, (u_1, v_1, u_2, v_2, ...) in the
  /// tip polar frame [m]: the physical tip displacements (the boundary is
  /// kept physical by every reduction).
  void tip_displacement(Eigen::VectorXd& out) const { m_disk->tip_displacement(out); }
  /// Whether the disk runs in modal coordinates (undamped and asked for).
  bool modal_bladed_disk() const { return m_modal_disk; }
  const Eigen::VectorXd& casing() const { return m_casing->now(); }
  const Eigen::VectorXd& gap() const override { return m_gap; }
  /// Normal multipliers lambda_n of the last step, one per tip [N].
  const Eigen::VectorXd& lambda() const override { return m_solve->lambda(); }
  /// Tangential multipliers of the last step, one per tip [N]: the friction
  /// force on the tip along +v (counter-clockwise); the casing takes the
  /// opposite. Coulomb: the solution's lambda_t; sliding_sign: the force the
  /// law applied, -mu sign(v_slide~) lambda_n. Zero on open tips.
  const Eigen::VectorXd& tangential_lambda() const { return m_solve->tangential_lambda(); }
  /// Coulomb law: each tip's state after the last step (all open before the
  /// first step and under sliding_sign).
  const std::vector<ReducedContactState>& contact_states() const { return m_solve->states(); }
  /// Coulomb law: the certificate of the last step's problem over the tips
  /// it was solved on (all zero when no tip closed).
  const ReducedCoulombCertificate& last_certificate() const { return m_solve->certificate(); }
  FrictionLaw friction_law() const { return m_law; }
  /// Coulomb law, the last step's problem (empty when no tip closed): the
  /// tips it was solved on, in order; W over them (rows and columns (n, t)
  /// per tip) [m/N]; the predicted [g~; s~] [m]; and every tip's geometry at
  /// the predicted state (the rows B: q_u, q_v, c_u, c_v, shape). For tests.
  const std::vector<int>& coulomb_tips() const { return m_solve->solved_tips(); }
  const Eigen::MatrixXd& coulomb_w() const { return m_solve->w(); }
  const Eigen::VectorXd& coulomb_predicted() const { return m_solve->predicted_rows(); }
  const std::vector<TipContact>& predicted_tips() const { return m_solve->predicted_tips(); }
  double energy() const override;
  double initial_energy() const override { return m_initial_energy; }
  double external_work() const override { return m_external_work; }
  double contact_work() const override { return m_contact_work; }
  /// W_damp up to step n-1 [J], >= 0 (0 undamped).
  double damping_work() const override { return m_damping_work; }
  /// Flops of a contact-free, force-free step: the dense M^-1 K^ q (2 r^2),
  /// 4 r of vector updates, about 64 per tip for the gaps, sliding
  /// velocities and step report, and the casing's flops (below). Damped,
  /// also dt A^-1 C^ (q_n - q_{n-1}) (2 r^2) and about 5 r for the
  /// difference and W_damp.
  double flops_per_step() const;
  /// The casing part's (full_casing_part.hpp, modal_casing_part.hpp): the
  /// floor under every reduced run.
  double casing_flops_per_step() const { return m_casing->flops_per_step(); }

private:
  /// start(casing_force, q0) after its set_force.
  void start_at(const Eigen::Ref<const Eigen::VectorXd>& q0);
  /// Adds the contact corrections gathered by the disk and casing parts to
  /// the predicted state.
  void apply_corrections();
  /// Zeroes the corrections of a step (disk and casing).
  void clear_corrections();
  /// W_damp of the step just taken: (x_{n+1} - x_{n-1})^T C (x_{n+1} - x_{n-1}) / (4 dt)
  /// over both parts, x_{n+1} their next().
  double step_damping_work();

  /// The bladed disk: physical or modal coordinates (disk_part.hpp).
  std::unique_ptr<DiskPart> m_disk;
  bool m_modal_disk = false;
  /// The casing: full sparse or modal (casing_part.hpp).
  std::unique_ptr<CasingPart> m_casing;
  /// The contact solve of the friction law (tip_contact_solve.hpp).
  std::unique_ptr<TipContactSolve> m_solve;
  double m_dt;
  double m_mu;
  const ReducedTipContact& m_contact;
  FrictionLaw m_law;

  int m_n = 0;
  Eigen::VectorXd m_gap;
  std::vector<TipContact> m_tips;           ///< tips at the current state
  std::vector<TipContact> m_predicted;      ///< tips at the predicted state of the step
  double m_initial_energy = 0.0;
  double m_external_work = 0.0;
  double m_contact_work = 0.0;
  double m_damping_work = 0.0;
};

} // namespace rsi

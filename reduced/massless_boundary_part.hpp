#pragma once
// The rotor part of a reduced component with a massless boundary (MacNeal:
// M^_BB = 0, M^_BI = 0, C^_BB = 0): scheme 2 of component_integrator.hpp,
// NLstep's leapfrog (component_rotor_part.hpp).
//    Split x = (u_B, q_I). The boundary rows of (*) lose their inertia and
//    become a static balance at every time level,
//      K^_BB u_B^n + K^_BI q_I^n = B_B^T lambda_n + f_B(t_n),           (B)
//    the interior rows stay explicit,
//      A_I (q_I^{n+1} - 2 q_I^n + q_I^{n-1}) = -dt^2 (K^_II q_I^n + K^_IB u_B^n - f_I(t_n))
//                                              - dt C^_I (q_I^n - q_I^{n-1}),   (I)
//    A_I = M^_II + dt/2 C^_I (B_I = 0: contact acts on the boundary only).
//    f_B, f_I: the boundary and interior rows of f. A force on the boundary
//    rows has no mass to accelerate: it enters the static balance (B) at
//    the same time level as lambda_n, u_B^n = -S K^_BI q_I^n + S B_B^T
//    lambda_n + S f_B(t_n), S = K^_BB^-1 (the boundary jumps with the load,
//    as a massless node does); the contact is solved against it.
//    In (I) the code uses (B) to write K^_II q_I^n + K^_IB u_B^n =
//    K_c q_I^n + K^_IB S B_B^T lambda_n + K^_IB S f_B(t_n), K_c = K^_II -
//    K^_IB S K^_BI the condensed stiffness (the same numbers in exact
//    arithmetic, fewer flops): the interior sees f_I - K^_IB S f_B.
//    The step n -> n+1 (NLstep's leapfrog, Monjaraz-Tec, Gross, Krack,
//    Comput. Struct. 260 (2022) 106698: explicit on the modes, static
//    condensation of the boundary with the contact solved on it):
//      q_I^{n+1} from (I), with u_B^n of the previous step's balance;
//      u~_B = -S K^_BI q_I^{n+1} + S f_B(t_{n+1}),   S = K^_BB^-1 (Cholesky once; for
//             MacNeal's CCM coordinates S = R_B, the residual flexibility,
//             and -S K^_BI = Phi_1B: the kept modes' boundary motion);
//      u_B^{n+1} = u~_B + S B_B^T lambda_{n+1}, lambda_{n+1} from the
//             contact at time n+1: [g; s] = [g~; s~] + W lambda_{n+1},
//      W = B_B S B_B^T  (a COMPLIANCE [length/force]: the condensed static
//             flexibility of the boundary; no dt^2 M^-1 anywhere),
//    g~, s~ at u~_B (rigid_casing_part.hpp; the slip increment is relative to u_B^n).
//    (B) then holds at n+1 to round-off, and (I) at n+1 uses the balanced
//    u_B^{n+1}: the pair is (*) at every n, with lambda_n paired with x_n.
//    Stable step without contact: eliminating u_B with (B) at lambda = 0
//    leaves q_I'' + C q_I' + (K^_II - K^_IB S K^_BI) q_I = 0, whose largest
//    eigenvalue (M^_II = I) is omega_max^2 of reduced/critical_step (for
//    MacNeal the condensed stiffness is Omega_1^2: omega_max = omega_psi),
//    so dt < 2/omega_psi: what ComponentIntegrator checks. Caveat: a CLOSED
//    contact constrains u_B (its normal; in stick also its tangents), and
//    the interior then sees the constrained condensation, stiffer than the
//    free one (the infinite eigenvalues of the massless boundary come down
//    when u_B is held; all of u_B held, K^_II = Omega^2 + Phi_1B^T R_B^-1
//    Phi_1B for MacNeal). A long closed contact can thus be unstable at a
//    step the free modes allow; run_component's energy monitor reports it.
//    Measured (bench_component_rubbing, bench/RESULTS.md), Rotor 37
//    MacNeal-50: 2/omega of the interior 1.70e-5 s free, 1.63e-5 s with the
//    16 normals held, 1.03e-5 s with the whole boundary held, against the
//    README's 4.675e-6 s.
// The massless boundary's rows of M^, C^ vanish, so the energy identity of
// component_integrator.hpp holds for either choice of the start's u_B^{-1};
// start() takes the contact-free, load-free balance -S K^_BI q_I^0 (the
// structure at rest before t = 0; the load f(0) and the contact act from
// t = 0 on: u~_B^0 = u_B^{-1} + S f_B(0), its slip relative to u_B^{-1},
// and start_balance() puts lambda_0 into u_B^0).
// Costs per contact-free step (dense): 2 (psi^2 + psi n_B) (+ 3 psi damped,
// M^_II = I); a step with a closing contact adds 2 r 3 nc.

#include <Eigen/Core>

#include "component_rotor_part.hpp"

namespace rsi {

class MasslessBoundaryPart final : public ComponentRotorPart {
public:
  /// rows: B_B (3 nc x n_B). Throws std::invalid_argument when M^_BB, M^_BI
  /// are not exactly zero or C^ is not zero on the boundary, and
  /// ComponentIntegrationError when K^_BB or A_I is not positive definite.
  MasslessBoundaryPart(const ReducedBasis& basis, const ComponentIntegratorOptions& options,
                       const Eigen::MatrixXd& rows);

  bool contact_at_next_level() const override { return true; }
  /// q_I^0 from q0, u_B^{-1} = -S K^_BI q_I^0, u~_B^0 = u_B^{-1} (+ S f_B(0)).
  void start(const Eigen::Ref<const Eigen::VectorXd>& q0) override;
  /// u_B^0 = u~_B^0 + S B_B^T lambda_0 and q_I^{-1} at rest under it.
  void start_balance(const Eigen::VectorXd& lambda0) override;
  void predict(const Eigen::VectorXd& lambda, double t_n, double t_next) override;
  const Eigen::VectorXd& trial_boundary() const override { return m_un; }
  const Eigen::VectorXd& boundary() const override { return m_u; }
  void correct(const Eigen::VectorXd& lambda) override;
  Eigen::VectorXd boundary_increment() const override { return m_un - m_up; }
  void add_step_work() override;
  void advance() override;
  bool finite() const override { return m_x.allFinite(); }
  Eigen::VectorXd q() const override;

private:
  void state_in_basis(Eigen::VectorXd& x, Eigen::VectorXd& xp) const override;

  int m_nc = 0;
  Eigen::MatrixXd m_g;             ///< the correction per unit lambda, S B_B^T (n_B x 3 nc)
  Eigen::VectorXd m_ci;            ///< diag C^ on the interior coordinates (damped)
  Eigen::MatrixXd m_p;             ///< dt^2 A_I^-1 K_c
  Eigen::MatrixXd m_pb;            ///< dt^2 A_I^-1 K^_IB S B_B^T (psi x 3 nc)
  Eigen::MatrixXd m_d;             ///< dt A_I^-1 C^_I (damped, M^_II not diagonal)
  Eigen::VectorXd m_d_diagonal;    ///< with diagonal M^_II: dt A_I^-1 C^_I as a vector
  Eigen::MatrixXd m_z;             ///< -S K^_BI (n_B x psi)
  Eigen::VectorXd m_x, m_xp, m_xn; ///< q_I^n, q_I^{n-1}, q_I^{n+1}
  Eigen::VectorXd m_u, m_up, m_un; ///< u_B^n, u_B^{n-1}; u~_B, then u_B^{n+1}
  Eigen::VectorXd m_work_b;        ///< q_I^{n+1} - q_I^{n-1} (damped)
  /// The force's correction per step: dt^2 A_I^-1 (f_I - K^_IB S f_B) of
  /// f0, f1 (psi); S f_B of f0, f1 (n_B).
  Eigen::VectorXd m_gf0, m_gf1, m_sf0, m_sf1;
};

} // namespace rsi

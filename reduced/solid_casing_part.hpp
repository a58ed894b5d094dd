#pragma once
// The flexible 3D casing as a reduced component's casing part
// (component_casing_part.hpp; issue 27 items 3 and 4, SPEC §9 "Flexible
// casing in 3D"): the reduced solver's own tip/casing law, written from the
// SPEC and not from reference/contact, and the casing's own modal step.
//
// The casing. c = Phi p, Phi the casing basis of casing_basis.hpp (the
// lowest modes of the clamped casing plus a static correction for its
// load; Phi^T M_c Phi = I, Phi^T K_c Phi = diag(omega^2)), undamped. Its
// central-difference step, mode by mode, with the load F on the casing
// dofs and the contact's generalized force H^T lambda,
//   p_{n+1} = 2 p_n - p_{n-1} + dt^2 (s_n Phi^T F - omega^2 p_n + H_n^T lambda_n),
// started from rest (p_0 = 0, p_{-1} = dt^2/2 s_0 Phi^T F), s_n = 1 on the
// steps with t_n <= duration (a millionth of a step allowed), 0 after: the
// full-order run's rule (problem.hpp, ProblemForcing), so that at the same
// step both apply the same impulse (every mode kept: the same run to
// round-off); at their own steps the impulses F (t_N + dt/2) differ by at
// most dt F, 5.7e-4 of the CI case's at its CB step of 1.1e-7 s over
// 2e-4 s. Energy and works of the identity of central
// differences, multiplied by (p_{n+1} - p_{n-1})/2:
//   E_{n+1/2} = 1/2 |p_{n+1} - p_n|^2 / dt^2 + 1/2 p_n^T diag(omega^2) p_{n+1},
//   W_ext += s_n F^T Phi (p_{n+1} - p_{n-1})/2,
//   W_contact += lambda_n^T H_n (p_{n+1} - p_{n-1})/2.
//
// The law. The rotor turns at Omega about z; the tips' displacements are in
// its frame, which is the casing's at t = 0. Tip c (undeformed radius r_c,
// angle phi_c, height z_c; frame rows e_n = -e_r(phi_c), e_t1 = z,
// e_t2 = e_q(phi_c): rigid_casing.hpp) sits at time t at the casing's polar
// angle theta = phi_c + Omega t, above the point (face, xi, eta, rho) of
// the casing surface on the ray at theta and z_c (casing_surface.hpp, the
// model's geometry). With e_r(a) = (cos a, sin a, 0), e_q(a) = (-sin a,
// cos a, 0), N_i the face's shape functions and u_i its nodes' casing
// displacements (Phi's rows at their ux, uy, uz; none for a clamped node),
// the casing's surface point moves by u(xi, eta) = sum N_i u_i, and
//   g_c = rho - r_c + e_n . u_tip + e_r(theta) . u(xi, eta)
//         (the surface point's radius minus the tip's: > 0 open),
//   s_c = [z; e_q(phi_c)] du_tip - [z; e_q(theta)] du(xi, eta) + (0, r_c Omega dt)
//         (the tip's increment over the step relative to the casing's
//         material point under it, plus the casing passing by at r_c Omega).
// So the casing's rows of contact c in p are
//   H_c = sum_i N_i [e_r(theta); -z; -e_q(theta)] Phi_i   (3 x m),
// Phi_i the rows of node i's ux, uy, uz; the tip's are B_c (the rigid
// casing's frame on u_B). The point is located at t_{n+1} for the step to
// t_{n+1} (small displacements: the undeformed tip and surface locate it),
// so the step's problem is linear in the correction:
//   [g; s] = [g~; s~] + (W_rotor + dt^2 H H^T) lambda,
// g~ = rho - r + B_n u~_B + H_n p~, s~ = B_t (u~_B - u_B^n) + H_t (p~ - p_n)
// + (0, r Omega dt) at the rotor's trial boundary and the casing's free step
// p~ = 2 p_n - p_{n-1} + dt^2 (s_n Phi^T F - omega^2 p_n). The casing's
// share of W, dt^2 H H^T (its inverse mass is I in p), changes every step
// (the tips move over the casing): flexibility_rows() gives H to the
// contact solve, which forms the closed contacts' part of it only
// (coulomb_node_solve.hpp); add_flexibility() forms the whole.
// With a massless rotor boundary (MacNeal) the solved lambda is the
// rotor's lambda_{n+1} in static balance with u_B^{n+1} and the casing's
// lambda_n of the step above: the gap at t_{n+1} is closed in both parts
// by the same multiplier, each part's energy identity exact in its own
// terms (component_integrator.hpp).
//
// Units: the model's (N, mm, t, s). Owns copies of its data.

#include <array>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "casing_basis.hpp"
#include "casing_surface.hpp"
#include "component_casing_part.hpp"
#include "rigid_casing_part.hpp"

namespace rsi {

/// The casing's load: F on its dofs (empty: none) over [0, duration].
struct SolidCasingLoad {
  Eigen::VectorXd force;
  double duration = 0.0; ///< [s]
};

class SolidCasingPart final : public ComponentCasingPart {
public:
  /// tips: the tips' frames and boundary indices about z with a constant
  /// zero gap, Omega its omega and sliding omega (rigid_casing.hpp);
  /// n_boundary, dt as RigidCasingPart's. surface: the casing's contact
  /// surface; casing_dofs: its deck node id -> the rows of Phi of its ux,
  /// uy, uz (-1: clamped; a node absent: clamped). basis: Phi (the casing's
  /// dofs x m) and omega^2. load: F with as many entries as Phi has rows
  /// (or none), duration >= 0. Throws std::invalid_argument naming the
  /// argument, and ComponentIntegrationError when a tip at t = 0 is above
  /// no face of the surface.
  SolidCasingPart(const RigidCasing& tips, int n_boundary, double dt, CasingSurface surface,
                  std::map<int, std::array<int, 3>> casing_dofs, const CasingBasis& basis,
                  SolidCasingLoad load);

  const RigidCasing& tips() const override { return m_tips.tips(); }
  const Eigen::MatrixXd& rows() const override { return m_tips.rows(); }
  void start() override;
  void predict(const Eigen::VectorXd& u_trial, const Eigen::VectorXd& u_now, double t_n,
               double t_next) override;
  const Eigen::VectorXd& prediction() const override { return m_pred; }
  bool flexible() const override { return true; }
  /// w += dt^2 H H^T of the last prediction (w symmetric on entry; only
  /// its lower triangle is read).
  void add_flexibility(Eigen::MatrixXd& w) const override;
  /// &H, nullptr while the casing is held (t = 0).
  const Eigen::MatrixXd* flexibility_rows() const override { return m_held ? nullptr : &m_h; }
  /// p_{n+1} = p~ + dt^2 H^T lambda; the step's works.
  void correct(const Eigen::VectorXd& lambda) override;
  void advance() override;
  void gaps_at(const Eigen::VectorXd& u_boundary, double t) override;
  const Eigen::VectorXd& gap() const override { return m_gap; }
  /// rho - r_c at time t.
  double rest_gap(int c, double t) const override;
  double energy() const override;
  double external_work() const override { return m_external_work; }
  double contact_work() const override { return m_contact_work; }
  bool finite() const override { return m_p.allFinite(); }
  /// sqrt(max omega_i^2).
  double omega_max() const override;

  /// p_n, the casing's modal coordinates.
  const Eigen::VectorXd& modal_state() const { return m_p; }
  /// p~ of the last prediction.
  const Eigen::VectorXd& trial_state() const { return m_p_trial; }
  /// H of the last located time (3 nc x m).
  const Eigen::MatrixXd& casing_rows() const { return m_h; }
  /// s_n: 1 while the load acts at step n, else 0 (and 0 without a load).
  double load_share(long n) const;

private:
  /// rho_c and H at time t, for every tip (once per time).
  void locate(double t);
  /// [e_r(theta); -z; -e_q(theta)] of tip c at time t.
  Eigen::Matrix3d casing_directions(int c, double t) const;

  RigidCasingPart m_tips; ///< the tips' side: B_B, B_B u~, and (0, r Omega dt)
  double m_dt;
  double m_omega;
  int m_nc, m_m;
  CasingSurface m_surface;
  std::map<int, std::array<int, 3>> m_casing_dofs;
  Eigen::MatrixXd m_phi;           ///< Phi, the casing's dofs x m
  Eigen::VectorXd m_omega_squared; ///< omega_i^2
  Eigen::VectorXd m_force_modal;   ///< Phi^T F (empty: no load)
  double m_duration = 0.0;
  long m_n = 0; ///< the casing's level
  Eigen::VectorXd m_p, m_p_prev, m_p_trial, m_p_next;
  bool m_held = false; ///< the last prediction held the casing (t = 0)
  double m_located_t = -1.0;
  std::vector<double> m_rho; ///< rho_c at m_located_t
  std::vector<int> m_face;   ///< each tip's face at m_located_t: the next search's hint
  Eigen::MatrixXd m_h;       ///< H at m_located_t
  Eigen::VectorXd m_pred, m_gap;
  double m_external_work = 0.0, m_contact_work = 0.0;
};

} // namespace rsi

#pragma once
// The 2D tip/ring contact of SPEC §2 as a FrictionalContactLaw
// (frictional_contact_law.hpp): the geometry of TipCasingContact
// (tip_casing_contact.hpp), with a tangential row and a slip increment in
// place of its sign-only friction direction, for Coulomb friction with
// stick and slip (issue 12 items 1-2). On the system dof vector
// [bladed disk; casing].
//
// For the step t_n -> t_{n+1} = t_next with u_n and the prediction u~,
// tip k at the predicted fixed-frame angle
//   alpha~_k = alpha_k0 + Omega t_{n+1} + v~_k / R_t,
// in casing element e at xi with Hermite values N (ring_element.hpp):
//   g~_k = R_c + N . (u, u_s)~_e - (R_t + u~_k)                 (> 0 open)
//   s~_k = Omega (R_t + u~_k) dt + (v~_k - v_n,k) - N . ((v, v_s)~_e - (v, v_s)_n,e)
//          the tangential increment of the tip over the casing point it
//          faces, over the step: the rotation carries the tip by
//          Omega (R_t + u) dt, its own tangential displacement and the
//          casing's at that point (fixed alpha~) move in the same sense.
//   G_k: -1 on tip u_k, +N on the casing u, u_s (as TipCasingContact);
//   T_k: +1 on tip v_k, -N on the casing v, v_s (the derivative of s~ in
//        the tangential dofs: TipCasingContact's T with the opposite sign).
// The force on the structures is lambda_n G^T + lambda_t T^T: lambda_n > 0
// pushes the tip inward and the casing outward; slip lambda_t = -mu lambda_n
// sign(s) drags the tip against its sliding and the casing along it.
//
// Which sliding rate, and why: the increment over the step, (u~ - u_n) and
// after correction (u_{n+1} - u_n), i.e. the forward rate (u_{n+1} - u_n)/dt.
// It is the quantity the per-step problem can make zero (stick: the tip
// does not move over the casing during the step), it is linear in the
// correction (s = s~ + T du), and it is the rate the central-difference
// energy balance pairs the contact force with over the step. The central
// rate (u_{n+1} - u_{n-1})/2dt would make stick depend on the previous step.
//
// Linearisation: as for G, the dependence of alpha on v (the point of the
// casing the tip faces) is kept in g~ and s~ but not in the rows, and the
// term Omega u~_k dt of s~ (1.5e-4 of u_k per step on the default case) is
// not in T, so the friction force stays tangential. Units SI.

#include <vector>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "frictional_contact_law.hpp"

namespace rsi {

class TipRingFrictionalContact : public FrictionalContactLaw {
public:
  /// Keeps copies of what it needs; the casing dofs start at
  /// bladed_disk.n_dofs() in the system vector; mu and Omega from the case.
  TipRingFrictionalContact(const BladedDisk& bladed_disk, const Casing& casing, const Case& c);

  int n_contacts() const override { return static_cast<int>(m_tip_radial.size()); }
  int n_tangents() const override { return 1; }
  double friction_coefficient() const override { return m_mu; }
  /// current, predicted: same size, holding every dof of dofs_read();
  /// t_next finite; dt > 0 finite. Throws std::invalid_argument otherwise.
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& current,
                const Eigen::Ref<const Eigen::VectorXd>& predicted, double t_next, double dt,
                FrictionalContactGeometry& out) const override;
  /// The tip u and v of every blade and the u, u_s, v, v_s of every casing
  /// node that is not clamped.
  std::vector<int> dofs_read(int n_dofs) const override;

private:
  std::vector<int> m_tip_radial;
  std::vector<int> m_tip_tangential;
  std::vector<double> m_tip_angle0;
  std::vector<int> m_casing_node_dof; ///< system index of node j's u, or -1 if clamped
  int m_casing_elements;
  double m_tip_radius;
  double m_casing_radius;
  double m_omega;
  double m_mu;
};

} // namespace rsi

#pragma once
// Contact of the blade tips with the casing (SPEC §2, kinematics of
// contact), on the system dof vector [bladed disk; casing].
//
// Tip k sits at the fixed-frame angle alpha_k = alpha_k0 + Omega t + v_k/R_t
// (alpha_k0: polar angle of the undeformed tip). With xi its position in
// the casing element e that holds it and N(xi) the Hermite shape values
// (ring_element.hpp), u_c(alpha) = N . (u, u_s) of the element's nodes and
//   g_k = R_c + u_c(alpha_k) - (R_t + u_k),        > 0 open;
//   G_k: -1 on tip u_k, +N on the casing u, u_s of element e;
//   T_k: -1 on tip v_k, +N on the casing v, v_s of element e;
//   D_k = G_k + mu s_k T_k, s_k = sign of the sliding velocity
//   Omega (R_t + u_k) + v_k' - v_c'(alpha_k) of the tip over the casing.
// lambda_k D_k^T pushes the tip inward and the casing outward, and drags the
// tip back and the casing forward along the sliding (Coulomb, |f_t| = mu lambda).
// The dependence of alpha on v_k is kept in the gap, not in G (SPEC §3).

#include <vector>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "contact_law.hpp"

namespace rsi {

class TipCasingContact : public ContactLaw {
public:
  /// Keeps copies of what it needs from the parts; the casing dofs start at
  /// bladed_disk.n_dofs() in the system vector.
  TipCasingContact(const BladedDisk& bladed_disk, const Casing& casing, const Case& c);

  int n_constraints() const override { return static_cast<int>(m_tip_radial.size()); }
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& x,
                const Eigen::Ref<const Eigen::VectorXd>& v, double t,
                ContactState& s) const override;
  double friction_coefficient() const override { return m_mu; }
  /// The tip u and v of every blade and the u, u_s, v, v_s of every casing
  /// node that is not clamped (a tip may meet any casing element).
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

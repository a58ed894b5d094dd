#pragma once
// The rigid casing part of a reduced component's integration
// (component_integrator.hpp): the contact rows on the boundary coordinates
// and the gaps and slips they see, over the casing geometry of
// rigid_casing.hpp. The contact rows of node c are B_c = F_c P_c (F_c the
// rigid casing's frame rows e_n, e_t1, e_t2; P_c picks its ux, uy, uz from
// the boundary coordinates u_B), B_B = [B_1; ...; B_nc] (3 nc x n_B).
// At a trial boundary displacement u~_B of the step t_n -> t_{n+1}, from u_B^n,
// the predicted gaps and slips per contact are
//   g~_c = g(t_{n+1}) + e_n . u~_c,  s~_c = [e_t1; e_t2](u~_c - u_c^n) + (0, r_c Omega dt)
// (rigid_casing.hpp), stacked per contact as [g~_c; s~_c] (3 nc entries);
// the gap at a boundary displacement u_B is g_c(t) = g(t) + e_n . u_c.
// B_B is 3 x 3 blocks (the frames) on each node's ux, uy, uz: it is
// applied block by block (about 30 nc flops for the gaps and slips).

#include <array>

#include <Eigen/Core>

#include "component_casing_part.hpp"
#include "rigid_casing.hpp"

namespace rsi {

class RigidCasingPart final : public ComponentCasingPart {
public:
  /// `casing` is copied. n_boundary: the basis' boundary coordinates; dt [s]
  /// the step of the slip. Throws std::invalid_argument when a contact
  /// node's boundary index is not below n_boundary.
  RigidCasingPart(const RigidCasing& casing, int n_boundary, double dt);

  const RigidCasing& tips() const override { return m_casing; }
  /// B_B, 3 nc x n_B.
  const Eigen::MatrixXd& rows() const override { return m_b; }
  /// [g~; s~] at the trial u~_B, from u_B^n, for the step to t_next.
  void predict(const Eigen::VectorXd& u_trial, const Eigen::VectorXd& u_now, double t_n,
               double t_next) override;
  /// The last prediction, 3 nc entries (g~, s~_t1, s~_t2 per contact).
  const Eigen::VectorXd& prediction() const override { return m_pred; }
  /// g_c at u_B and t into gap().
  void gaps_at(const Eigen::VectorXd& u_boundary, double t) override;
  /// The last gaps, nc entries (zeros before the first gaps_at).
  const Eigen::VectorXd& gap() const override { return m_gap; }
  /// g(t, phi_c) - growth_c.
  double rest_gap(int c, double t) const override { return m_casing.imposed_gap(c, t); }

private:
  /// Contact node c's ux, uy, uz from the boundary coordinates.
  Eigen::Vector3d node_of(const Eigen::VectorXd& u_boundary, int c) const;

  RigidCasing m_casing;
  double m_dt;
  int m_nc;
  Eigen::MatrixXd m_b; ///< B_B: 3 nc x n_B, the contact rows on u_B
  Eigen::VectorXd m_pred, m_gap;
};

} // namespace rsi

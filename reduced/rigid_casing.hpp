#pragma once
// A rigid casing seen from the rotating blade (issue 12 item 1, the reduced
// side's own 3D node-to-rigid-surface geometry, written from
// ../shared/external/rotor37/README.md and not from reference/contact).
//
// Axis coordinates. The rotation axis a (unit, through the origin; z by
// default) completes a right-handed orthonormal basis (b_1, b_2, a): b_1 is
// the coordinate axis next, in the cycle x -> y -> z -> x, to the one a is
// nearest (first of the largest |a_k|), minus its part along a, and
// b_2 = a x b_1 (about z: b_1 = x, b_2 = y; about x: b_1 = y, b_2 = z).
// The rows of Q = [b_1; b_2; a] take a point to axis coordinates
// (s_1, s_2, s_3) = Q x_c.
// Per contact node c (undeformed position x_c, polar radius
// r_c = |(s_1, s_2)|, polar angle phi_c = atan2(s_2, s_1)), a fixed
// orthonormal contact frame, written in axis coordinates and taken back by Q^T:
//   e_n  = Q^T (-s_1, -s_2, 0) / r_c (inward: a displacement along e_n opens the gap)
//   e_t1 = Q^T (0, 0, 1) = a         (axial)
//   e_t2 = e_n x e_t1 = Q^T (-sin phi, cos phi, 0)   (the counter-clockwise tangent about a)
// stored as the rows of F_c = [e_n; e_t1; e_t2]. About z, Q = I and
// e_n = -(x, y, 0) / r_c, phi_c = atan2(y, x).
//
// Normal gap. The casing surface lies at g(t) from the undeformed node
// along -e_n (outward); a displacement u_c of the node moves it by -e_n.u_c
// towards the casing, so the gap is
//   g_c(t, u) = g(t, phi_c) - growth_c + e_n . u_c   (g > 0 open, g < 0 penetration)
// (growth_c: the node's static radial growth under rotation effects, u
// measured from that deflected state; none without them)
// and a normal multiplier lambda_n >= 0 acts on the node as the force
// lambda_n e_n (pushing it inward, which opens the gap: the Signorini sign
// W_nn > 0 of the per-step problem).
// Imposed gap g(t, phi), one of
//   constant: g(t) = g_0;
//   linear:   g(t) = g_0 - v t (a plane approaching at speed v; tests);
//   oval:     g(t) = g_m (1 - 2 exp(-((mod(theta, pi)/pi - 1/2)/w)^2)),
//             theta = Omega t + phi_c, w = 0.15 (the README's oval casing:
//             the gap closes to -g_m twice a revolution).
//
// Sliding. A blade turning at Omega (signed, > 0 counter-clockwise about
// e_z) sees the casing move at -r_c Omega e_t2. The casing's sliding speed
// is kept apart from the gap phase: Omega_s = Omega in that physical case,
// Omega_s = -Omega for NLstep's PLAUSIBLE set-up (gap phase Omega t + phi,
// relative sliding of the tip -r Omega e_t2: its gap velocity
// u_b' + (g', 0, -r Omega) in (n, t1, t2); shared/external/rotor37/README.md).
// The slip increment of node c over the step t_n -> t_{n+1}, relative to
// the casing, in the tangent frame (t1, t2):
//   s_c = [e_t1; e_t2] (u_c^{n+1} - u_c^n) + (0, r_c Omega_s dt)
// (the node's displacement increment minus the casing's, -r_c Omega_s dt e_t2).
// Coulomb's law then opposes s_c: lambda_t = -mu lambda_n s_c/|s_c| in slip,
// so a fast casing (r Omega dt >> the node's own increment) drags the node
// along -e_t2 with lambda_t2 = -mu lambda_n.
//
// Units: those of the component (N, mm, t, s for the 3D blades): x, g in
// its length unit, Omega in rad/s, t in s.
// Owns its data (copies of the coordinates and frames).

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "component.hpp"

namespace rsi {

enum class CasingGapKind { constant, linear, oval };

struct CasingGap {
  CasingGapKind kind = CasingGapKind::constant;
  double g0 = 0.0;     ///< constant, linear: g(0); oval: g_m > 0 [length]
  double rate = 0.0;   ///< linear: v [length/s], finite
  double width = 0.15; ///< oval: w in (0, 1)
};

class RigidCasing {
public:
  /// `positions[c]`: node c's coordinates; `boundary_index[c]`: the index of
  /// its ux, uy, uz in the component's boundary list (the order of
  /// ReducedBasis::boundary_position). omega: rotation speed of the gap
  /// phase [rad/s], finite, signed; sliding_omega: Omega_s of the header,
  /// finite (0: the casing does not slide). axis: a of the header, finite
  /// and nonzero (normalised here). Throws std::invalid_argument for a node
  /// on the axis (r_c = 0), a gap out of range, sizes that do not match, a
  /// zero or non-finite axis, or a repeated or negative boundary index.
  /// growth: per contact, the static radial growth under rotation effects
  /// (finite), subtracted from g; empty: none.
  RigidCasing(const std::vector<Eigen::Vector3d>& positions,
              const std::vector<std::array<int, 3>>& boundary_index, const CasingGap& gap,
              double omega, double sliding_omega,
              const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ(),
              std::vector<double> growth = {});
  /// The physical case: Omega_s = Omega.
  RigidCasing(const std::vector<Eigen::Vector3d>& positions,
              const std::vector<std::array<int, 3>>& boundary_index, const CasingGap& gap,
              double omega)
      : RigidCasing(positions, boundary_index, gap, omega, omega) {}

  int n_contacts() const { return static_cast<int>(m_frame.size()); }
  /// Rows e_n, e_t1, e_t2 of contact c.
  const Eigen::Matrix3d& frame(int c) const { return m_frame[c]; }
  const std::array<int, 3>& boundary_index(int c) const { return m_index[c]; }
  double radius(int c) const { return m_radius[c]; }
  double polar_angle(int c) const { return m_phi[c]; }
  /// s_3 = a . x_c, the node's undeformed axial coordinate [length].
  double axial_coordinate(int c) const { return m_axial[c]; }
  double omega() const { return m_omega; }
  double sliding_omega() const { return m_sliding_omega; }
  const CasingGap& gap_law() const { return m_gap; }
  /// g(t, phi_c) - growth_c [length].
  double imposed_gap(int c, double t) const;
  /// The casing's displacement over a step of dt, in c's tangent frame,
  /// negated: the (t1, t2) term added to the node's increment, (0, r_c Omega_s dt).
  double casing_slip(int c, double dt) const { return m_radius[c] * m_sliding_omega * dt; }

private:
  double shape_gap(int c, double t) const; ///< g(t, phi_c)

  std::vector<Eigen::Matrix3d> m_frame;
  std::vector<std::array<int, 3>> m_index;
  std::vector<double> m_radius;
  std::vector<double> m_phi;
  std::vector<double> m_axial;
  CasingGap m_gap;
  std::vector<double> m_growth;
  double m_omega = 0.0;
  double m_sliding_omega = 0.0;
};

/// The rigid casing over the contact nodes `node_ids` of a component whose
/// boundary holds their ux, uy, uz (3D solid nodes, CalculiX directions
/// 1..3), about the component's rotation_axis. Throws std::invalid_argument naming the node when it
/// has no coordinates, or one of its three translations is not a boundary dof. sliding_omega:
/// Omega_s of the header (omega in the physical case). growth: as RigidCasing's.
RigidCasing rigid_casing_of(const Component& component, const std::vector<int>& node_ids,
                            const CasingGap& gap, double omega, double sliding_omega,
                            std::vector<double> growth = {});
inline RigidCasing rigid_casing_of(const Component& component, const std::vector<int>& node_ids,
                                   const CasingGap& gap, double omega) {
  return rigid_casing_of(component, node_ids, gap, omega, omega);
}

/// The rotor37 README's oval casing: g_m = 0.356 mm, w = 0.15.
inline CasingGap oval_casing_gap(double g_m = 0.356) {
  return {CasingGapKind::oval, g_m, 0.0, 0.15};
}

} // namespace rsi

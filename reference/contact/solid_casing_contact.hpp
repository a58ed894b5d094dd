#pragma once
// Blade tips against a flexible solid casing in 3D (issue 27 item 3; SPEC §9
// "Flexible casing in 3D"): the reference solver's law. The rotor turns at
// Omega about z (> 0 counter-clockwise); its displacements are in its own
// frame, which coincides with the casing's at t = 0. The casing is at rest,
// its contact surface the 6-node faces of casing_surface.hpp.
//
// Per tip c, from its undeformed position X_c in the rotor's frame: radius
// r_c = |(X_x, X_y)| > 0, angle phi_c = atan2(X_y, X_x), height Z_c. At
// time t it sits at the polar angle theta_c = phi_c + Omega t of the casing,
// above the point of the face that casing_surface locates there (face f,
// (xi, eta), distance rho from the axis; N_i the face's shape functions,
// u_i its nodes' displacements, 0 for a clamped node). The frames, with
// e_r(a) = (cos a, sin a, 0), e_q(a) = (-sin a, cos a, 0):
//   tip (rotor frame)   e_n = -e_r(phi_c), e_t1 = z, e_t2 = e_q(phi_c)
//   casing (its frame)  the same directions at theta_c: -e_r(theta_c), z,
//                       e_q(theta_c)   (the rotor's frame turned by Omega t)
//   gap      g_c = rho - r_c - growth_c + e_n . u_tip - (-e_r(theta_c)) . u(xi, eta)
//            (> 0 open: the casing's surface point's radius minus the
//            tip's; a tip moving inward or the casing outward opens it)
//   slip     over the step t_n -> t_{n+1}, the tip's increment relative to
//            the casing's material point under it, in (t1, t2), plus the
//            rotation's sliding r_c Omega dt along e_t2 (the tip passes the
//            casing counter-clockwise for Omega > 0, as RigidSurfaceContact
//            with Omega_s = Omega):
//            s~_c = (z . (du_tip - du(xi, eta)),
//                    e_q(phi_c) . du_tip - e_q(theta_c) . du(xi, eta) + r_c Omega dt)
//   rows     B_c = the tip's 3 dofs with e_n, z, e_q(phi_c), and each face
//            node's 3 dofs with -N_i times the casing's directions: the
//            force B_c^T lambda on the tip is the opposite of the sum on the
//            face's nodes (sum N_i = 1).
// The face and (xi, eta) are those at t_{n+1} (the tip's angle then; small
// displacements: the undeformed surface and tip positions locate it), so
// g and s of u~ + du are g~ + G du and s~ + T du exactly.
//
// Units: the model's (mm, s, rad/s). Owns copies of its data.

#include <array>
#include <map>
#include <vector>

#include "casing_surface.hpp"
#include "frictional_contact_law.hpp"
#include "rigid_surface_contact.hpp"

namespace rsi {

class SolidCasingContact : public FrictionalContactLaw {
public:
  /// tips: at least one, dofs >= 0 and distinct, positions finite with r > 0,
  /// each above the surface (its height within the surface's axial extent:
  /// located at t = 0); growth finite. casing_dofs: the casing's deck node id
  /// -> system dofs (ux, uy, uz), distinct from the tips' and each other's;
  /// a face node absent is clamped (no dof). omega finite, mu >= 0 finite. Throws
  /// std::invalid_argument naming the parameter and its range.
  SolidCasingContact(std::vector<RigidSurfaceNode> tips, CasingSurface surface,
                     std::map<int, std::array<int, 3>> casing_dofs, double omega, double mu);

  int n_contacts() const override { return static_cast<int>(m_tips.size()); }
  int n_tangents() const override { return 2; }
  double friction_coefficient() const override { return m_mu; }
  /// current, predicted: same size, every dof of the rows inside; t_next
  /// finite; dt > 0 finite. Throws std::invalid_argument otherwise, and
  /// std::runtime_error when a tip's ray misses the surface.
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& current,
                const Eigen::Ref<const Eigen::VectorXd>& predicted, double t_next, double dt,
                FrictionalContactGeometry& out) const override;
  /// The tips' dofs and every casing dof of the map.
  std::vector<int> dofs_read(int n_dofs) const override;

  /// The point of the surface above tip c at time t.
  SurfacePoint point(int contact, double t) const;
  /// The gap of tip c at time t with no displacement, rho - r_c - growth_c.
  double rest_gap(int contact, double t) const;
  /// r_c, the tip's distance from the axis.
  double radius(int contact) const { return m_tips.at(static_cast<size_t>(contact)).radius; }
  const CasingSurface& surface() const { return m_surface; }

private:
  struct Tip {
    RigidSurfaceNode node;
    double radius = 0.0, angle = 0.0;
  };
  std::vector<Tip> m_tips;
  CasingSurface m_surface;
  std::map<int, std::array<int, 3>> m_casing_dofs;
  double m_omega;
  double m_mu;
};

} // namespace rsi

#pragma once
// Node-to-rigid-surface contact in 3D (SPEC §8; issue 12 item 1; the
// rubbing case of shared/external/rotor37/README.md): a rigid casing turns
// at -Omega past the contact nodes of a blade (seen in the blade's frame),
// with a gap imposed as a function of time and node.
//
// The rotation axis a (unit, through the origin; z by default) and two
// unit vectors e_1, e_2 with (e_1, e_2, a) orthonormal and right-handed:
// e_1 the coordinate axis that follows, in the cycle x -> y -> z -> x, the
// one nearest to a (the first of the largest |a_k|), with its component
// along a removed, and e_2 = a x e_1. About z that is e_1 = x, e_2 = y;
// about x, e_1 = y, e_2 = z (a model turned by the cyclic permutation
// x -> y -> z -> x keeps its polar angles).
// Per contact node c, from its undeformed position X, with the components
// p_1 = e_1 . X, p_2 = e_2 . X across the axis, radius r = |(p_1, p_2)| > 0
// and polar angle phi = atan2(p_2, p_1):
//   frame    e_n  = -(p_1 e_1 + p_2 e_2) / r   (inward: a displacement along e_n opens)
//            e_t1 = a                          (axial)
//            e_t2 = e_n x e_t1 = -sin phi e_1 + cos phi e_2
//            (e_n, e_t1, e_t2) orthonormal and right-handed; e_t2 points
//            along a counter-clockwise rotation about a. About z:
//            e_n = -(x, y, 0) / r, e_t1 = (0, 0, 1), phi = atan2(y, x).
//   gap      g_c(t, u) = g0_c(t) - growth_c + e_n . u_c        (> 0 open)
//            (growth_c: the node's static radial growth under rotation
//            effects, u measured from that deflected state; 0 without)
//            g0 constant, or the oval casing of the README:
//            g0(t) = g_m (1 - 2 exp(-((mod(theta, pi)/pi - 1/2)/w)^2)),
//            theta = Omega t + phi, mod the floored modulo (as MATLAB's),
//            w = 0.15; period pi/Omega in t, minimum -g_m at
//            mod(theta, pi) = pi/2, g_m (1 - 2 exp(-1/(4 w^2))) at the ends.
//            Moving the node by u_c along e_n increases g by |u_c|: opens.
//   casing   velocity -r Omega_s e_t2 past the tip, so over a step of dt
//            it moves by -r Omega_s dt e_t2. Omega (signed: > 0
//            counter-clockwise) sets the gap phase, Omega_s the sliding:
//            Omega_s = Omega for a casing at rest in a rotor turning at
//            Omega (the physical case: phase and sliding of one rotation);
//            Omega_s = -Omega reproduces NLstep's PLAUSIBLE set-up, whose
//            gap phase turns counter-clockwise while its tip slides
//            clockwise (gamma = u_b' + (g', 0, -r Omega) in (n, t1, t2),
//            shared/external/rotor37/README.md).
// For the step t_n -> t_{n+1} = t_next, with u_n and the prediction u~:
//   g~_c = g0_c(t_{n+1}) + e_n . u~_c
//   s~_c = (e_t1 . (u~_c - u_n,c),  e_t2 . (u~_c - u_n,c) + r Omega_s dt)
//          (the node's tangential increment relative to the casing: a node
//          at rest slides by +r Omega_s dt along e_t2)
//   B_c  = rows e_n^T, e_t1^T, e_t2^T on the node's dofs (ux, uy, uz),
// exact (the law is linear in u): g and s of u_{n+1} = u~ + du are g~ + G du
// and s~ + T du. Small displacements: frame, radius and angle are those of
// the undeformed node (as NLstep's rubbing example does).
//
// Units: those of the model (mm, s and rad/s for Rotor 37). Owns copies of
// its data.

#include <array>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "component.hpp"
#include "frictional_contact_law.hpp"

namespace rsi {

/// The imposed gap g0(t, phi): a constant, or the oval casing.
struct ImposedGap {
  enum class Kind { constant, oval };
  Kind kind = Kind::constant;
  double value = 0.0;  ///< g0 for constant; g_m > 0 for oval [length]
  double width = 0.15; ///< w of the oval, > 0

  static ImposedGap constant(double g0) { return {Kind::constant, g0, 0.15}; }
  static ImposedGap oval(double g_m, double width = 0.15) { return {Kind::oval, g_m, width}; }
  /// g0 at theta = Omega t + phi (any finite theta).
  double operator()(double theta) const;
};

struct RigidSurfaceNode {
  std::array<int, 3> dofs{{-1, -1, -1}};              ///< system indices of ux, uy, uz
  Eigen::Vector3d position = Eigen::Vector3d::Zero(); ///< undeformed X
  /// Static radial growth at the run's speed (rotation effects): the gap at
  /// zero displacement is g0(t) - growth; finite.
  double growth = 0.0;
};

struct ContactFrame {
  Eigen::Vector3d normal;   ///< e_n
  Eigen::Vector3d tangent1; ///< e_t1
  Eigen::Vector3d tangent2; ///< e_t2
  double radius = 0.0;      ///< r = |(p_1, p_2)|, the distance from the axis
  double angle = 0.0;       ///< phi = atan2(p_2, p_1)
};

class RigidSurfaceContact : public FrictionalContactLaw {
public:
  /// nodes: at least one; dofs >= 0 and all distinct; positions finite with
  /// r > 0. gap: constant finite, or oval with g_m > 0 and width > 0 finite.
  /// omega finite (any sign; 0: no sliding, constant oval). mu >= 0 finite.
  /// sliding_omega: Omega_s of the header, finite. axis: the rotation
  /// axis through the origin, finite and nonzero (normalised here). Throws
  /// std::invalid_argument naming the parameter and its range.
  RigidSurfaceContact(std::vector<RigidSurfaceNode> nodes, const ImposedGap& gap, double omega,
                      double mu, double sliding_omega,
                      const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ());
  /// The physical case, Omega_s = Omega.
  RigidSurfaceContact(std::vector<RigidSurfaceNode> nodes, const ImposedGap& gap, double omega,
                      double mu)
      : RigidSurfaceContact(std::move(nodes), gap, omega, mu, omega) {}

  int n_contacts() const override { return static_cast<int>(m_nodes.size()); }
  int n_tangents() const override { return 2; }
  double friction_coefficient() const override { return m_mu; }
  /// current, predicted: same size, every node dof inside; t_next finite;
  /// dt > 0 finite. Throws std::invalid_argument otherwise.
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& current,
                const Eigen::Ref<const Eigen::VectorXd>& predicted, double t_next, double dt,
                FrictionalContactGeometry& out) const override;
  /// The 3 n_contacts node dofs (throws std::invalid_argument if one is
  /// outside n_dofs).
  std::vector<int> dofs_read(int n_dofs) const override;

  const ContactFrame& frame(int contact) const { return m_frames.at(contact); }
  const RigidSurfaceNode& node(int contact) const { return m_nodes.at(contact); }
  /// g0_c(t), the gap at zero displacement.
  double imposed_gap(int contact, double t) const;
  /// The casing's velocity at the node, -r Omega_s e_t2.
  Eigen::Vector3d casing_velocity(int contact) const;
  double rotation_speed() const { return m_omega; }
  const Eigen::Vector3d& axis() const { return m_axis; }
  double sliding_speed() const { return m_sliding_omega; }

private:
  std::vector<RigidSurfaceNode> m_nodes;
  std::vector<ContactFrame> m_frames;
  ImposedGap m_gap;
  double m_omega;
  double m_mu;
  double m_sliding_omega;
  Eigen::Vector3d m_axis; ///< a, unit
};

/// The contact nodes `node_ids` of a 3D component (dof kinds ux, uy, uz,
/// coordinates from component.nodes), with system dof = component dof +
/// offset. Throws std::invalid_argument naming the node if it is missing or
/// lacks one of the three translations, or for offset < 0.
std::vector<RigidSurfaceNode> rigid_surface_nodes(const Component& component,
                                                  const std::vector<int>& node_ids, int offset = 0);

} // namespace rsi

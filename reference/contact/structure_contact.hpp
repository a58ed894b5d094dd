#pragma once
// How the structures of a problem meet, as the reference integrator sees
// it: one handle over whichever law the problem names (problem.hpp,
// ProblemContact). The integrator takes a ContactLaw (the sliding-sign
// law: D_k = G_k + mu s_k T_k, contact_law.hpp) or a FrictionalContactLaw
// (Coulomb with stick and slip: rows B_c = (G_c, T_c), frictional_contact_law.hpp);
// this handle holds exactly one of them, so a driver builds its integrator
// and reads the contacts without knowing which geometry is behind them:
// - tip_ring, sliding_sign: TipCasingContact (2D tips against the ring);
// - tip_ring, coulomb: TipRingFrictionalContact;
// - rigid_surface: RigidSurfaceContact (3D nodes against the rigid casing,
//   gap g0(Omega t + phi), the casing sliding at -r Omega_s e_t2);
// - solid_casing: SolidCasingContact (3D nodes against the flexible solid
//   casing, structure 1, at their angle phi + Omega t).
// A new law is one more case here; the drivers do not change.

#include <memory>

#include "contact_law.hpp"
#include "frictional_contact_law.hpp"
#include "problem.hpp"
#include "rigid_surface_contact.hpp"
#include "solid_casing_contact.hpp"

namespace rsi {

class StructureContact {
public:
  /// The law of `problem.contact` (owned). Throws std::invalid_argument for
  /// a problem without contact (ContactKind::none), and what the law's
  /// constructor throws.
  explicit StructureContact(const Problem& problem);
  /// The law of `problem.contact` at rotation speed `rotation_speed` in
  /// place of the case's (the gap's phase and the casing's sliding, with or
  /// against the rotation as the case says): rigid_surface only (the 2D
  /// laws read the speed from their case), std::invalid_argument otherwise.
  StructureContact(const Problem& problem, double rotation_speed);
  /// A law built elsewhere (not owned: it must outlive the handle).
  explicit StructureContact(const ContactLaw& law) : m_law(&law) {}
  explicit StructureContact(const FrictionalContactLaw& law) : m_frictional(&law) {}
  explicit StructureContact(const RigidSurfaceContact& law)
      : m_frictional(&law), m_rigid_surface(&law) {}

  /// The sliding-sign law, or nullptr.
  const ContactLaw* law() const { return m_law; }
  /// The Coulomb law, or nullptr.
  const FrictionalContactLaw* frictional_law() const { return m_frictional; }
  /// The rigid casing's law (its imposed gap and contact frames), or nullptr.
  const RigidSurfaceContact* rigid_surface() const { return m_rigid_surface; }
  /// The flexible solid casing's law, or nullptr.
  const SolidCasingContact* solid_casing() const { return m_solid_casing; }
  bool coulomb() const { return m_frictional != nullptr; }
  int n_contacts() const;

private:
  std::shared_ptr<const void> m_owned;
  const ContactLaw* m_law = nullptr;
  const FrictionalContactLaw* m_frictional = nullptr;
  const RigidSurfaceContact* m_rigid_surface = nullptr;
  const SolidCasingContact* m_solid_casing = nullptr;
};

} // namespace rsi

#pragma once
// The abradable liner (abradable_liner.hpp) on the rigid casing of a
// node-to-rigid-surface contact (rigid_surface_contact.hpp), as the
// full-order step meets it (docs/decisions.md, "The abradable liner").
//
// Cells. Contact node c of polar angle phi_c and axial coordinate
// z_c = a . X_c (undeformed, as the rigid law's frame) is over the cell of
// angle theta = Omega t + phi_c (the gap phase: the liner and the oval are
// both fixed to the casing, so the wear lobes lie where the oval closes)
// and row axial_row(z_c); a node outside [z_min, z_max] is refused at
// construction (std::invalid_argument naming the node).
//
// The normal problem. With g~ the rigid law's predicted gap to the unworn
// surface at t_{n+1} and p the cell's wear, the indentation past the worn
// surface is delta~ = -g~ - p; with c = W_nn the node's normal Delassus
// compliance (dt^2 / m on a lumped mass), the force is the liner's compliant
// solve F = F_bar(delta~ - c F) (AbradableLiner::compliant_force), exact in
// closed form. Two nodes over one cell in one step solve in turn, the second
// from the state the first left (the cell is pushed twice in the step).
//
// With a tip patch (liner_patch.hpp) a node presses every cell under its
// patch, all at its depth, and its force is the patch's compliant root; a
// cell under the patches of two nodes in one step is pushed by both in turn,
// as above. Without one, the single cell under the node, as before.
//
// Step protocol: begin_step(); respond() per node in node order; then
// commit_step() once the step's contact problem is final (the cells' states
// become those of the responses, the plastic work is added, the elastic
// energy sum F^2 / (2 k) of the step's bars kept for the energy balance).
//
// Worn through. A bar's wear cannot reach its length h: past it the tip
// would cut into the backing the model holds rigid and does not contact.
// commit_step() notes the first cell whose committed wear reaches h
// (worn_through(): its sector, row, wear and h); the integrator stops the
// run there with that message (central_difference.cpp).
//
// Units: the model's. Owns the liner (states), references the rigid law
// (which must outlive it).

#include <string>
#include <vector>

#include "abradable_liner.hpp"
#include "liner_patch.hpp"
#include "rigid_surface_contact.hpp"

namespace rsi {

class LinerSurface {
public:
  /// Throws std::invalid_argument for bad liner parameters or a contact node
  /// outside the liner's axial extent (naming the node's index and z).
  LinerSurface(const RigidSurfaceContact& law, const LinerGeometry& geometry,
               const LinerMaterial& material, const LinerPatch& patch = {});

  const AbradableLiner& liner() const { return m_liner; }
  const RigidSurfaceContact& law() const { return m_law; }
  const LinerPatch& patch() const { return m_patch; }
  /// The cells contact node c presses at time t: the one under it, or those
  /// under its patch.
  std::vector<int> cells(int contact, double t) const;

  void begin_step();
  /// The compliant solve of node c at t_next (header) from its cells' states
  /// as this step left them; remembered for commit_step(). Returns the
  /// normal force.
  double respond(int contact, double t_next, double rigid_gap, double compliance);
  /// Keeps the step's responses (header).
  void commit_step();
  /// Empty until a committed cell's wear reaches the liner's thickness h;
  /// then what happened, naming the cell (header).
  const std::string& worn_through() const { return m_worn_through; }

  /// Sum of F^2 / (2 k) over the last committed step's responses.
  double elastic_energy() const { return m_elastic_energy; }
  double plastic_work() const { return m_liner.plastic_work(); }

private:
  struct Pending {
    int cell = 0;
    LinerBarResponse response;
  };
  const RigidSurfaceContact& m_law;
  AbradableLiner m_liner;
  LinerPatch m_patch;
  std::vector<std::vector<int>> m_rows; ///< per contact: its row, or its patch's rows
  std::vector<Pending> m_pending;
  double m_elastic_energy = 0.0;
  std::string m_worn_through;
};

} // namespace rsi

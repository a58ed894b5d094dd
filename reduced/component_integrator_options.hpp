#pragma once
// The options of a reduced component's integration (component_integrator.hpp):
// the step, the friction law and its solver, the modal damping and the
// external force f(t) = f0 + f1 cos(omega_f t + phi_f) in reduced coordinates.

#include <optional>

#include <Eigen/Core>

#include "abradable_cells.hpp"
#include "coulomb_gauss_seidel.hpp"
#include "liner_contact_solve.hpp"

namespace rsi {

/// The abradable liner on the rigid casing (liner_contact_solve.hpp).
struct ComponentLiner {
  AbradableCellsGeometry geometry;
  AbradableCellsMaterial material;
  LinerContactSolveOptions solve;
  /// Every contact node's tip patch (liner_patch_cells.hpp); both widths 0:
  /// absent, a node presses the one cell under it.
  TipPatch patch;
};

struct ComponentIntegratorOptions {
  double dt = 0.0;         ///< time step [s], > 0 and finite
  double mu = 0.0;         ///< Coulomb friction coefficient, >= 0
  Eigen::VectorXd damping; ///< diag(C^), r entries >= 0 (modal_damping), or empty: undamped
  bool force_step = false; ///< integrate even if dt >= 2/omega_max
  /// Solve each step's contact on the closing contacts only (grown as
  /// needed); false: on the whole W (the plain way, kept to cross-check).
  bool closing_subset = true;
  CoulombGaussSeidelOptions coulomb;
  /// External force f(t) = force_constant + force_harmonic cos(force_frequency t
  /// + force_phase) in reduced coordinates (component_integrator.hpp, (*));
  /// each vector r finite entries or empty (= 0). Both empty: no force (the default).
  Eigen::VectorXd force_constant; ///< f0 [force]
  Eigen::VectorXd force_harmonic; ///< f1 [force]
  double force_frequency = 0.0;   ///< omega_f [rad/s], finite
  double force_phase = 0.0;       ///< phi_f [rad], finite
  /// The abradable liner whose bars replace Signorini (absent: the rigid,
  /// unworn casing surface).
  std::optional<ComponentLiner> liner;
};

} // namespace rsi

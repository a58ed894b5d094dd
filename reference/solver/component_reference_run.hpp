#pragma once
// The full-order reference of a 3D component rubbing on the rigid casing:
// the one full-order loop (full_order_run.hpp) on the component's own K and
// M, Coulomb friction with stick and slip through RigidSurfaceContact,
// Rayleigh damping C = alpha M + beta K, zero initial conditions, no other
// force. Written apart from the reduced component integrator
// (reduced/component_integrator.hpp): their agreement on the same component
// is the evidence.
//
// Monitors, checked every step (RunMonitor with rubbing_monitor.hpp): the
// integrator's own (a failed contact solve: IntegrationError, reported as
// the status with its step); the runaway test (a contact node whose normal
// displacement |g_c - g0_c(t)| exceeds its radius, or a non-finite gap:
// that step is not counted); and every energy_every steps and at the last
// the balance in its one form
//   |E - E_0 - W_ext - W_contact + W_damp| <= balance_tolerance * scale,
// W_ext = 0 here (no force), scale the largest of |E|, |W_ext|,
// |W_contact|, W_damp at the checks (E costs a product with K and one with
// M). A run that breaks one stops at that step (completed = false, status
// says which and when); the rows before it are already with the sink.

#include <cstdint>
#include <functional>

#include <Eigen/SparseCore>

#include "case_file.hpp"
#include "history.hpp"
#include "rigid_surface_contact.hpp"

namespace rsi {

struct ComponentReferenceOptions {
  double dt = 0.0;           ///< time step [s], > 0, below 2/omega_max unless force
  /// 1 .. 2147483647 (what RunSummary counts); 64-bit so that a count
  /// derived from a case is checked before it wraps.
  std::int64_t steps = 0;
  std::int64_t output_every = 1; ///< >= 1: a row at t = 0 and every output_every steps
  std::int64_t energy_every = 1; ///< >= 1: the balance check's period (rows between carry E = NaN)
  RayleighDamping damping;   ///< alpha, beta >= 0
  double balance_tolerance = 1e-8; ///< relative, in (0, 1)
  double omega_max = 0.0;    ///< of (K, M) if known [rad/s]; 0: computed (Lanczos)
  bool force = false;        ///< integrate at dt >= 2/omega_max
  std::function<void()> checkpoint;        ///< called every 1000 steps (may throw)
  std::function<void(double)> progress;    ///< fraction done, every 1000 steps
};

/// One history row with the response dof's displacement beside it.
using ComponentRowSink = std::function<void(const HistoryRow& row, double response)>;

/// Runs `law` on (stiffness, mass) from rest; `response_dof` a dof of the
/// component. Returns the summary (method "full"): the certificate's worst
/// values over every step, the balance, the critical step. Throws
/// std::invalid_argument for bad options, StabilityError (run_monitor.hpp)
/// for dt >= 2/omega_max without force, IntegrationError if M is not
/// positive definite.
RunSummary run_component_reference(const Eigen::SparseMatrix<double>& stiffness,
                                   const Eigen::SparseMatrix<double>& mass,
                                   const RigidSurfaceContact& law, int response_dof,
                                   const ComponentReferenceOptions& options,
                                   const ComponentRowSink& sink);

} // namespace rsi

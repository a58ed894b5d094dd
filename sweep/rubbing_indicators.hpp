#pragma once
// The indicators of one rubbing run of a component sweep (a blade on its
// rigid casing), accumulated row by row from the history as it is produced
// (nothing is kept but the response dof, for its spectrum). Every indicator
// reads the rows at t >= transient only (as sweep_indicators.hpp):
// - max_tip_radial: the largest |u_r,c| over the contact nodes c, where
//   u_r,c = g0_c(t) - g_c is the node's radial (outward) displacement: the
//   gap is g_c = g0_c(t) + e_n . u_c with e_n inward
//   (rigid_surface_contact.hpp), so e_n . u_c = -u_r,c [model length];
// - max_contact_force: the largest normal multiplier lambda_n [model force];
// - contact_fraction: the share of rows with at least one lambda_n > 0;
// - energy_ratio: E(last row) / E(first row after the transient), as the
//   paper's sweep; undefined (NaN) when E(first) is not > 0 (a gap never
//   closed leaves the blade at rest: E = 0 throughout);
// - max_abs_response: the largest |u| of the response dof [model length];
// - the three largest spectral peaks of the response dof
//   (response_spectrum.hpp: Hann window, mean removed).
// Against a flexible casing the gap is the two bodies' (the casing moves
// too): no imposed gap, max_tip_radial is not read (0) and the sweep writes
// max_abs_response in its place.
// The energy balance residual is the run's own monitor (its summary), not
// read here.

#include <vector>

#include "history.hpp"
#include "response_spectrum.hpp"
#include "rigid_surface_contact.hpp"

namespace rsi {

struct RubbingIndicators {
  int rows = 0; ///< history rows read (t >= transient)
  double max_tip_radial = 0.0;
  double max_abs_response = 0.0;
  double max_contact_force = 0.0;
  double contact_fraction = 0.0;
  double energy_ratio = 0.0; ///< NaN when undefined (E(first) <= 0)
  std::vector<SpectralPeak> peaks; ///< largest first, at most 3
};

class RubbingIndicatorAccumulator {
public:
  /// `casing`: the run's contact law (its imposed gap g0_c(t), in the
  /// history's contact order); `transient` [s]: rows before it are
  /// skipped; `output_interval` [s]: the time between rows.
  RubbingIndicatorAccumulator(const RigidSurfaceContact& casing, double transient,
                              double output_interval);
  /// Against a flexible casing: no imposed gap (max_tip_radial stays 0).
  RubbingIndicatorAccumulator(double transient, double output_interval);

  /// Reads one row and the response dof beside it.
  void add(const HistoryRow& row, double response);

  /// The indicators of the rows read; with fewer than 4 rows after the
  /// transient (a run stopped early) no peaks.
  RubbingIndicators finish() const;

private:
  const RigidSurfaceContact* m_casing; ///< null: a flexible casing
  double m_transient;
  double m_interval;
  RubbingIndicators m_out;
  long m_contact_rows = 0;
  double m_first_energy = 0.0;
  double m_last_energy = 0.0;
  std::vector<double> m_response;
};

} // namespace rsi

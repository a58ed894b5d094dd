#pragma once
// The indicators of one run of a sweep (issue 15), accumulated row by row
// from the history as it is produced (nothing of the history is kept but
// blade 1's radial tip displacement, for its spectrum). Every indicator
// reads the rows at t >= transient only:
// - the largest |u_k| (radial) and |v_k| (tangential) tip displacement over
//   all blades, in the tip polar frame of the rotating disk [m];
// - the largest normal contact force lambda_k [N];
// - the contact fraction: the share of (blade, row) pairs with lambda_k > 0;
// - the energy ratio E(last row) / E(first row after the transient): above
//   1, contact fed more energy in than the damping took out;
// - the three largest spectral peaks of blade 1's radial tip displacement
//   (response_spectrum.hpp: Hann window, mean removed).

#include <vector>

#include "history.hpp"
#include "response_spectrum.hpp"

namespace rsi {

struct SweepIndicators {
  int rows = 0; ///< history rows read (t >= transient)
  double max_tip_radial = 0.0;
  double max_tip_tangential = 0.0;
  double max_contact_force = 0.0;
  double contact_fraction = 0.0;
  double energy_ratio = 0.0;
  std::vector<SpectralPeak> peaks; ///< largest first, at most 3
};

class SweepIndicatorAccumulator {
public:
  /// `transient` [s]: rows before it are skipped; `output_interval` [s]:
  /// the time between rows (the spectrum's sampling interval).
  SweepIndicatorAccumulator(double transient, double output_interval);

  /// Reads one row; it must carry the tip displacements
  /// (RunOptions::tip_displacement), else std::invalid_argument.
  void add(const HistoryRow& row);

  /// The indicators of the rows read; with fewer than 4 rows after the
  /// transient (a run stopped early) no peaks.
  SweepIndicators finish() const;

private:
  double m_transient;
  double m_interval;
  SweepIndicators m_out;
  long m_contact_pairs = 0;
  long m_pairs = 0;
  double m_first_energy = 0.0;
  double m_last_energy = 0.0;
  std::vector<double> m_blade1_radial;
};

} // namespace rsi

#pragma once
// The model's own interaction lines (issue 15; Legrand, Pierre, Cartraud,
// Lombard, J. Sound Vib. 2009). A bladed-disk mode of nodal diameter n and
// rotating-frame frequency omega_b is, in the fixed frame, a pair of waves
// of n lobes turning at (Omega n +- omega_b) / n; a casing mode of n lobes
// and frequency omega_c is a pair of waves turning at +- omega_c / n. The
// blades' backward wave and the casing's forward wave travel together when
//   n Omega - omega_b = omega_c,  that is  Omega_int = (omega_b + omega_c) / n,
// the speed at which contact can feed both modes at once. Seen from the
// rotating frame (where the tip histories are), the casing mode appears at
// |omega_c - n Omega| and omega_c + n Omega, and the first of these crosses
// the blade family omega_b exactly at Omega_int.
//
// Lobes: the casing's nodal diameter is the dominant circumferential
// harmonic of its mode over the nodes (nodal_diameter.hpp, one block a
// node); the clamp splits each pair, so two casing modes share an n. Only
// n = 1 .. N/2 are listed: a casing harmonic above N/2 meets the N blades as
// its alias N - n, which the blades' own families already cover.

#include <vector>

#include "case_file.hpp"

namespace rsi {

struct InteractionLine {
  int family = 0;         ///< blade mode family j: the j-th distinct frequency at nodal diameter n
  int nodal_diameter = 0; ///< n >= 1
  double blade_hz = 0.0;  ///< omega_b / 2 pi, rotating frame
  int casing_mode = 0;    ///< index of the casing mode (1 = lowest)
  double casing_hz = 0.0; ///< omega_c / 2 pi, fixed frame
  double speed_rad_s = 0.0; ///< Omega_int = (omega_b + omega_c) / n
};

/// Omega_int = 2 pi (blade_hz + casing_hz) / n [rad/s].
double interaction_speed(double blade_hz, double casing_hz, int nodal_diameter);

/// A mode and its nodal diameter (the casing's: its lobes).
struct ClassifiedMode {
  double frequency_hz = 0.0;
  int nodal_diameter = 0;
};

/// The lines of the disk's modes (ascending, N = n_blades sectors, at least
/// `families` whole families) against the casing's (ascending; casing_mode
/// counts from 1 in this list), ordered by family, n, casing mode.
std::vector<InteractionLine> interaction_lines(const std::vector<ClassifiedMode>& disk,
                                               int n_blades,
                                               const std::vector<ClassifiedMode>& casing,
                                               int families);

/// Every (blade family j <= families, casing mode among the lowest
/// casing_modes) pair of equal nodal diameter n in 1 .. N/2, ordered by
/// family, n, casing mode.
std::vector<InteractionLine> interaction_lines(const Case& c, int families, int casing_modes);

} // namespace rsi

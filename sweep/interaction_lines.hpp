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
// node); the clamp splits each pair, so two casing modes share an n. The
// paper's 2D map lists n = 1 .. N/2 only. With `aliased` (the 3D system's
// map) a casing mode of n > N/2 lobes is listed too: the N tips sample its
// wave cos(n theta - omega_c t) at theta_j = 2 pi j / N + Omega t as
// cos(2 pi n j / N + (n Omega - omega_c) t), a pattern of the disk's nodal
// diameter k = |n - m N| <= N/2 (m the nearest integer to n / N): the
// blades' wave of k diameters that matches it (backward for n = k + m N,
// forward for n = m N - k, the same pattern at the tips) meets it when
// n Omega - omega_c = omega_b(k), at Omega_int = (omega_b(k) + omega_c) / n.
// Few blades make this matter: the 6-sector CI disk's casing has its lowest
// modes at 4 to 8 lobes, all above N/2 = 3 (reports/sweep-system3d-ci).

#include <vector>

#include "case_file.hpp"

namespace rsi {

struct InteractionLine {
  int family = 0;         ///< blade mode family j: the j-th distinct frequency at nodal diameter k
  int nodal_diameter = 0; ///< k, the disk's (= n but for an aliased line)
  double blade_hz = 0.0;  ///< omega_b / 2 pi, rotating frame
  int casing_mode = 0;    ///< index of the casing mode (1 = lowest)
  double casing_hz = 0.0; ///< omega_c / 2 pi, fixed frame
  double speed_rad_s = 0.0; ///< Omega_int = (omega_b + omega_c) / n
  int casing_lobes = 0;     ///< n >= 1, the casing's
};

/// k = |n - m N| <= N/2, m the nearest integer to n / N: the nodal diameter
/// of the pattern an n-lobed wave makes at N equally spaced tips.
int aliased_nodal_diameter(int lobes, int n_blades);

/// Omega_int = 2 pi (blade_hz + casing_hz) / n [rad/s].
double interaction_speed(double blade_hz, double casing_hz, int nodal_diameter);

/// A mode and its nodal diameter (the casing's: its lobes).
struct ClassifiedMode {
  double frequency_hz = 0.0;
  int nodal_diameter = 0;
};

/// The lines of the disk's modes (ascending, N = n_blades sectors, at least
/// `families` whole families) against the casing's (ascending; casing_mode
/// counts from 1 in this list), ordered by family, n, casing mode; n = 1 ..
/// N/2, or with `aliased` every n >= 1 of the casing's modes whose alias k
/// has the family.
std::vector<InteractionLine> interaction_lines(const std::vector<ClassifiedMode>& disk,
                                               int n_blades,
                                               const std::vector<ClassifiedMode>& casing,
                                               int families, bool aliased = false);

/// Every (blade family j <= families, casing mode among the lowest
/// casing_modes) pair of equal nodal diameter n in 1 .. N/2, ordered by
/// family, n, casing mode.
std::vector<InteractionLine> interaction_lines(const Case& c, int families, int casing_modes);

} // namespace rsi

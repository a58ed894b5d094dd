#pragma once
// The tip patch a contact node stands for on the abradable liner
// (abradable_liner.hpp; docs/decisions.md, "The wear converges under a tip
// patch"). With one cell per node the same tip force acts on a bar whose
// face shrinks as the cells are refined, and the wear does not converge;
// in Legrand et al.'s model (J. Comput. Nonlinear Dyn. 7 (2012) 011010)
// the tip covers several bars at once. Here a contact node stands for a
// patch of the tip, w_c wide around the casing and w_a along the axis, and
// presses every cell under it, each bar of its own face at its own
// indentation.
//
// Cells under a patch centred at the casing-frame angle theta and the axial
// coordinate z (a = w_c / r its angular width):
//   sectors  every i (mod n_theta) whose centre (i + 1/2) dtheta lies in
//            [theta - a/2, theta + a/2], i.e. i from
//            ceil((theta - a/2)/dtheta - 1/2) to floor((theta + a/2)/dtheta - 1/2);
//            n_theta or more of them: every sector once; none: the sector
//            holding theta (a patch narrower than a cell: one cell, as
//            without a patch);
//   rows     every row j whose centre z_min + (j + 1/2) dz lies in
//            [z - w_a/2, z + w_a/2]; none: the row holding z;
//   cells    every (row, sector) pair.
// Centres rather than overlaps: each cell's bar stays whole (its face, its
// state), so the plastic work keeps its closed form from the final wear,
// and the pressed area is the patch's to within one cell a side (first
// order in the cell size).
//
// The patch's normal law. All bars of a patch sit at one depth d past the
// unworn surface (d = -g): F = sum_i F_i(d - p_i), each F_i the bar law of
// abradable_liner.hpp. The sum S(d) is continuous, piecewise linear and
// nondecreasing, with breakpoints at each bar's p_i (contact) and
// p_i + delta_Y,i (yield). The compliant solve F = S(d~ - c F) has the
// unique root d* of G(d) = d + c S(d) = d~ (G strictly increasing); the
// breakpoints x sorted, the first with G(x) > d~ closes the piece that holds
// d*, on which every bar's branch is fixed, and there, with
// delta~_i = d~ - p_i,
//   F = (sum_elastic k delta~_i + sum_plastic (F_Y,i + k_t (delta~_i - delta_Y,i)))
//       / (1 + c (n_elastic k + n_plastic k_t)),
// formed from the predictions (never from d~ - c F, which cancels for
// c k >> 1: abradable_liner.hpp). One bar: AbradableLiner::compliant_force's
// force, the same operations. Each bar's state and W_p: the bar law at
// delta~_i - c F. With c = 0 the force is the bars' own forces summed (the
// law itself, as the one-bar solve).
//
// Units: the model's.

#include <vector>

#include "abradable_liner.hpp"

namespace rsi {

/// A contact node's share of the blade tip (both 0: no patch).
struct LinerPatch {
  double circumferential = 0.0; ///< w_c >= 0 [length], around the casing
  double axial = 0.0;           ///< w_a >= 0 [length], along the axis
  bool present() const { return circumferential > 0.0 || axial > 0.0; }
};

/// The sectors whose centres lie within the angular window of width
/// `angular_width` [rad] about theta (header), in increasing angle from the
/// window's start.
std::vector<int> patch_sectors(const AbradableLiner& liner, double theta, double angular_width);
/// The rows whose centres lie within [z - width/2, z + width/2] (header);
/// z must lie over the liner (axial_row throws otherwise).
std::vector<int> patch_rows(const AbradableLiner& liner, double z, double width);

/// The compliant solve of one patch.
struct LinerPatchResponse {
  double force = 0.0;                 ///< the root F [force]
  std::vector<LinerBarResponse> bars; ///< each bar's law at delta~_i - c F
};

/// The root of F = sum_i F_i(depth_pred - p_i - c F) over the bars in
/// `states` (header), c >= 0 finite, depth_pred finite; throws
/// std::invalid_argument for an empty patch or bad numbers.
LinerPatchResponse patch_compliant_force(const AbradableLiner& liner,
                                         const std::vector<LinerCellState>& states,
                                         double depth_pred, double compliance);

} // namespace rsi

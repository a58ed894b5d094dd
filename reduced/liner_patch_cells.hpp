#pragma once
// The tip patch: the liner cells a contact node presses and their joint
// compliant solve (SPEC §9; docs/decisions.md, "The wear does not converge
// as the cells are refined"), the reduced side's own (the reference solver
// implements the same rule apart).
//
// Why. With one cell a node, refining the cells leaves the same tip force
// on a shrinking bar (area r dtheta dz), and the wear grows with the cell
// count. A contact node stands instead for a patch of the blade tip of
// circumferential width w_c and axial width w_a [length] (its share of the
// tip, Legrand et al.'s tip edge covering several bars), and its normal
// force is the sum of the forces of every cell under the patch, each bar of
// its own face at its own indentation.
//
// Cells under contact c (theta_c = Omega t + phi_c its casing-frame angle,
// z_c its undeformed axial coordinate, r the liner's radius, a = w_c / r):
//   sectors: every i (mod n_theta) whose centre (i + 1/2) dtheta lies in the
//     closed window [theta_c - a/2, theta_c + a/2] (mod 2 pi), i.e. i from
//     ceil((theta_c - a/2) / dtheta - 1/2) to floor((theta_c + a/2) / dtheta
//     - 1/2); n_theta or more integers: every sector once; none: the sector
//     holding theta_c (the one-cell rule). theta_c is first taken into
//     [0, 2 pi) as AbradableCells::sector does (the same set in exact
//     arithmetic, and bounded integers).
//   rows: every j in [0, n_axial) whose centre z_min + (j + 1/2) dz lies in
//     [z_c - w_a/2, z_c + w_a/2]; none: the row holding z_c.
//   cells: every (row, sector) pair, row n_theta + sector, ascending.
//
// Joint compliant solve. d~ the node's predicted depth past the UNWORN
// surface, c >= 0 its normal Delassus compliance, bar i with wear p_i and
// yield force F_Y,i at the common depth d: F_bar,i(d - p_i)
// (abradable_cells.hpp). The force solves
//   F = G(d~ - c F),   G(d) = sum_i F_bar,i(d - p_i).
// G is continuous, piecewise linear and nondecreasing, with breakpoints
// p_i (bar i touches) and p_i + F_Y,i / k (it yields), so d + c G(d) is
// increasing and the root unique. The piece holding it starts at the
// largest breakpoint b with b + c G(b) <= d~ (a binary search over the
// sorted breakpoints; G(b) needs only wear differences, no d~). On it, E the
// touching elastic bars, P the yielding ones (n_E, n_P of them),
// delta~_i = d~ - p_i:
//   n_P = 0:  F = sum_E k delta~_i / (1 + c n_E k),
//   else:     F = [(k + k_H) sum_E k delta~_i + sum_P k (k_H delta~_i + F_Y,i)]
//                 / [(k + k_H) (1 + c n_E k) + c k k_H n_P],
// formed from delta~, never from d = d~ - c F (which cancels for stiff
// bars, abradable_cells.hpp); every term of the numerator is >= 0. With one
// bar these are AbradableCells::compliant's formulas term for term, so one
// bar classified alike gives its force bit for bit. Each bar's response
// (force, state, plastic work) is then the bar law at delta~_i - c F; their
// forces sum to F up to that difference's rounding, eps (1 + c k) of each.
//
// Units: the model's. Bad arguments throw std::invalid_argument.

#include <vector>

#include "abradable_cells.hpp"

namespace rsi {

/// The tip patch a contact node stands for (case key rubbing.liner.tip_patch).
struct TipPatch {
  double circumferential = 0.0; ///< w_c [length], finite >= 0
  double axial = 0.0;           ///< w_a [length], finite >= 0
  /// Both widths 0: absent, a node presses the one cell under it.
  bool present() const { return circumferential != 0.0 || axial != 0.0; }
};

/// The sectors, ascending and each once, whose centre lies in the closed
/// window of `angle` [rad] (>= 0) centred on `theta` (finite) (header).
std::vector<int> patch_sectors(const AbradableCells& cells, double theta, double angle);
/// patch_sectors into `sectors` (its capacity kept: the solve places every
/// patch at every step).
void patch_sectors(const AbradableCells& cells, double theta, double angle,
                   std::vector<int>& sectors);

/// The rows, ascending, whose centre lies in the window of `width`
/// [length] (>= 0) centred on `z` (within the liner's axial extent) (header).
std::vector<int> patch_rows(const AbradableCells& cells, double z, double width);

/// The cells j n_theta + i of `rows` x `sectors`, row by row, into `cells`
/// (cleared, its capacity kept).
void cells_of(const std::vector<int>& rows, const std::vector<int>& sectors, int n_theta,
              std::vector<int>& cells);

/// The cells under a patch at casing-frame angle theta and axial coordinate
/// z, ascending (header); the angular window is patch.circumferential / r.
std::vector<int> patch_cells(const AbradableCells& cells, double theta, double z,
                             const TipPatch& patch);

/// The root F of F = sum_i F_bar(from_i, depth_pred - p_i - c F) for
/// c = compliance >= 0 (header), with each bar's response at
/// depth_pred - p_i - c F written to `bars` (resized to from.size() >= 1).
double patch_compliant(const AbradableCells& cells, const std::vector<BarState>& from,
                       double depth_pred, double compliance, std::vector<BarResponse>& bars);

/// One linear piece of a patch's law G (header): G(d) = slope d + intercept
/// for d in [lower, upper]. Below every bar: slope = intercept = 0,
/// lower = -infinity, upper the least wear; past every breakpoint upper =
/// +infinity.
struct LinearPiece {
  double slope = 0.0;
  double intercept = 0.0;
  double lower = 0.0;
  double upper = 0.0;
};

/// patch_compliant for one patch solved again and again (the sweeps of a
/// Gauss-Seidel step, d~ changing, the bars' states mostly not): the
/// sorted breakpoints and each G(b) the root search has evaluated are kept
/// while `from` stays the same bit for bit, so a repeated solve costs the
/// binary search's comparisons. G(b) is the same sum in the same order as
/// patch_compliant's, so every call returns patch_compliant's bits. One
/// object serves one liner's cells (G depends on their k and k_H).
class PatchCompliantSolve {
public:
  double operator()(const AbradableCells& cells, const std::vector<BarState>& from,
                    double depth_pred, double compliance, std::vector<BarResponse>& bars);
  /// operator()'s F alone: a Gauss-Seidel sweep needs only the bars a later
  /// contact's chain reads (their responses by `response`, the same bits).
  double force(const AbradableCells& cells, const std::vector<BarState>& from, double depth_pred,
               double compliance);
  /// The piece of G holding `depth` (the last with lower <= depth): on it
  /// the touching elastic bars E (p_i <= lower < p_i + F_Y,i / k) and the
  /// yielding ones P (p_i + F_Y,i / k <= lower) give
  /// slope = n_E k + n_P k k_H / (k + k_H) and
  /// intercept = -sum_E k p_i + sum_P k (F_Y,i - k_H p_i) / (k + k_H)
  /// (abradable_cells.hpp's bar law, summed).
  LinearPiece piece(const AbradableCells& cells, const std::vector<BarState>& from, double depth);
  /// Bar `from`'s response at the patch's force F: the law at
  /// depth_pred - p - c F (header).
  static BarResponse response(const AbradableCells& cells, const BarState& from, double depth_pred,
                              double compliance, double force) {
    return cells.bar(from, (depth_pred - from.wear) - compliance * force);
  }

private:
  /// The breakpoints of `from`, sorted, kept while `from` stays the same.
  void place(const AbradableCells& cells, const std::vector<BarState>& from);

  std::vector<BarState> m_from; ///< the states the breakpoints belong to
  std::vector<double> m_breaks; ///< sorted
  std::vector<double> m_g;      ///< G(m_breaks[j]), NaN until evaluated
};

} // namespace rsi

#pragma once
// Mode selection for the reduction bases of a cyclic bladed disk (issue 14
// item 3; the paper's conclusion: "further work has to be done for
// optimizing the selection of the modes in the reduction basis for each CMS
// method"). A strategy picks which component modes (CB: fixed-interface,
// CCM: free-interface) a basis keeps, out of a candidate pool of the lowest
// ones; the builders (craig_bampton.hpp, craig_chang_martinez.hpp) then take
// the chosen indices instead of a count.
//
// Vocabulary (paper Fig. 3; SPEC V2). The dof vector is N identical sector
// blocks (bladed_disk.hpp), so every mode has one nodal diameter n in
// [0, N/2] (reference/solver/nodal_diameter.hpp). Modes of n = 1..N/2-1
// (n != N/2 for even N) come in degenerate pairs (a sine and a cosine
// pattern, equal frequencies: SPEC V2, equal to 1e-8 relative); n = 0 and
// n = N/2 are single. A *unit* is a single mode or a whole pair: any
// rotation of a pair's two vectors is as good an eigenvector as another, so
// a basis holding one vector of a pair holds a direction chosen by the
// eigensolver's round-off (modal_analysis.hpp notes that CB-4 ... CB-64 of
// the campaign do), and its cyclic symmetry is broken. Every strategy but
// `lowest` keeps whole units. A *family* (branch) is one curve of Fig. 3:
// family k holds the k-th unit (by frequency) of every nodal diameter,
// N modes in all (22 for the paper's disk: 1 + 2 x 10 + 1). The lowest
// families are the blade modes of near-equal frequencies across the
// diameters (43.99-44.00 Hz, 274.2-274.8 Hz for the free modes); the higher
// ones bend where disk modes enter at low n (paper §2: "the curves tend to
// incurve"), so a family is defined by its rank in each diameter, not by a
// frequency window.
//
// Strategies (for `modes` = m asked):
// - lowest: the m lowest modes, exactly the basis of the count-based
//   builders (bit for bit), cutting pairs and families where m falls.
// - families: whole families, in order k = 1, 2, ...: floor(m/N) of them
//   when the pool holds them complete (fewer otherwise). A count that cuts
//   a family is rounded DOWN: the basis never holds more modes than asked
//   (a budget), and m < N keeps none (the Guyan basis). On the paper's
//   disk the lowest 22K modes are exactly families 1..K for K <= 4 (both
//   the free and the fixed-interface spectra), so families equals lowest
//   at multiples of 22 and differs only where lowest cuts a family.
// - forced: whole families first, and within a family the nodal diameters
//   excited by the forcing first: units by (family, rank of the diameter in
//   forced_nodal_diameter_order). It differs from families only where the
//   count cuts a family, and there it keeps the forcing's diameters and
//   their aliases (2, 0, 4, 6, 8, 10 for the paper's p = 2) before the
//   others. Why not every excited diameter of every family before any
//   other one (the literal reading, which would double the frequency range
//   of the excited diameters): that assumes opposite blades are hit alike,
//   which the casing's single clamp and the blade-by-blade contact
//   sequence break. On the paper's case the odd diameters carry much of
//   the blade-1 gap: that order stalls at e2 = 0.11-0.13 from 44 to 88
//   modes (CB and CCM), where whole families reach 0.025-0.032 at 88
//   (measured, issue 14).
// - participation: units ranked by a participation measure of the boundary
//   (participation.hpp: a mode's share of the lowest-order coefficient of
//   the boundary's dynamic stiffness (CB) or receptance (CCM) that depends
//   on the kept modes: ||L_i||^2 / omega_i^2 with L_i the effective
//   interface mass row for CB, ||phi_iB||^2 / omega_i^6 for CCM), largest
//   first; a pair is ranked by the mean of its two members (the sum over a
//   pair does not depend on the rotation the solver chose). Within a
//   blade-dominated family the tips move alike at every diameter: the free
//   modes' measures differ there by about 1e-6 relative between diameters,
//   so where a count cuts such a family the choice among its diameters is
//   as arbitrary as lowest's frequency order (deterministic, not physical).
// families, forced and participation take units in their order and stop at
// the first unit that does not fit in what remains of m (round down: the
// kept set is a prefix of one order, so bases grow nested with m for a
// given pool). The basis's n_modes is the number kept, which may be below m;
// ReducedBasis::requested_modes keeps m.
//
// The candidate pool (candidate_pool_size) is the lowest
// min(available, max(3m, m + 2N)) modes for every strategy but lowest
// (pool = m): three times the count lets participation reach past the
// lowest modes and holds the whole families that families and forced need
// (on the paper's disk the lowest 22K modes are families 1..K), and m + 2N
// gives small counts (m < N) two whole families beyond the count to choose
// from. A pair cut by the top of the pool is not a candidate.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "bladed_disk.hpp"
#include "reduced_basis.hpp"

namespace rsi {

enum class ModeSelection { lowest, families, forced, participation };

/// "lowest", "families", "forced" or "participation"; throws ReductionError
/// naming the allowed values otherwise.
ModeSelection parse_mode_selection(const std::string& name);

std::string to_string(ModeSelection selection);

/// What a selection needs to know about the model and its forcing.
struct SelectionContext {
  int n_sectors = 0;   ///< N, sector blocks of the dof vector (BladedDisk::n_sectors)
  int sector_dofs = 0; ///< dofs per block (BladedDisk::dofs_per_sector)
  /// p of the casing forcing F0 cos(p theta_j) (case key forcing.nodal_diameter), >= 0.
  int forcing_nodal_diameter = 0;
};

/// The context of a bladed disk forced with nodal diameter p.
SelectionContext selection_context(const BladedDisk& bladed_disk, int forcing_nodal_diameter);

/// Throws ReductionError unless N >= 1, sector_dofs >= 1, p >= 0 and
/// n_dofs = N sector_dofs.
void check_context(const SelectionContext& context, int n_dofs);

/// Size of the candidate pool for m modes (see the header comment):
/// m for lowest; 0 for m = 0; else min(available, max(3m, m + 2N)).
int candidate_pool_size(ModeSelection selection, int modes, int available, int n_sectors);

/// Nodal diameter of every column of `shapes` (n_sectors * sector_dofs rows,
/// a shape on every dof of the disk; CB's fixed-interface modes placed with
/// zeros on the boundary rows).
std::vector<int> nodal_diameters(const Eigen::Ref<const Eigen::MatrixXd>& shapes,
                                 const SelectionContext& context);

/// 1 for nodal diameter 0 and N/2 (N even), 2 otherwise (a sine/cosine pair).
int nodal_diameter_multiplicity(int nodal_diameter, int n_sectors);

/// Nodal diameter seen by N blades for a spatial harmonic h of the forcing:
/// |h mod N| folded into [0, N/2] (aliasing of a pattern sampled at N blades).
int alias_nodal_diameter(int harmonic, int n_sectors);

/// The order of the nodal diameters for `forced` (within a family), and how
/// many of them (the first n_excited) the forcing reaches in a perfectly
/// cyclic system.
///
/// Derivation. The bladed disk is loaded only through contact. A casing
/// forced as cos(p theta) has p inward lobes; the normal contact force
/// along the rotor, lambda(theta) >= 0, is then (in the cyclic ideal)
/// 2 pi / p-periodic and one-signed: its Fourier series holds the harmonics
/// h = m p, m = 0, 1, 2, ..., and nothing else. N blades sample it, so
/// harmonic h loads the nodal diameter alias_nodal_diameter(h, N). The order
/// of m follows the size of the coefficients a_m of such a pattern: for
/// narrow lobes (a train of pulses) a_m = 2 a_0 for every m >= 1; for wide
/// ones (half-wave rectified cosine) a_1 = 1/2, a_0 = 1/pi, a_2 = 2/(3 pi),
/// a_m decaying. So m = 1 (the forcing's own diameter p) comes first in both
/// limits (a_1 >= pi/2 a_0), then the mean m = 0 (a one-signed pattern has
/// |a_m| <= 2 a_0 for all m: never less than half of any harmonic), then
/// m = 2, 3, ..., which decay as the lobes widen. A diameter already reached
/// is not repeated. For p = 2, N = 22: 2, 0, 4, 6, 8, 10 (all even
/// diameters: harmonics 12, 14, ... alias back onto them). The diameters
/// not reached (the odd ones here) are loaded only through what breaks the
/// symmetry (the casing's single clamp, SPEC §2, and contacts that do not
/// come in symmetric sets); they follow in ascending order (the lower
/// harmonics of an asymmetry first).
struct NodalDiameterOrder {
  std::vector<int> order; ///< every nodal diameter 0..N/2 once, excited ones first
  int n_excited = 0;      ///< order[0 .. n_excited) are reached by the harmonics m p
};
NodalDiameterOrder forced_nodal_diameter_order(int forcing_nodal_diameter, int n_sectors);

/// A single mode or a degenerate pair of the candidates.
struct CyclicUnit {
  std::vector<int> members; ///< candidate indices (ascending), 1 or 2 of them
  int nodal_diameter = 0;
  int family = 0; ///< 0-based rank of the unit among the units of its diameter
};

/// The complete units of the candidates (omega_squared ascending, one nodal
/// diameter each), ordered by their first member. Within a diameter of
/// multiplicity 2, consecutive candidates pair up; a pair must be
/// degenerate, |omega_a - omega_b| <= 1e-8 omega_b (SPEC V2), else
/// ReductionError (not a cyclic model, or a misclassified mode). A last
/// member left alone is dropped (its partner lies above the pool) if it is
/// within that tolerance of the pool's top; below it, its partner would be
/// among the candidates: ReductionError.
std::vector<CyclicUnit> cyclic_units(const Eigen::Ref<const Eigen::VectorXd>& omega_squared,
                                     const std::vector<int>& nodal_diameter, int n_sectors);

/// What a strategy chooses from: the pool, ascending.
struct Candidates {
  Eigen::VectorXd omega_squared;   ///< [rad^2/s^2], ascending
  std::vector<int> nodal_diameter; ///< of each candidate
  Eigen::VectorXd participation;   ///< of each candidate (participation only; else empty)
};

/// The kept candidates' indices, ascending, for m = `modes` (0 <= m <= pool).
/// lowest: 0 .. m-1 (no unit structure needed). Throws ReductionError for a
/// participation without measure or the errors of cyclic_units.
std::vector<int> select_modes(ModeSelection selection, int modes, const Candidates& candidates,
                              const SelectionContext& context);

} // namespace rsi

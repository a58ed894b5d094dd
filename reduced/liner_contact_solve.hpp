#pragma once
// The contact solve of a reduced component rubbing an abradable liner
// (SPEC §9; issue 26 item 2), the reduced side's own: it includes nothing
// of reference/contact (docs/decisions.md, "The abradable liner").
//
// Problem. [g; s] = [g~; s~] + W lambda as in component_contact_solve.hpp,
// W dense (a mass-carrying boundary: dt^2 B M^-1 B^T; MacNeal's massless
// one: the condensed static flexibility). Contact c lies over the cell
// k(c) = row_c n_theta + sector(Omega t_{n+1} + phi_c) (the gap phase: the
// liner turns with the oval, abradable_cells.hpp), and its normal law is the
// cell's bar instead of Signorini:
//   lambda_n,c = F_bar(state_c, delta_c),  delta_c = -g_c - p(state_c),
// g_c the gap to the unworn surface, state_c the cell's state at the step's
// start, or, when an earlier contact (node order) lies over the same cell in
// this step, the state that contact's response left (two tips over one bar
// push it in turn). Coulomb holds on top, |lambda_t,c| <= mu lambda_n,c,
// stick s_c = 0 inside the disk, slip lambda_t,c = -mu lambda_n,c s_c/|s_c|
// on its rim.
//
// Algorithm: a block Gauss-Seidel over the contacts in node order. For
// contact c, the others held (y = [g; s] kept up to date):
//   normal row: the exact compliant solve of its bar with c = W_nn,c, from
//     delta~ = -(y_n - W_nn lambda_n) - p (AbradableCells::compliant);
//   tangential pair: the exact solution of Coulomb with the threshold
//     R = mu lambda_n just found: x = lambda_t minimises
//     1/2 x^T W_tt x + b^T x over |x| <= R, b = y_t - W_tt lambda_t. Inside,
//     x = -W_tt^-1 b (stick); else x = -(W_tt + nu I)^-1 b with |x| = R,
//     nu > 0 found by Newton's method on 1/R - 1/|x(nu)| from nu = 0
//     (Moré and Sorensen 1983: concave and increasing, so the iterates rise
//     monotonically to the root); then s = W_tt x + b = -nu x opposes x
//     (slip).
// A sweep recomputes y from scratch (no round-off accumulated over sweeps)
// and the cells' chained states from the step's start. It stops at the
// first sweep whose largest change Delta <= relative_change x the largest
// multiplier L, or, within a factor 100 of that, Delta <= relative_change x
// S, S = max_c (|g~_c| + sum_j |W_cj lambda_j|) / W_nn,c: the force that
// the rounding of y_c's terms moves the local solve by (its normal update
// is 1/W_nn-Lipschitz in y_c). A step whose only forces are small next to
// the gaps' terms cannot reach Delta <= 1e-14 L (measured: Rotor 37,
// MacNeal-50, a 4.3 N contact stuck at 1.5e-14 of it for 20,000 sweeps).
// Nor, sometimes, 1e-12 L: with tip patches over a worn liner (Rotor 37,
// 4096 x 80 cells, 830 rad/s) a 0.55 N contact sat at a change of 1.1e-12 N
// (2e-12 of L) for 20,000 sweeps while S was 8,468 N (the floor 8.5e-11 N):
// so a solve whose change stays at or below relative_change x S for 100
// sweeps in a row has stagnated at its round-off floor and stops too (the
// certificate below then checks the law). With mu = 0 each row update is an exact coordinate
// minimisation of the convex 1/2 l^T W l + g~^T l + sum_c Phi_c(lambda_n,c)
// (Phi_c the conjugate of the bar's monotone law shifted by p; a single
// tip per cell), so the sweeps converge (Luo and Tseng 1992); mu > 0 is a
// perturbation of it of the size of the normal/tangential coupling of W,
// as for the rigid casing (coulomb_gauss_seidel.hpp): not proven, and a
// solve that does not converge in max_sweeps is REPORTED (thrown), never
// carried on.
// Tip patch (liner_patch_cells.hpp; absent when both widths are 0, and then
// everything above and below holds word for word, on the same code path):
// contact c presses every cell under its patch at t_{n+1}, and its normal
// law is the sum of their bars at the common depth,
//   lambda_n,c = sum_i F_bar(state_i, delta_c - p_i),  delta_c = -g_c,
// each bar's state chained as above (a later contact, in node order, whose
// patch shares a cell with an earlier one starts that cell from the state
// the earlier one's response left). The normal row's update is the patch's
// joint compliant solve (patch_compliant) from d~ = -(y_n - W_nn lambda_n);
// a contact is active when its predicted depth passes the least worn of its
// cells; the certificate's F_c is that solve at the final y; the elastic
// energy sums F_i^2 / (2 k) over every (contact, cell) response; the commit
// goes contact by contact in node order. The Gauss-Seidel argument above
// carries over: the patch's law is still monotone in the node's depth.
//
// Direct start (with a patch, mu > 0, and no two patches sharing a cell this
// step): the step solved directly where every touching contact slips
// (liner_slip_set.hpp: each patch law's linear piece as a series spring,
// the slip set on top, the pieces updated until none changes), and taken as
// the sweeps' start; the contacts it loads join the active set. Where it
// declines the sweeps start from the last step's multipliers as before.
// Either way the sweeps' stopping rule and the certificate below decide:
// from the direct start the first sweep's change is at the round-off floor
// (Rotor 37, MacNeal-50, 4096 x 80 cells: 1.01 sweeps a contact step
// against 11.9 from the last step's multipliers; a probe counted 1 decline
// in the first 12,000 contact steps).
//
// Active set: the contacts whose predicted indentation is positive or that
// carried a force at the last step, and those the direct start loads, grown
// (in node order) by any contact the others' forces push into its cell,
// until none is.
//
// Certificate (every step, on every contact): the bar law's residual
// |lambda_n,c - F_c|, F_c the compliant solve from
// delta~_c = -(g_c - W_nn lambda_n,c) - p at the final y: zero exactly when
// lambda_n,c = F_bar(state_c, -g_c - p), and, unlike
// |lambda_n,c - F_bar(-g_c - p)|, bounded as the bar stiffens (the compliant
// map is 1/W_nn-Lipschitz in delta~: a bar of any k leaves it at about
// |W_c:|_1 Delta / W_nn, Delta the last sweep's change). Over the largest
// multiplier it must be <= law_tolerance (a detector of gross trouble,
// thrown above it). Then the cone violation, and the stick and slip
// residuals as the rigid solve scales them. The responses committed are
// these last compliant solves. The report's max_penetration and max_complementarity are those of
// the gap to the UNWORN surface (-g, |lambda_n g|), as the full-order run
// reports them: a tip in a bar sits past it.
//
// Commit: the step's responses become the cells' states in node order
// (wear never decreases), their plastic work is summed; the bars' elastic
// energy sum F^2 / (2 k) of the step is kept for the energy balance.
//
// Worn through: a cell whose committed wear reaches the liner's thickness h
// (its bar consumed: past it the tip would cut the backing, which the model
// holds rigid and does not contact) ends the run, thrown after the commit
// as a ComponentIntegrationError naming the sector, row, wear and h.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "abradable_cells.hpp"
#include "component_contact_solve.hpp"
#include "liner_patch_cells.hpp"
#include "liner_slip_set.hpp"

namespace rsi {

struct LinerContactSolveOptions {
  int max_sweeps = 20000;         ///< >= 1
  double relative_change = 1e-14; ///< in [0, 1)
  double law_tolerance = 1e-8;    ///< relative bar-law residual reported as failure, in (0, 1)
};

/// Where each contact node meets the liner.
struct LinerContactLayout {
  std::vector<double> polar_angle; ///< phi_c [rad]
  std::vector<double> axial;       ///< a . x_c [length], within the liner's extent
  double omega = 0.0;              ///< the gap phase's speed [rad/s]
  TipPatch patch;                  ///< every node's tip patch; both widths 0: absent
};

class LinerContactSolve final : public ComponentContactSolve {
public:
  /// Throws std::invalid_argument: a layout not of n_contacts entries, a
  /// node outside the liner's axial extent (naming it), mu < 0 or bad options.
  LinerContactSolve(int n_contacts, double dt, double mu, const AbradableCells& cells,
                    const LinerContactLayout& layout, const LinerContactSolveOptions& options = {});

  void set_contact_matrix(const Eigen::MatrixXd& w) override;
  const Eigen::MatrixXd& contact_matrix() const override { return m_w; }
  void start() override;
  void solve(const Eigen::VectorXd& predicted, int step, StepReport& report) override;
  const Eigen::VectorXd& lambda_next() const override { return m_lambda; }
  const std::vector<ReducedContactState>& states() const override { return m_state; }
  void add_contact_work(const Eigen::VectorXd& lambda_n, const Eigen::MatrixXd& rows,
                        const Eigen::VectorXd& increment) override;
  double contact_work() const override { return m_contact_work; }
  long sweeps() const override { return m_sweeps; }
  /// Steps the sweeps started from the direct start (accepted since start()).
  long direct_starts() const { return m_direct_starts; }

  const AbradableCells& cells() const { return m_cells; }
  /// The cell under contact c at time t (the one-cell rule).
  int cell(int c, double t) const;
  /// The cells under contact c's tip patch at time t, ascending; without a
  /// patch the one cell(c, t).
  std::vector<int> cells_under(int c, double t) const;
  /// Sum of F^2 / (2 k) over the last step's bars.
  double elastic_energy() const { return m_elastic_energy; }
  double plastic_work() const { return m_cells.plastic_work(); }
  /// The part of the contact work done by the normal multipliers.
  double normal_work() const { return m_normal_work; }
  /// The largest relative bar-law residual of any step.
  double max_law_residual() const { return m_max_law_residual; }

private:
  /// S of the stopping rule (header), over the active contacts.
  double rounding_scale(const Eigen::VectorXd& predicted) const;
  /// An upper bound of S for multipliers up to `size`:
  /// max_c (|predicted_c| / W_nn,c + size sum_j |W_cj| / W_nn,c).
  double rounding_scale_bound(const Eigen::VectorXd& predicted, double size) const;
  /// One sweep over the active contacts; returns the largest change.
  double sweep(const Eigen::VectorXd& predicted);
  /// The state contact c's bar starts from this step (the chain of the header).
  BarState start_state(int c) const;
  /// The least wear of contact c's cells (of its one cell without a patch):
  /// chained (this step's start states) or as committed (the active test).
  double least_wear(int c, bool chained) const;
  /// With a patch: the cells under every contact this step, and each
  /// (contact, cell)'s latest earlier contact over the same cell.
  void place_patches(double t);
  /// With a patch: the state the cell at `position` of contact c's patch
  /// starts from this step (the chain of the header).
  BarState patch_start_state(int c, int position) const;
  /// With a patch, mu > 0 and no shared cell: the step solved directly
  /// (liner_slip_set.hpp) into the sweeps' start; false where it declines.
  bool direct_start(const Eigen::VectorXd& predicted);
  /// With a patch: the joint compliant solve of contact c from depth d~
  /// (header), its bars' responses kept in m_patch_response[c]: every one
  /// (`all`), or only those a later contact's chain reads (a sweep's).
  double patch_solve(int c, double depth_pred, double compliance, bool all);
  [[noreturn]] void fail(int step, const std::string& what) const;

  int m_nc;
  double m_dt, m_mu;
  AbradableCells m_cells;
  LinerContactSolveOptions m_options;
  std::vector<int> m_row;
  std::vector<double> m_phi;
  double m_omega;
  Eigen::MatrixXd m_w;
  std::vector<Eigen::Matrix2d> m_wtt;
  Eigen::VectorXd m_w_row_abs; ///< sum_j |W_cj| / W_nn,c over each normal row c
  Eigen::VectorXd m_lambda, m_y;
  std::vector<ReducedContactState> m_state;
  std::vector<int> m_cell;             ///< per contact, this step
  std::vector<char> m_active;          ///< per contact
  std::vector<BarResponse> m_response; ///< per contact, the last evaluation
  /// An earlier (contact, position in its patch) over the same cell, or -1.
  struct PatchLink {
    int contact = -1;
    int position = -1;
  };
  TipPatch m_patch;
  bool m_patched = false;                                 ///< m_patch.present()
  std::vector<double> m_axial;                            ///< z_c per contact
  double m_patch_angle = 0.0;                             ///< w_c / r [rad]
  std::vector<std::vector<int>> m_patch_rows;             ///< per contact, fixed (z_c is)
  std::vector<char> m_rows_meet;                          ///< c n_c + e: their rows share one
  std::vector<std::vector<int>> m_patch_sectors;          ///< per contact, this step
  std::vector<std::vector<int>> m_patch_cells;            ///< per contact, this step
  /// Per contact and patch cell: a later contact's chain may read its response.
  std::vector<std::vector<char>> m_read;
  std::vector<std::vector<PatchLink>> m_previous;         ///< per contact and patch cell
  std::vector<std::vector<BarResponse>> m_patch_response; ///< per contact and patch cell
  std::vector<BarState> m_from;                           ///< scratch of patch_solve, direct_start
  std::vector<PatchCompliantSolve> m_patch_solve;         ///< per contact
  bool m_chained = false;                 ///< with a patch: two patches share a cell this step
  std::optional<LinerSlipSet> m_slip_set; ///< with a patch and mu > 0
  Eigen::VectorXd m_start;                ///< scratch of the direct start
  double m_contact_work = 0.0, m_normal_work = 0.0, m_elastic_energy = 0.0;
  double m_max_law_residual = 0.0;
  long m_sweeps = 0;
  long m_direct_starts = 0;
};

} // namespace rsi

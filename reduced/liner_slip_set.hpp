#pragma once
// A direct solve of one liner contact step when every touching contact
// slips (issue 26: the liner's run at most 1.5 times the rigid one), used as
// the start of the liner's Gauss-Seidel (liner_contact_solve.hpp), which
// then checks it with its own stopping rule and certificate. Same problem:
//     [g; s] = [g~; s~] + W lambda,  lambda_n,c = G_c(-g_c),
// G_c contact c's patch law (liner_patch_cells.hpp), Coulomb on top.
//
// Derivation. G_c is continuous, piecewise linear and nondecreasing in the
// depth d = -g. On one of its pieces, G_c(d) = a d + b (a > 0), and
// lambda_n = G_c(-g) is the closed gap of a contact whose gap has a series
// spring:
//     g'_c = g_c + lambda_n,c / a - b / a = 0,
// i.e. W_nn,c + 1/a in place of W_nn,c and g~_c - b/a in place of g~_c; an
// open contact's lambda_n = 0 with g' >= 0 is G_c <= 0 on the line's
// extension. Below every bar (a = b = 0, d < p_min the least wear) the
// contact is rigid at the worn surface: g~_c + p_min, g' >= 0 open. So with
// every contact's piece fixed, the step is the rigid casing's step with
// friction on (W', g~'), which coulomb_slip_set.hpp solves directly where
// every closed contact slips. Then each contact's depth -g_c (the true gap
// at the solution) names the piece it lies on; a contact off its piece
// moves to that piece and the slip set is solved again (a Newton iteration
// on the piecewise linear law, active-set style), until no piece changes.
// A contact the slip set closes on the rigid stand-in (d = the least wear up
// to round-off, maybe just below it) moves onto the first bars' piece.
//
// It declines (false, lambda untouched) when the slip set declines (stick,
// a reversal, a singular system, ...), when a contact lies on a piece of
// slope 0 over touching bars (a perfectly plastic patch, H = 0: a force
// independent of the depth, no series spring), when `piece_at` returns a
// piece with a NaN or infinite slope or intercept or a NaN bound, or after
// 20 pieces' solves. Its answer need not be trusted: the Gauss-Seidel starts
// from it and stops only by its own rule.

#include <functional>

#include <Eigen/Core>

#include "coulomb_slip_set.hpp"
#include "liner_patch_cells.hpp"

namespace rsi {

class LinerSlipSet {
public:
  /// The piece of contact c's law holding depth d (-g) [length].
  using PieceAt = std::function<LinearPiece(int c, double depth)>;

  /// mu: friction coefficient, finite and > 0 (std::invalid_argument).
  explicit LinerSlipSet(double mu);

  /// Tries the step (`w`: W, 3 nc square, symmetric to the bit;
  /// `predicted`: [g~; s~]); `lambda`: the warm start on entry (W's size),
  /// on success the solution, on decline unchanged.
  bool solve(const Eigen::MatrixXd& w, const Eigen::VectorXd& predicted, const PieceAt& piece_at,
             Eigen::VectorXd& lambda);
  /// Slip-set solves in the last call.
  int iterations() const { return m_iterations; }

private:
  CoulombSlipSet m_slip;
  int m_iterations = 0;
  std::vector<LinearPiece> m_piece;
  Eigen::MatrixXd m_w;      ///< W' (header)
  Eigen::VectorXd m_pred;   ///< [g~'; s~]
  Eigen::VectorXd m_lambda; ///< the candidate
};

} // namespace rsi

#pragma once
// A reduction basis of the bladed disk: u = T q, with the boundary dofs
// kept as physical coordinates inside q (SPEC §3; characteristic constraint
// modes: u_B = Psi_c q_c instead, boundary_shapes), and the reduced matrices
// K^ = T^T K T, M^ = T^T M T (paper eq. 6); MacNeal's M^ is the kept
// modes' mass alone, zero on the boundary (macneal.hpp).

#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "failure_kinds.hpp"

namespace rsi {

/// A reduction that cannot be built as asked: more modes than exist, a
/// boundary set making R_B numerically singular (exit status 2 in the CLI).
class ReductionError : public BadInput {
public:
  using BadInput::BadInput;
};

struct ReducedBasis {
  std::string method;             ///< "cb", "ccm", "guyan", "macneal" or "cc"
  int n_modes = 0;                ///< eta (CB), psi (CCM, MacNeal), 0 (Guyan)
  Eigen::MatrixXd transformation; ///< T, n x r
  Eigen::MatrixXd stiffness;      ///< K^ = T^T K T, r x r
  Eigen::MatrixXd mass;           ///< M^ = T^T M T, r x r (MacNeal: diag(0_B, I_psi))
  /// Position in q of each boundary dof, in the order of the partition's
  /// boundary; empty for "cc", whose boundary is not a set of coordinates.
  std::vector<int> boundary_position;
  /// "cc" (characteristic_constraint.hpp): u_B = boundary_shapes q_c, the
  /// n_B x n_c characteristic constraint modes, q_c the last n_c entries of
  /// q; empty for the other methods.
  Eigen::MatrixXd boundary_shapes;
  /// omega_i [rad/s] of the kept modes (CB: fixed-interface, CCM and MacNeal:
  /// free-interface), in the order of their coordinates in q (the positions
  /// that are not boundary positions); empty for Guyan. For modal damping.
  Eigen::VectorXd mode_omega;
  /// M^ is zero on the boundary rows and columns (MacNeal): (K^, M^) has
  /// n_B infinite eigenvalues, the boundary follows a static balance.
  bool massless_boundary = false;
  double cond_rb = 0.0;       ///< cond(R_B) (CCM, MacNeal; 0 otherwise)
  double build_seconds = 0.0; ///< time to build T, K^, M^

  // The mode selection (mode_selection.hpp). A count-based builder keeps
  // the lowest modes: selection "lowest", requested_modes = n_modes,
  // mode_index 0 .. n_modes-1.
  std::string selection = "lowest"; ///< to_string(ModeSelection)
  /// The count asked for. n_modes is the count kept: a selection that
  /// keeps whole pairs or families rounds down (n_modes <= requested_modes).
  int requested_modes = 0;
  int candidate_modes = 0; ///< the pool: how many of the lowest modes it chose from
  /// Index of each kept mode in the ascending spectrum (CB: fixed-interface,
  /// CCM and MacNeal: free-interface), in the order of mode_omega.
  std::vector<int> mode_index;
  /// Nodal diameter of each kept mode, in the order of mode_omega; empty
  /// unless reduce_bladed_disk was given a SelectionContext.
  std::vector<int> mode_nodal_diameter;
  /// Participation measure of each kept mode (participation.hpp), in the
  /// order of mode_omega; empty unless the selection is "participation".
  Eigen::VectorXd mode_participation;

  int n_reduced() const { return static_cast<int>(transformation.cols()); }
  /// n_B: the boundary dofs the basis represents (coordinates or shapes).
  int n_boundary() const {
    return boundary_shapes.size() != 0 ? static_cast<int>(boundary_shapes.rows())
                                       : static_cast<int>(boundary_position.size());
  }
};

} // namespace rsi

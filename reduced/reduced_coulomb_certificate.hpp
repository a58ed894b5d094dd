#pragma once
// The certificate of one contact step with Coulomb friction, computed on the
// reduced side from the step's data alone (no solver state): issue 12, the
// per-step problem of the forward-increment Lagrange multipliers
// (Carpenter, Taylor, Katona 1991; SPEC §3).
//
// Data: nc contacts with d tangential directions (d = 1: 2D tip/ring law,
// d = 2: 3D node-to-rigid-surface law), W = dt^2 B M^-1 B^T ((1+d) nc square,
// ordered per contact: n, t1[, t2]), the predicted [g~; s~] and lambda. With
//     [g; s] = [g~; s~] + W lambda,
// per contact c the law is
//   Signorini  g_c >= 0, lambda_n,c >= 0, g_c lambda_n,c = 0;
//   Coulomb    |lambda_t,c| <= mu lambda_n,c (Euclidean norm in R^d);
//              stick: s_c = 0; slip: lambda_t,c = -mu lambda_n,c s_c / |s_c|;
//              open: lambda_c = 0.
// The certificate measures each condition's worst violation over contacts;
// the classification (open / stick / slip) is the solver's claim, and the
// certificate checks the residual each class must satisfy. Units: gaps and
// slips in m, W = dt^2 B M^-1 B^T in m/N (B dimensionless), lambda in N.

#include <vector>

#include <Eigen/Core>

namespace rsi {

/// One contact's state after a step.
enum class ReducedContactState { open, stick, slip };

/// Short name ("open", "stick", "slip") for messages and output.
const char* to_string(ReducedContactState state);

struct ReducedCoulombCertificate {
  double max_penetration = 0.0;     ///< max over contacts of max(-g_c, 0) [m]
  double min_normal = 0.0;          ///< min over contacts of lambda_n,c (0 without contacts) [N]
  double max_complementarity = 0.0; ///< max |g_c lambda_n,c| [m N]
  double max_cone_violation = 0.0;  ///< max(|lambda_t,c| - mu lambda_n,c, 0) [N]
  double max_stick_residual = 0.0;  ///< max |s_c| over contacts classified stick [m]
  /// max |lambda_t,c + mu lambda_n,c s_c/|s_c|| over contacts classified slip;
  /// a slip contact with s_c = 0 exactly counts | |lambda_t,c| - mu lambda_n,c | [N]
  double max_slip_residual = 0.0;
  double max_open_residual =
      0.0; ///< max |lambda_c| (all 1+d entries) over contacts classified open [N]
  int n_open = 0;
  int n_stick = 0;
  int n_slip = 0;
};

/// The certificate of `lambda` for the problem (w, predicted, d, mu) with the
/// classification `state` (one entry per contact). Throws
/// std::invalid_argument when d is not 1 or 2, mu is negative or not finite,
/// w is not square of size (1+d) nc, or predicted, lambda, state do not
/// match it.
ReducedCoulombCertificate
reduced_coulomb_certificate(const Eigen::Ref<const Eigen::MatrixXd>& w,
                            const Eigen::Ref<const Eigen::VectorXd>& predicted, int d, double mu,
                            const Eigen::Ref<const Eigen::VectorXd>& lambda,
                            const std::vector<ReducedContactState>& state);

/// The same from y = predicted + W lambda formed by the caller (a W never
/// formed whole: coulomb_node_solve.hpp); the same checks, on y's size.
ReducedCoulombCertificate
reduced_coulomb_certificate_of(const Eigen::Ref<const Eigen::VectorXd>& y, int d, double mu,
                               const Eigen::Ref<const Eigen::VectorXd>& lambda,
                               const std::vector<ReducedContactState>& state);

} // namespace rsi

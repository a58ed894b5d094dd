#pragma once
// The per-step frictional contact problem of the explicit scheme (SPEC §3,
// §8; issue 12 items 1-2): its data and its certificate.
//
// Explicit central differences with forward-increment Lagrange multipliers
// (Carpenter, Taylor, Katona 1991). After the contact-free prediction u~ of
// u_{n+1}, contact c (c = 0..nc-1) has d tangential directions (d = 1: the
// 2D tip/ring law; d = 2: the 3D node-to-rigid-surface law) and a block B_c
// of 1 + d rows: the normal gap gradient G_c, then T_c1 [, T_c2]. The force
// on the structures is B_c^T lambda_c, lambda_c = (lambda_n, lambda_t), a
// positive lambda_n opens the gap. The correction u_{n+1} = u~ + dt^2 M^-1
// B^T lambda gives
//
//   q = q~ + W lambda,   q_c = (g_c, s_c),   W = dt^2 B M^-1 B^T
//
// (W symmetric positive semi-definite, (1+d) nc square, ordered per contact
// n, t1 [, t2]); g~_c is the predicted normal gap (> 0 open), s~_c in R^d the
// predicted tangential slip increment of the node over the step relative to
// the surface, in the contact frame. Find lambda with, for every c:
//   Signorini  g_c >= 0, lambda_n >= 0, g_c lambda_n = 0;
//   Coulomb    |lambda_t| <= mu lambda_n (Euclidean in R^d);
//              stick: |lambda_t| < mu lambda_n  =>  s_c = 0;
//              slip:  s_c != 0  =>  lambda_t = -mu lambda_n s_c / |s_c|;
//   an open contact (lambda_n = 0) carries lambda_t = 0 (the cone says so).
// Static = kinetic coefficient mu >= 0; mu = 0 is frictionless Signorini.
//
// Units: g, s and q in the model's length unit [m], lambda in its force
// unit [N], W [m/N] (SI in the comments; Rotor 37 runs in mm and N).
//
// Certificate (FrictionalContactCertificate and certify() below): the residuals of
// these conditions at a given lambda, raw and scaled, and the class of each
// contact. Scales, from the arithmetic of q = q~ + W lambda: row i of q is a
// sum of m + 1 terms (m = (1+d) nc), so its round-off is at most
// gamma_{m+1} delta_i (Higham, Accuracy and Stability, eq. 3.5) with
//   delta_i = |q~_i| + sum_j |W_ij| |lambda_j|     (length, per row),
//   Lambda  = max_j |lambda_j|                       (force, global).
// Length residuals of row i are divided by delta_i, force residuals by
// Lambda, products by both; a residual whose scale is 0 is exact (0 / 0 is
// reported as 0, x / 0 with x > 0 as infinity).
//
// Classification at round-off level, with a relative threshold theta
// (default: frictional_contact_default_theta(m) = 64 (m + 1) eps, above the
// solver's stopping level 4 (m + 1) eps with a margin of 16; see the solver):
//   open  if lambda_n <= theta Lambda (includes lambda = 0);
//   stick if closed and |lambda_t| < mu lambda_n - theta Lambda (strictly
//         inside the cone beyond round-off): then s_c = 0 is required;
//   slip  otherwise (on the cone's edge within round-off), where
//         lambda_t |s_c| + mu lambda_n s_c = 0 is required. This is the slip
//         law multiplied by |s_c|: it also holds for a contact that sticks on
//         the cone's edge (s_c = 0), whose slip direction is round-off, and
//         its scaled residual |lambda_t |s| + mu lambda_n s| / (Lambda delta_t)
//         is the raw slip residual |lambda_t + mu lambda_n s/|s|| / Lambda
//         weighted by |s| / delta_t (delta_t: the largest delta_i over the
//         contact's tangential rows). The raw slip residual is reported too.
// Which classification the rest of the project should trust: the classes
// only select which law's residual applies; every condition of the problem
// is covered by one residual whatever the class (an open contact's
// |lambda_t| <= mu theta Lambda + its cone violation).

#include <string>
#include <vector>

#include <Eigen/Core>

namespace rsi {

/// The data of one step's problem. Owns copies of its arrays.
class FrictionalContactProblem {
public:
  /// n_tangents d in {1, 2}; friction mu >= 0 and finite; W square of size
  /// (1 + d) nc, finite, symmetric to 1e-12 of its largest entry, with a
  /// positive diagonal (each row of B nonzero); normal_gap g~ of size nc and
  /// slip s~ of size d nc (per contact t1 [, t2]), finite. nc >= 1.
  /// Throws std::invalid_argument naming the parameter and the allowed range.
  FrictionalContactProblem(int n_tangents, double mu, const Eigen::Ref<const Eigen::MatrixXd>& w,
                           const Eigen::Ref<const Eigen::VectorXd>& normal_gap,
                           const Eigen::Ref<const Eigen::VectorXd>& slip);

  int n_contacts() const { return m_n_contacts; }
  int n_tangents() const { return m_n_tangents; }
  int block_size() const { return 1 + m_n_tangents; } ///< 1 + d
  int n_unknowns() const { return m_n_contacts * (1 + m_n_tangents); }
  double friction() const { return m_mu; }
  const Eigen::MatrixXd& w() const { return m_w; }
  /// q~ = (g~_0, s~_0, g~_1, s~_1, ...), ordered like W.
  const Eigen::VectorXd& predicted() const { return m_predicted; }
  /// q = q~ + W lambda.
  Eigen::VectorXd gaps_and_slips(const Eigen::Ref<const Eigen::VectorXd>& lambda) const;

private:
  int m_n_contacts;
  int m_n_tangents;
  double m_mu;
  Eigen::MatrixXd m_w;
  Eigen::VectorXd m_predicted;
};

enum class ContactClass { open, stick, slip };

const char* to_string(ContactClass c);

/// The residuals of the problem at one lambda (see the file comment).
struct FrictionalContactCertificate {
  std::vector<ContactClass> classes; ///< per contact
  double theta = 0.0;                ///< classification threshold used
  double force_scale = 0.0;          ///< Lambda [N]
  // Raw residuals, worst over contacts.
  double max_penetration = 0.0;     ///< max(-g, 0) [m]
  double min_normal = 0.0;          ///< min lambda_n [N]
  double max_complementarity = 0.0; ///< max |g lambda_n| [N m]
  double max_cone_violation = 0.0;  ///< max(|lambda_t| - mu lambda_n, 0) [N]
  double max_stick_residual = 0.0;  ///< max |s_c| over stick contacts [m]
  double max_slip_residual =
      0.0; ///< max |lambda_t + mu lambda_n s/|s|| over slip contacts with s != 0 [N]
  // Scaled residuals (dimensionless, round-off is O(m eps)).
  double penetration = 0.0;     ///< max(-g_c, 0) / delta_n
  double negative_normal = 0.0; ///< max(-lambda_n, 0) / Lambda
  double complementarity = 0.0; ///< |g lambda_n| / (delta_n Lambda)
  double cone_violation = 0.0;  ///< max(|lambda_t| - mu lambda_n, 0) / Lambda
  double stick_residual = 0.0;  ///< |s_c| / delta_t, stick contacts
  double slip_residual = 0.0; ///< |lambda_t |s| + mu lambda_n s| / (Lambda delta_t), slip contacts
  int n_open = 0;
  int n_stick = 0;
  int n_slip = 0;

  /// The largest scaled residual.
  double worst() const;
  /// One line: classes counted, raw and scaled residuals.
  std::string summary() const;
};

/// 64 (m + 1) eps for a problem of m unknowns (file comment).
double frictional_contact_default_theta(int n_unknowns);

/// The certificate of `lambda` (size n_unknowns) for `problem`; theta in
/// (0, 1) (throws std::invalid_argument otherwise, or for a wrong size or a
/// non-finite lambda).
FrictionalContactCertificate certify(const FrictionalContactProblem& problem,
                                     const Eigen::Ref<const Eigen::VectorXd>& lambda, double theta);
/// The same with the default theta.
FrictionalContactCertificate certify(const FrictionalContactProblem& problem,
                                     const Eigen::Ref<const Eigen::VectorXd>& lambda);

} // namespace rsi

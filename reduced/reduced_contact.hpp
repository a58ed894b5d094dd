#pragma once
// Blade-tip / casing contact seen from the reduced model (SPEC §2-3),
// written apart from the reference solver's contact code: the tips' u, v
// are entries of the reduced coordinates q (the boundary kept physical),
// the casing is full.
//
// For tip k at the fixed-frame angle alpha_k = alpha_k0 + Omega t + v_k/R_t,
// in casing element e at local coordinate xi with Hermite values N(xi):
//   gap       g_k = R_c + N . (u, u_s)_e - R_t - u_k
//   sliding   v_slide = Omega (R_t + u_k) + v_k' - N . (v, v_s)_e'
//   slip      s_k = Omega (R_t + u_k) dt + (v_k - v_k,b) - N . ((v, v_s)_e - (v, v_s)_e,b)
//             (subscript b: the state `before`)
// The normal row G_k is -e(u_k) on q and +N on the casing (u, u_s)_e; the
// force row D_k adds mu s_k times (-e(v_k) on q, +N on the casing (v, v_s)_e).
//
// The slip s_k is the Coulomb law's sliding rate (friction_law "coulomb",
// issue 12): the FORWARD increment over the step from `before` (x_n) to the
// evaluated state (x~_{n+1} in the predictor), of the tip relative to the
// casing material point under it, counter-clockwise positive: the tip's
// fixed-frame arc Omega (R_t + u_k) dt (the imposed rotation at the radius
// of the evaluated state) plus its own tangential increment, minus the
// casing's tangential displacement increment at the contact point (Hermite
// values N at the evaluated alpha_k). It is v_slide dt formed as increments
// (no division by dt and back). Its linear part in (q, c) is the tangential
// row T_k = +e(v_k) on q, -N on the casing (v, v_s)_e: the rotation term
// Omega u_k dt is frozen at the evaluated state, as the contact point is,
// so the friction force T_k^T lambda_t is purely tangential.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "bladed_disk.hpp"
#include "case_file.hpp"
#include "casing.hpp"
#include "reduced_basis.hpp"

namespace rsi {

/// One tip's contact geometry at a given state.
struct TipContact {
  double gap = 0.0;              ///< [m]
  double sliding = 0.0;          ///< relative tangential velocity [m/s]
  double sign = 0.0;             ///< sign of `sliding` (0 without friction)
  double slip = 0.0;             ///< forward slip increment over the step [m]
  int q_u = -1;                  ///< position of the tip's u in q
  int q_v = -1;                  ///< position of the tip's v in q
  std::array<int, 4> c_u{};      ///< casing dofs (u1, u1_s, u2, u2_s); -1 at the clamp
  std::array<int, 4> c_v{};      ///< casing dofs (v1, v1_s, v2, v2_s); -1 at the clamp
  std::array<double, 4> shape{}; ///< Hermite values N(xi)
};

class ReducedTipContact {
public:
  ReducedTipContact(const ReducedBasis& basis, const Casing& casing, const Case& c);

  int n_tips() const { return static_cast<int>(m_q_u.size()); }
  double friction_coefficient() const { return m_mu; }
  /// The case's operating_point.friction_law.
  FrictionLaw friction_law() const { return m_law; }

  /// All tips at reduced state q and casing state c at time t, the rates
  /// being the backward differences q' = (q - q_before) / dt and
  /// c' = (c - c_before) / dt, formed only at the entries a tip reads (no
  /// temporaries: this runs once or twice per step), and the slip as the
  /// forward increment from (q_before, c_before) to (q, c). `out` is
  /// resized to n_tips() and reused.
  void evaluate(const Eigen::VectorXd& q, const Eigen::VectorXd& q_before, const Eigen::VectorXd& c,
                const Eigen::VectorXd& c_before, double dt, double t,
                std::vector<TipContact>& out) const;

private:
  std::vector<int> m_q_u;
  std::vector<int> m_q_v;
  std::vector<double> m_alpha0;
  std::vector<int> m_node_first; ///< casing dof of node j's u, or -1
  double m_tip_radius;
  double m_casing_radius;
  double m_omega;
  double m_mu;
  FrictionLaw m_law;
};

} // namespace rsi

#pragma once
// Unilateral contact constraints as the explicit integrator sees them
// (SPEC §3): for each constraint k, a gap g_k (> 0 open), its gradient G_k
// (which way the gap opens: a normal force lambda_k G_k^T pushes the bodies
// apart) and the direction D_k = G_k + mu s_k T_k along which the contact
// force lambda_k D_k^T acts (T_k: the tangential counterpart of G_k, s_k the
// sign of the sliding velocity, so the friction part opposes sliding).
//
// A ContactLaw evaluates them for a given displacement and velocity of the
// whole system; the integrator never sees the geometry behind them.

#include <numeric>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace rsi {

/// A sparse row: (dof, coefficient) pairs.
using SparseRow = std::vector<std::pair<int, double>>;

inline double dot(const SparseRow& row, const Eigen::Ref<const Eigen::VectorXd>& x) {
  double sum = 0.0;
  for (const auto& [dof, c] : row)
    sum += c * x(dof);
  return sum;
}

struct ContactState {
  Eigen::VectorXd gap;              ///< g_k [m], > 0 open
  std::vector<SparseRow> gradient;  ///< G_k
  std::vector<SparseRow> direction; ///< D_k = G_k + mu s_k T_k
  Eigen::VectorXd sliding_velocity; ///< relative tangential velocity [m/s] (0 without friction)
  Eigen::VectorXd friction_sign;    ///< s_k used in D_k (0 without friction)
};

class ContactLaw {
public:
  virtual ~ContactLaw() = default;
  virtual int n_constraints() const = 0;
  /// Gaps and rows at displacement x and velocity v of the whole system at
  /// time t, written into `state` (its storage is reused from call to call:
  /// the integrator calls this twice per step).
  virtual void evaluate(const Eigen::Ref<const Eigen::VectorXd>& x,
                        const Eigen::Ref<const Eigen::VectorXd>& v, double t,
                        ContactState& state) const = 0;
  /// Friction coefficient (for the friction-law monitor); 0 for frictionless laws.
  virtual double friction_coefficient() const = 0;
  /// Every dof whose displacement or velocity evaluate() may read, over all
  /// calls, for a system of n_dofs dofs: a caller may leave the other entries
  /// of x and v stale (the reference integrator gathers only these). The
  /// default is all of them.
  virtual std::vector<int> dofs_read(int n_dofs) const {
    std::vector<int> all(n_dofs);
    std::iota(all.begin(), all.end(), 0);
    return all;
  }
};

} // namespace rsi

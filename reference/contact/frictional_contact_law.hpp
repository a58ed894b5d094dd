#pragma once
// A contact law as the frictional per-step problem needs it
// (frictional_contact_problem.hpp): for the state u_n and the contact-free
// prediction u~ of u_{n+1}, per contact c the predicted normal gap g~_c, the
// predicted tangential slip increment s~_c in R^d (node relative to the
// opposite surface over the step, in the contact frame) and the 1 + d rows
// B_c (normal gap gradient, then the tangents) over the system dofs, such
// that to first order in the correction du = u_{n+1} - u~
//   g_c(u_{n+1}) = g~_c + G_c du,    s_c(u_{n+1}) = s~_c + T_c du,
// and the contact force on the structures is B_c^T (lambda_n, lambda_t).
// The integrator then forms W = dt^2 B M^-1 B^T and solves the problem; it
// never sees the geometry behind the rows.

#include <numeric>
#include <vector>

#include <Eigen/Core>

#include "contact_law.hpp"

namespace rsi {

/// The output of FrictionalContactLaw::evaluate. Storage reused from call
/// to call.
struct FrictionalContactGeometry {
  Eigen::VectorXd normal_gap;  ///< g~_c, nc entries [m], > 0 open
  Eigen::VectorXd slip;        ///< s~_c, d nc entries (per contact t1 [, t2]) [m]
  std::vector<SparseRow> rows; ///< B, (1 + d) nc rows (per contact n, t1 [, t2])
};

class FrictionalContactLaw {
public:
  virtual ~FrictionalContactLaw() = default;
  virtual int n_contacts() const = 0;
  virtual int n_tangents() const = 0;              ///< d: 1 in 2D, 2 in 3D
  virtual double friction_coefficient() const = 0; ///< mu >= 0
  /// Geometry of the step from t_n = t_next - dt to t_next, for the
  /// displacements u_n (`current`) and u~ (`predicted`) of the whole system.
  virtual void evaluate(const Eigen::Ref<const Eigen::VectorXd>& current,
                        const Eigen::Ref<const Eigen::VectorXd>& predicted, double t_next,
                        double dt, FrictionalContactGeometry& out) const = 0;
  /// Every dof evaluate() may read (as ContactLaw::dofs_read).
  virtual std::vector<int> dofs_read(int n_dofs) const {
    std::vector<int> all(n_dofs);
    std::iota(all.begin(), all.end(), 0);
    return all;
  }
};

} // namespace rsi

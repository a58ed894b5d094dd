#pragma once
// The contact solve of a reduced component's step (component_integrator.hpp):
// per contact node three rows (n, t1, t2) and the step's problem
//   [g; s] = [g~; s~] + W lambda,
// [g~; s~] the rigid casing part's prediction, W (3 nc square, constant over
// a run) the rotor part's. Two laws share this interface: the rigid casing
// with Signorini and Coulomb (coulomb_node_solve.hpp) and the abradable
// liner's bars with Coulomb (liner_contact_solve.hpp). The contact work of a
// step is lambda_n^T B (x_{n+1} - x_{n-1})/2, summed into W_contact.

#include <vector>

#include <Eigen/Core>

#include "history.hpp"
#include "reduced_coulomb_certificate.hpp"

namespace rsi {

class ComponentContactSolve {
public:
  virtual ~ComponentContactSolve() = default;
  ComponentContactSolve() = default;
  ComponentContactSolve(const ComponentContactSolve&) = delete;
  ComponentContactSolve& operator=(const ComponentContactSolve&) = delete;

  /// W of every step's problem (3 nc square), symmetrised here.
  virtual void set_contact_matrix(const Eigen::MatrixXd& w) = 0;
  virtual const Eigen::MatrixXd& contact_matrix() const = 0;
  /// Before the first step: every multiplier zero, every contact open, no work.
  virtual void start() = 0;
  /// lambda of the problem of `predicted` ([g~; s~], 3 nc) into
  /// lambda_next(); the contact fields of `report`. `step`: the step the
  /// problem belongs to (n + 1: its time is step dt).
  virtual void solve(const Eigen::VectorXd& predicted, int step, StepReport& report) = 0;
  /// The last solve's multipliers, 3 nc entries (n, t1, t2 per contact).
  virtual const Eigen::VectorXd& lambda_next() const = 0;
  virtual const std::vector<ReducedContactState>& states() const = 0;
  /// W_contact += lambda_n^T B_B (u_B^{n+1} - u_B^{n-1}) / 2.
  virtual void add_contact_work(const Eigen::VectorXd& lambda_n, const Eigen::MatrixXd& rows,
                                const Eigen::VectorXd& increment) = 0;
  virtual double contact_work() const = 0;
  /// Gauss-Seidel sweeps summed since start().
  virtual long sweeps() const = 0;
};

} // namespace rsi

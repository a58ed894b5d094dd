#pragma once
// What the reduced solver's one time loop (reduced_drive.hpp) asks of an
// integrator, whatever it couples: the paper's bladed disk with its casing
// (reduced_integrator.hpp) or one component on a rigid casing
// (component_integrator.hpp). Each implementation states its scheme in its
// own header; all of them advance central differences
//   M (x_{n+1} - 2 x_n + x_{n-1}) / dt^2 + C (x_{n+1} - x_{n-1}) / (2 dt) + K x_n = F_n + B^T lambda_n
// from rest, so they share the discrete energy E_{n-1/2} and the balance
//   E = E_0 + W_ext + W_contact - W_damp
// that the monitors check, each term accumulated step by step.

#include <Eigen/Core>

#include "history.hpp"

namespace rsi {

class ReducedStepper {
public:
  virtual ~ReducedStepper() = default;
  /// From rest (zero displacement and velocity) under the loads the
  /// integrator holds at t = 0.
  virtual void start() = 0;
  /// Step n -> n+1; throws a NumericalFailure when the step cannot be taken.
  virtual StepReport step() = 0;
  /// n, the steps taken since start().
  virtual int step_index() const = 0;
  /// t_n [s].
  virtual double time() const = 0;
  /// E_{n-1/2} [J] (computed when asked: it costs products with M and K).
  virtual double energy() const = 0;
  virtual double initial_energy() const = 0;
  virtual double external_work() const = 0; ///< W_ext up to step n-1 [J]
  virtual double contact_work() const = 0;  ///< W_contact up to step n-1 [J]
  virtual double damping_work() const = 0;  ///< W_damp up to step n-1 [J], >= 0
  /// The gaps at x_n, one per contact [length].
  virtual const Eigen::VectorXd& gap() const = 0;
  /// The multipliers of the step that produced x_n [force]: per contact the
  /// normal one, or (n, t1, t2) for a 3D component (its header says which).
  virtual const Eigen::VectorXd& lambda() const = 0;
};

} // namespace rsi

#pragma once
// The casing part of a reduced component's integration
// (component_integrator.hpp): what the contact solve of a step sees of the
// casing. Two parts share it: the rigid casing (rigid_casing_part.hpp: the
// gaps and slips are the tips' alone, W is the rotor's) and the flexible 3D
// casing in its modes (solid_casing_part.hpp: the casing has its own
// coordinates, stepped beside the rotor's, and its flexibility adds to W).
//
// Per contact node c three rows (n, t1, t2); on the rotor the rows B_B
// (3 nc x n_B) of the tips' frames (rigid_casing.hpp) on the boundary
// coordinates u_B. A step t_n -> t_{n+1}: predict() at the rotor's trial
// boundary u~_B (and, flexible, the casing's own free step), the contact
// solve on [g; s] = [g~; s~] + W lambda with W = the rotor's plus
// add_flexibility()'s (given to the solve as flexibility_rows()), correct() with the solved
// multipliers (flexible: the casing's correction), advance(), then gaps_at() the new level. A
// flexible casing sums its own energy and works: E, W_ext and W_contact of the integrator are the
// rotor's plus the casing's.

#include <Eigen/Core>

#include "rigid_casing.hpp"

namespace rsi {

class ComponentCasingPart {
public:
  virtual ~ComponentCasingPart() = default;
  ComponentCasingPart() = default;
  ComponentCasingPart(const ComponentCasingPart&) = delete;
  ComponentCasingPart& operator=(const ComponentCasingPart&) = delete;

  /// The tips: their frames, boundary indices, radii and angles (for a
  /// flexible casing the RigidCasing of its tips with no imposed gap).
  virtual const RigidCasing& tips() const = 0;
  int n_contacts() const { return tips().n_contacts(); }
  /// B_B, 3 nc x n_B.
  virtual const Eigen::MatrixXd& rows() const = 0;
  /// Before the first step: the casing at rest, no work.
  virtual void start() {}
  /// [g~; s~] at the trial u~_B, from u_B^n, for the step t_n -> t_next
  /// (flexible: the casing's own free step from t_n). t_next = t_n = 0: the
  /// contact at t = 0 of a massless boundary, the casing held where it is.
  virtual void predict(const Eigen::VectorXd& u_trial, const Eigen::VectorXd& u_now, double t_n,
                       double t_next) = 0;
  /// The last prediction, 3 nc entries (g~, s~_t1, s~_t2 per contact).
  virtual const Eigen::VectorXd& prediction() const = 0;
  /// Whether the step's W depends on the casing (flexibility_rows()).
  virtual bool flexible() const { return false; }
  /// w += the casing's share of the last prediction's W (flexible only).
  virtual void add_flexibility(Eigen::MatrixXd& /*w*/) const {}
  /// H with the casing's share of the last prediction's W = dt^2 H H^T
  /// (3 nc x m; flexible only), or nullptr when it has none (rigid, held).
  virtual const Eigen::MatrixXd* flexibility_rows() const { return nullptr; }
  /// The casing's correction by the step's solved multipliers (flexible only).
  virtual void correct(const Eigen::VectorXd& /*lambda*/) {}
  /// The casing's level n -> n+1 (flexible only).
  virtual void advance() {}
  /// g_c at u_B and time t (the casing's current level) into gap().
  virtual void gaps_at(const Eigen::VectorXd& u_boundary, double t) = 0;
  /// The last gaps, nc entries.
  virtual const Eigen::VectorXd& gap() const = 0;
  /// The gap of contact c at time t with no displacement [length].
  virtual double rest_gap(int c, double t) const = 0;
  /// The casing's E_{n-1/2}, W_ext and W_contact (0 for the rigid casing).
  virtual double energy() const { return 0.0; }
  virtual double external_work() const { return 0.0; }
  virtual double contact_work() const { return 0.0; }
  virtual bool finite() const { return true; }
  /// The casing's largest angular frequency in its coordinates (0: rigid).
  virtual double omega_max() const { return 0.0; }
};

} // namespace rsi

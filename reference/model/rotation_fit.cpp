#include "rotation_fit.hpp"

#include <cmath>
#include <string>

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>

#include "case_file.hpp"

namespace rsi {
namespace {

/// Below this, the deflections at the m highest fit speeds do not span m
/// shapes (relative to the largest R diagonal entry of their QR).
constexpr double shape_rank_tolerance = 1e-8;
/// Singular values of the scaled feature matrix below 1/this of the largest
/// are dropped: the p x p solve keeps at least half the digits.
constexpr double largest_feature_condition = 1e8;

std::string speed_text(double speed) {
  std::string s = std::to_string(speed);
  return s.substr(0, s.find_last_not_of('0') + 1);
}

void check_fit_speeds(const ComponentCase& c, const std::vector<double>& speeds, int shapes) {
  const int count = rotation_fit_speed_count(shapes);
  if (static_cast<int>(speeds.size()) != count)
    throw CaseError(c.case_path + ": the rotation fit with " + std::to_string(shapes) +
                    " deflection shapes needs " + std::to_string(count) +
                    " fit speeds (m + m(m+1)/2 + 1), got " + std::to_string(speeds.size()));
  for (size_t j = 0; j < speeds.size(); ++j) {
    if (!std::isfinite(speeds[j]) || speeds[j] <= 0.0 || speeds[j] >= 1e5)
      throw CaseError(c.case_path + ": rotation fit speed " + speed_text(speeds[j]) +
                      " rad/s: allowed 0 < Omega < 1e5 rad/s");
    if (j > 0 && speeds[j] <= speeds[j - 1])
      throw CaseError(c.case_path + ": the rotation fit speeds must ascend, got " +
                      speed_text(speeds[j - 1]) + " then " + speed_text(speeds[j]) + " rad/s");
  }
}

bool same_dofs(const DofMap& a, const DofMap& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].node != b[i].node || a[i].kind != b[i].kind) return false;
  return true;
}

} // namespace

int rotation_fit_speed_count(int shapes) { return shapes + shapes * (shapes + 1) / 2 + 1; }

Eigen::VectorXd rotation_fit_features(const Eigen::VectorXd& a, double speed) {
  const Eigen::Index m = a.size();
  Eigen::VectorXd f(rotation_fit_speed_count(static_cast<int>(m)));
  Eigen::Index p = 0;
  for (Eigen::Index k = 0; k < m; ++k)
    f(p++) = a(k);
  for (Eigen::Index k = 0; k < m; ++k)
    for (Eigen::Index l = k; l < m; ++l)
      f(p++) = a(k) * a(l);
  f(p) = speed * speed;
  return f;
}

RotationFit fit_rotation(const ComponentCase& c, const ComponentLoadOptions& options,
                         const std::vector<double>& fit_speeds, int shapes) {
  if (shapes < 1 || shapes > 4)
    throw CaseError(c.case_path + ": the rotation fit's deflection shapes: allowed 1 to 4, got " +
                    std::to_string(shapes));
  check_fit_speeds(c, fit_speeds, shapes);
  const int p = rotation_fit_speed_count(shapes);
  RotationFit fit;
  fit.rest = rotating_component(c, options, 0.0).component;
  fit.fit_speeds = fit_speeds;
  const int n = fit.rest.n_dofs();
  fit.node_deflections = Eigen::MatrixXd::Zero(n, p + 1);
  std::vector<Eigen::SparseMatrix<double>> change(static_cast<size_t>(p));
  for (int j = 0; j < p; ++j) {
    RotatingComponent at = rotating_component(c, options, fit_speeds[static_cast<size_t>(j)]);
    if (!same_dofs(at.component.dofs, fit.rest.dofs))
      throw ImportError(c.case_path + ": ccx's model at " + speed_text(fit_speeds[static_cast<size_t>(j)]) +
                        " rad/s has other dofs than at rest");
    fit.node_deflections.col(j + 1) = at.deflection;
    change[static_cast<size_t>(j)] = at.component.stiffness - fit.rest.stiffness;
  }
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(fit.node_deflections.rightCols(shapes));
  const Eigen::VectorXd r = qr.matrixQR().topRows(shapes).diagonal().cwiseAbs();
  if (r.minCoeff() <= shape_rank_tolerance * r.maxCoeff())
    throw CaseError(c.case_path + ": the deflections at the " + std::to_string(shapes) +
                    " highest rotation fit speeds do not span " + std::to_string(shapes) +
                    " shapes: take fewer shapes or speeds further apart");
  fit.shapes = qr.householderQ() * Eigen::MatrixXd::Identity(n, shapes);
  Eigen::MatrixXd features(p, p);
  for (int j = 0; j < p; ++j)
    features.row(j) = rotation_fit_features(fit.shapes.transpose() * fit.node_deflections.col(j + 1),
                                            fit_speeds[static_cast<size_t>(j)])
                          .transpose();
  // Columns equilibrated (a in mm, s in rad^2/s^2 differ by 1e6): the
  // condition of the scaled matrix is what the solve loses.
  // A zero column (no deflection at all) keeps scale 1: its singular value
  // is then 0 and the rank check below names it.
  const Eigen::VectorXd scale = features.cwiseAbs().colwise().maxCoeff().transpose().unaryExpr(
      [](double x) { return x > 0.0 ? x : 1.0; });
  const Eigen::MatrixXd scaled = features * scale.cwiseInverse().asDiagonal();
  // A stiff part deflects in proportion to s, so a_k, a_k a_l and s are
  // nearly dependent (a two-brick deck: cond 1e10): the minimum-norm
  // solution over the singular values above 1e-8 of the largest (rank
  // kept in feature_rank) fits what the speeds can tell apart.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeFullU | Eigen::ComputeFullV);
  svd.setThreshold(1.0 / largest_feature_condition);
  const Eigen::VectorXd sv = svd.singularValues();
  fit.feature_rank = static_cast<int>(svd.rank());
  if (fit.feature_rank == 0)
    throw CaseError(c.case_path + ": the rotation fit's speeds leave the stiffness unchanged "
                    "(no deflection): rotation effects have nothing to fit");
  fit.feature_condition = sv(0) / sv(fit.feature_rank - 1);
  Eigen::VectorXd kept = Eigen::VectorXd::Zero(p);
  for (int k = 0; k < fit.feature_rank; ++k) kept(k) = 1.0 / sv(k);
  // C_q = sum_j (F^+)_{qj} (K_j - K0): (1) at the fit speeds, entry by entry.
  const Eigen::MatrixXd inverse = scale.cwiseInverse().asDiagonal() * svd.matrixV() *
                                  kept.asDiagonal() * svd.matrixU().transpose();
  fit.terms.assign(static_cast<size_t>(p), Eigen::SparseMatrix<double>(n, n));
  for (int q = 0; q < p; ++q)
    for (int j = 0; j < p; ++j)
      fit.terms[static_cast<size_t>(q)] += inverse(q, j) * change[static_cast<size_t>(j)];
  return fit;
}

Eigen::VectorXd rotation_fit_weights(const RotationFit& fit, double speed) {
  const double top = fit.fit_speeds.back();
  if (!std::isfinite(speed) || std::abs(speed) > top)
    throw CaseError("rotation speed " + speed_text(speed) + " rad/s is outside the rotation "
                    "fit: allowed |Omega| <= " + speed_text(top) +
                    " rad/s (the highest fit speed; no extrapolation)");
  const size_t nodes = fit.fit_speeds.size() + 1;
  std::vector<double> s(nodes, 0.0), unit(nodes, 0.0);
  for (size_t j = 1; j < nodes; ++j)
    s[j] = fit.fit_speeds[j - 1] * fit.fit_speeds[j - 1];
  gsl_interp* spline = gsl_interp_alloc(gsl_interp_cspline, nodes);
  gsl_interp_accel* accel = gsl_interp_accel_alloc();
  Eigen::VectorXd w(static_cast<Eigen::Index>(nodes));
  const double x = std::min(speed * speed, s.back());
  for (size_t j = 0; j < nodes; ++j) {
    unit.assign(nodes, 0.0);
    unit[j] = 1.0;
    gsl_interp_init(spline, s.data(), unit.data(), nodes);
    w(static_cast<Eigen::Index>(j)) = gsl_interp_eval(spline, s.data(), unit.data(), x, accel);
    gsl_interp_accel_reset(accel);
  }
  gsl_interp_accel_free(accel);
  gsl_interp_free(spline);
  return w;
}

Eigen::VectorXd rotation_fit_deflection(const RotationFit& fit, double speed) {
  if (speed == 0.0) return Eigen::VectorXd::Zero(fit.rest.n_dofs());
  return fit.node_deflections * rotation_fit_weights(fit, speed);
}

RotatingComponent rotating_component_at(const RotationFit& fit, double speed) {
  RotatingComponent rotating;
  rotating.speed = speed;
  rotating.component = fit.rest;
  if (speed == 0.0) {
    rotating.deflection = Eigen::VectorXd::Zero(fit.rest.n_dofs());
    return rotating;
  }
  rotating.deflection = rotation_fit_deflection(fit, speed);
  const Eigen::VectorXd f =
      rotation_fit_features(fit.shapes.transpose() * rotating.deflection, speed);
  for (size_t q = 0; q < fit.terms.size(); ++q)
    rotating.component.stiffness += f(static_cast<Eigen::Index>(q)) * fit.terms[q];
  return rotating;
}

} // namespace rsi

#include "frictional_contact_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace rsi {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

std::string str(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

/// x / scale with 0 / 0 = 0 and x / 0 = infinity for x > 0.
double ratio(double x, double scale) {
  if (scale > 0.0) return x / scale;
  return x > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

} // namespace

FrictionalContactProblem::FrictionalContactProblem(
    int n_tangents, double mu, const Eigen::Ref<const Eigen::MatrixXd>& w,
    const Eigen::Ref<const Eigen::VectorXd>& normal_gap,
    const Eigen::Ref<const Eigen::VectorXd>& slip)
    : m_n_contacts(static_cast<int>(normal_gap.size()))
    , m_n_tangents(n_tangents)
    , m_mu(mu) {
  const std::string where = "FrictionalContactProblem: ";
  if (n_tangents != 1 && n_tangents != 2)
    throw std::invalid_argument(where + "n_tangents = " + std::to_string(n_tangents) +
                                ", allowed 1 (2D) or 2 (3D)");
  if (!(std::isfinite(mu) && mu >= 0.0))
    throw std::invalid_argument(where + "mu = " + str(mu) + ", allowed [0, inf)");
  if (m_n_contacts < 1)
    throw std::invalid_argument(where + "normal_gap has " + std::to_string(m_n_contacts) +
                                " entries, allowed at least 1 (one per contact)");
  const int m = n_unknowns();
  if (slip.size() != static_cast<Eigen::Index>(n_tangents) * m_n_contacts)
    throw std::invalid_argument(where + "slip has " + std::to_string(slip.size()) +
                                " entries, allowed exactly n_tangents * n_contacts = " +
                                std::to_string(n_tangents * m_n_contacts));
  if (w.rows() != m || w.cols() != m)
    throw std::invalid_argument(where + "W is " + std::to_string(w.rows()) + " x " +
                                std::to_string(w.cols()) + ", allowed " + std::to_string(m) +
                                " x " + std::to_string(m) + " ((1 + n_tangents) n_contacts)");
  if (!normal_gap.allFinite() || !slip.allFinite())
    throw std::invalid_argument(where + "normal_gap and slip must be finite");
  if (!w.allFinite()) throw std::invalid_argument(where + "W must be finite");
  const double largest = w.cwiseAbs().maxCoeff();
  for (int i = 0; i < m; ++i) {
    if (!(w(i, i) > 0.0))
      throw std::invalid_argument(where + "W(" + std::to_string(i) + ", " + std::to_string(i) +
                                  ") = " + str(w(i, i)) +
                                  ", allowed (0, inf) (a zero row of B, or W not PSD)");
    for (int j = 0; j < i; ++j)
      if (std::abs(w(i, j) - w(j, i)) > 1e-12 * largest)
        throw std::invalid_argument(where + "W not symmetric at (" + std::to_string(i) + ", " +
                                    std::to_string(j) + "): " + str(w(i, j)) + " vs " +
                                    str(w(j, i)) + ", allowed difference 1e-12 max |W|");
  }
  m_w = w;
  m_predicted.resize(m);
  const int b = block_size();
  for (int c = 0; c < m_n_contacts; ++c) {
    m_predicted(b * c) = normal_gap(c);
    for (int k = 0; k < n_tangents; ++k)
      m_predicted(b * c + 1 + k) = slip(n_tangents * c + k);
  }
}

Eigen::VectorXd
FrictionalContactProblem::gaps_and_slips(const Eigen::Ref<const Eigen::VectorXd>& lambda) const {
  Eigen::VectorXd q = m_predicted;
  q.noalias() += m_w * lambda;
  return q;
}

const char* to_string(ContactClass c) {
  switch (c) {
  case ContactClass::open:
    return "open";
  case ContactClass::stick:
    return "stick";
  case ContactClass::slip:
    return "slip";
  }
  return "?";
}

double frictional_contact_default_theta(int n_unknowns) {
  return 64.0 * (n_unknowns + 1) * eps;
}

double FrictionalContactCertificate::worst() const {
  return std::max({penetration, negative_normal, complementarity, cone_violation, stick_residual,
                   slip_residual});
}

std::string FrictionalContactCertificate::summary() const {
  char buffer[640];
  std::snprintf(buffer, sizeof buffer,
                "%d open, %d stick, %d slip; raw: penetration %.3e, min lambda_n %.3e, "
                "|g lambda_n| %.3e, cone %.3e, stick |s| %.3e, slip %.3e; scaled: penetration "
                "%.2e, negative lambda_n %.2e, complementarity %.2e, cone %.2e, stick %.2e, "
                "slip %.2e (theta %.2e, Lambda %.3e)",
                n_open, n_stick, n_slip, max_penetration, min_normal, max_complementarity,
                max_cone_violation, max_stick_residual, max_slip_residual, penetration,
                negative_normal, complementarity, cone_violation, stick_residual, slip_residual,
                theta, force_scale);
  return buffer;
}

FrictionalContactCertificate certify(const FrictionalContactProblem& problem,
                                     const Eigen::Ref<const Eigen::VectorXd>& lambda) {
  return certify(problem, lambda, frictional_contact_default_theta(problem.n_unknowns()));
}

FrictionalContactCertificate certify(const FrictionalContactProblem& problem,
                                     const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                     double theta) {
  const std::string where = "certify: ";
  const int m = problem.n_unknowns();
  if (lambda.size() != m)
    throw std::invalid_argument(where + "lambda has " + std::to_string(lambda.size()) +
                                " entries, allowed exactly " + std::to_string(m));
  if (!lambda.allFinite()) throw std::invalid_argument(where + "lambda must be finite");
  if (!(theta > 0.0 && theta < 1.0))
    throw std::invalid_argument(where + "theta = " + str(theta) + ", allowed (0, 1)");
  const int nc = problem.n_contacts();
  const int d = problem.n_tangents();
  const int b = problem.block_size();
  const double mu = problem.friction();
  const Eigen::VectorXd q = problem.gaps_and_slips(lambda);
  // delta_i = |q~_i| + sum_j |W_ij| |lambda_j|.
  Eigen::VectorXd delta = problem.predicted().cwiseAbs();
  delta.noalias() += problem.w().cwiseAbs() * lambda.cwiseAbs();

  FrictionalContactCertificate r;
  r.theta = theta;
  const double scale = lambda.cwiseAbs().maxCoeff();
  r.force_scale = scale;
  r.min_normal = std::numeric_limits<double>::infinity();
  for (int c = 0; c < nc; ++c) {
    const double ln = lambda(b * c);
    const double g = q(b * c);
    const double delta_n = delta(b * c);
    const Eigen::VectorXd lt = lambda.segment(b * c + 1, d);
    const Eigen::VectorXd s = q.segment(b * c + 1, d);
    const double delta_t = delta.segment(b * c + 1, d).maxCoeff();
    const double lt_norm = lt.norm();
    const double s_norm = s.norm();

    r.max_penetration = std::max(r.max_penetration, std::max(-g, 0.0));
    r.penetration = std::max(r.penetration, ratio(std::max(-g, 0.0), delta_n));
    r.min_normal = std::min(r.min_normal, ln);
    r.negative_normal = std::max(r.negative_normal, ratio(std::max(-ln, 0.0), scale));
    r.max_complementarity = std::max(r.max_complementarity, std::abs(g * ln));
    r.complementarity = std::max(r.complementarity, ratio(std::abs(g * ln), delta_n * scale));
    const double cone = std::max(lt_norm - mu * ln, 0.0);
    r.max_cone_violation = std::max(r.max_cone_violation, cone);
    r.cone_violation = std::max(r.cone_violation, ratio(cone, scale));

    ContactClass cls;
    if (ln <= theta * scale)
      cls = ContactClass::open;
    else if (lt_norm < mu * ln - theta * scale)
      cls = ContactClass::stick;
    else
      cls = ContactClass::slip;
    r.classes.push_back(cls);
    if (cls == ContactClass::open) {
      ++r.n_open;
    } else if (cls == ContactClass::stick) {
      ++r.n_stick;
      r.max_stick_residual = std::max(r.max_stick_residual, s_norm);
      r.stick_residual = std::max(r.stick_residual, ratio(s_norm, delta_t));
    } else {
      ++r.n_slip;
      if (s_norm > 0.0)
        r.max_slip_residual = std::max(r.max_slip_residual, (lt + (mu * ln / s_norm) * s).norm());
      const double bilinear = (s_norm * lt + (mu * ln) * s).norm();
      r.slip_residual = std::max(r.slip_residual, ratio(bilinear, scale * delta_t));
    }
  }
  return r;
}

} // namespace rsi

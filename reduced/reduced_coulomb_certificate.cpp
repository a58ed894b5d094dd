#include "reduced_coulomb_certificate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rsi {

const char* to_string(ReducedContactState state) {
  switch (state) {
  case ReducedContactState::open:
    return "open";
  case ReducedContactState::stick:
    return "stick";
  case ReducedContactState::slip:
    return "slip";
  }
  return "?";
}

namespace {

constexpr const char* kWhere = "reduced_coulomb_certificate: ";

/// d in {1, 2}, mu finite and >= 0.
void check_law(int d, double mu) {
  if (d != 1 && d != 2)
    throw std::invalid_argument(std::string(kWhere) + "d (tangential directions) = " +
                                std::to_string(d) + ", allowed 1 or 2");
  if (!(mu >= 0.0) || !std::isfinite(mu))
    throw std::invalid_argument(std::string(kWhere) + "mu = " + std::to_string(mu) +
                                ", allowed a finite value >= 0");
}

/// check_law; the size n of y (and lambda) a multiple of 1 + d with one
/// state per contact. Returns nc.
int checked_contacts(Eigen::Index n, int d, double mu, Eigen::Index lambda_size,
                     const std::vector<ReducedContactState>& state) {
  check_law(d, mu);
  const int block = 1 + d;
  if (n % block != 0)
    throw std::invalid_argument(std::string(kWhere) + "the problem's size " + std::to_string(n) +
                                ", allowed (1+d) nc");
  if (lambda_size != n)
    throw std::invalid_argument(std::string(kWhere) + "lambda must have the problem's size " +
                                std::to_string(n) + " (got " + std::to_string(lambda_size) + ")");
  const int nc = static_cast<int>(n) / block;
  if (static_cast<int>(state.size()) != nc)
    throw std::invalid_argument(std::string(kWhere) + "state must have one entry per contact (" +
                                std::to_string(nc) + "), got " + std::to_string(state.size()));
  return nc;
}

} // namespace

ReducedCoulombCertificate
reduced_coulomb_certificate(const Eigen::Ref<const Eigen::MatrixXd>& w,
                            const Eigen::Ref<const Eigen::VectorXd>& predicted, int d, double mu,
                            const Eigen::Ref<const Eigen::VectorXd>& lambda,
                            const std::vector<ReducedContactState>& state) {
  check_law(d, mu);
  if (w.rows() != w.cols() || w.rows() % (1 + d) != 0)
    throw std::invalid_argument(std::string(kWhere) + "W is " + std::to_string(w.rows()) + " x " +
                                std::to_string(w.cols()) + ", allowed square of size (1+d) nc");
  if (predicted.size() != w.rows() || lambda.size() != w.rows())
    throw std::invalid_argument(std::string(kWhere) + "predicted and lambda must have W's size " +
                                std::to_string(w.rows()) + " (got " +
                                std::to_string(predicted.size()) + " and " +
                                std::to_string(lambda.size()) + ")");
  const Eigen::VectorXd y = predicted + w * lambda; // [g; s], per contact n, t1[, t2]
  return reduced_coulomb_certificate_of(y, d, mu, lambda, state);
}

ReducedCoulombCertificate
reduced_coulomb_certificate_of(const Eigen::Ref<const Eigen::VectorXd>& y, int d, double mu,
                               const Eigen::Ref<const Eigen::VectorXd>& lambda,
                               const std::vector<ReducedContactState>& state) {
  const int nc = checked_contacts(y.size(), d, mu, lambda.size(), state);
  const int block = 1 + d;
  ReducedCoulombCertificate out;
  out.min_normal = nc > 0 ? lambda(0) : 0.0;
  for (int c = 0; c < nc; ++c) {
    const int o = block * c;
    const double g = y(o);
    const double ln = lambda(o);
    const Eigen::VectorXd lt = lambda.segment(o + 1, d);
    const Eigen::VectorXd s = y.segment(o + 1, d);
    out.max_penetration = std::max(out.max_penetration, std::max(-g, 0.0));
    out.min_normal = std::min(out.min_normal, ln);
    out.max_complementarity = std::max(out.max_complementarity, std::abs(g * ln));
    out.max_cone_violation = std::max(out.max_cone_violation, std::max(lt.norm() - mu * ln, 0.0));
    switch (state[c]) {
    case ReducedContactState::open:
      ++out.n_open;
      out.max_open_residual =
          std::max(out.max_open_residual, lambda.segment(o, block).cwiseAbs().maxCoeff());
      break;
    case ReducedContactState::stick:
      ++out.n_stick;
      out.max_stick_residual = std::max(out.max_stick_residual, s.norm());
      break;
    case ReducedContactState::slip: {
      ++out.n_slip;
      const double slip = s.norm();
      const double r =
          slip > 0.0 ? (lt + (mu * ln / slip) * s).norm() : std::abs(lt.norm() - mu * ln);
      out.max_slip_residual = std::max(out.max_slip_residual, r);
      break;
    }
    }
  }
  return out;
}

} // namespace rsi

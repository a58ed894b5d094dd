#include "frictional_contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/LU>

namespace rsi {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

std::string str(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", x);
  return buffer;
}

/// One attempt of the semismooth Newton method with augmentation r_c =
/// r_factor / W_nn,c.
class AlartCurnierNewton {
public:
  AlartCurnierNewton(const FrictionalContactProblem& p, double r_factor)
      : m_p(p)
      , m_nc(p.n_contacts())
      , m_d(p.n_tangents())
      , m_b(p.block_size())
      , m_m(p.n_unknowns())
      , m_mu(p.friction())
      , m_r(m_nc)
      , m_rt(m_nc)
      , m_s(p.w().diagonal().cwiseSqrt()) {
    for (int c = 0; c < m_nc; ++c) {
      m_r(c) = r_factor / p.w()(m_b * c, m_b * c);
      m_rt(c) = r_factor / p.w().diagonal().segment(m_b * c + 1, m_d).maxCoeff();
    }
  }

  /// F(lambda) into f; with `jacobian`, the Newton matrix into j; returns
  /// whether the natural residuals pass the stopping test.
  bool evaluate(const Eigen::VectorXd& lambda, Eigen::VectorXd& f, Eigen::MatrixXd* jacobian) {
    const Eigen::MatrixXd& w = m_p.w();
    const Eigen::VectorXd q = m_p.gaps_and_slips(lambda);
    Eigen::VectorXd delta = m_p.predicted().cwiseAbs();
    delta.noalias() += w.cwiseAbs() * lambda.cwiseAbs();
    const double scale = lambda.cwiseAbs().maxCoeff();
    const double eta = 4.0 * (m_m + 1) * eps;
    f.resize(m_m);
    if (jacobian) {
      jacobian->setZero(m_m, m_m);
      m_unit_row.assign(m_m, 0);
    }
    bool pass = true;
    for (int c = 0; c < m_nc; ++c) {
      const int n = m_b * c;
      const double r = m_r(c);
      const double rt = m_rt(c);
      const double ln = lambda(n);
      const double g = q(n);
      const double a = ln - r * g;
      const bool closed = a > 0.0;
      const Eigen::VectorXd lt = lambda.segment(n + 1, m_d);
      const Eigen::VectorXd s = q.segment(n + 1, m_d);
      const Eigen::VectorXd tau = lt - rt * s;
      const double rho = closed ? m_mu * a : 0.0;
      const double tau_norm = tau.norm();
      // Normal row.
      if (closed) {
        f(n) = r * g;
        if (jacobian) jacobian->row(n) = r * w.row(n);
        pass = pass && std::abs(g) <= eta * delta(n) && ln >= -eta * scale;
      } else {
        f(n) = ln;
        if (jacobian) (*jacobian)(n, n) = 1.0, m_unit_row[n] = 1;
        pass = pass && std::abs(ln) <= eta * scale && g >= -eta * delta(n);
      }
      // Tangential rows.
      if (rho == 0.0) {
        f.segment(n + 1, m_d) = lt;
        if (jacobian)
          for (int k = 0; k < m_d; ++k)
            (*jacobian)(n + 1 + k, n + 1 + k) = 1.0, m_unit_row[n + 1 + k] = 1;
        pass = pass && lt.norm() <= eta * scale;
      } else if (tau_norm <= rho) { // stick
        f.segment(n + 1, m_d) = rt * s;
        if (jacobian) jacobian->middleRows(n + 1, m_d) = rt * w.middleRows(n + 1, m_d);
        for (int k = 0; k < m_d; ++k)
          pass = pass && std::abs(s(k)) <= eta * delta(n + 1 + k);
        pass = pass && lt.norm() <= m_mu * ln + eta * scale;
      } else { // slip
        const Eigen::VectorXd unit = tau / tau_norm;
        f.segment(n + 1, m_d) = lt - rho * unit;
        const double delta_t = delta.segment(n + 1, m_d).maxCoeff();
        pass = pass && std::abs(lt.norm() - m_mu * ln) <= eta * scale &&
               (s.norm() * lt + (m_mu * ln) * s).norm() <= eta * scale * delta_t;
        if (jacobian) {
          // d(tau) = E_t - r_t W_t; d(rho) = mu (e_n^T - r_n W_n).
          Eigen::MatrixXd dtau = -rt * w.middleRows(n + 1, m_d);
          for (int k = 0; k < m_d; ++k)
            dtau(k, n + 1 + k) += 1.0;
          Eigen::RowVectorXd drho = (-m_mu * r) * w.row(n);
          drho(n) += m_mu;
          Eigen::MatrixXd projector = Eigen::MatrixXd::Identity(m_d, m_d);
          projector.noalias() -= unit * unit.transpose();
          Eigen::MatrixXd block = -unit * drho;
          block.noalias() -= (rho / tau_norm) * projector * dtau;
          for (int k = 0; k < m_d; ++k)
            block(k, n + 1 + k) += 1.0;
          jacobian->middleRows(n + 1, m_d) = block;
        }
      }
    }
    return pass;
  }

  FrictionalContactSolution run(const Eigen::VectorXd& initial, int max_iterations) {
    FrictionalContactSolution out;
    Eigen::VectorXd lambda = initial;
    Eigen::VectorXd f(m_m), f_trial(m_m), trial(m_m), step(m_m);
    Eigen::MatrixXd j(m_m, m_m);
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(m_m);
    for (int it = 0;; ++it) {
      if (evaluate(lambda, f, &j)) {
        out.status = FrictionalContactStatus::converged;
        break;
      }
      if (it == max_iterations) {
        out.status = FrictionalContactStatus::no_convergence;
        out.message = "no convergence in " + std::to_string(max_iterations) +
                      " Newton steps (|F| = " + str(f.norm()) + ")";
        break;
      }
      // Equilibrated: S J S^-1 (S = diag(W)^1/2) has the rows of W's
      // correlation matrix on closed rows and of the identity on open ones,
      // whatever the scale of each row of B; rcond means something.
      j = m_s.asDiagonal() * j * m_s.cwiseInverse().asDiagonal();
      lu.compute(j);
      // Partial pivoting (about half of FullPivLU's time here); an exactly
      // singular matrix gives a zero pivot, hence rcond 0 (or NaN).
      const double rcond = lu.rcond();
      if (!(rcond >= m_m * eps)) {
        out.status = FrictionalContactStatus::singular;
        out.message = "singular Newton matrix at step " + std::to_string(it) +
                      " (reciprocal condition " + str(rcond) + " < m eps = " + str(m_m * eps) +
                      "): W singular on the closed contacts' rows?";
        break;
      }
      step = lu.solve(-m_s.cwiseProduct(f)).cwiseQuotient(m_s);
      // A row of J that is a row of the identity (open normal, rho = 0
      // tangential) says step_i = -F_i = -lambda_i exactly; the equilibrated
      // solve returns it only to round-off, and lambda_i + step_i would then
      // shrink by a factor eps per step towards 0 without reaching it (the
      // stopping test |lambda_i| <= eta Lambda cannot pass when every
      // multiplier is that remainder). Set it exactly.
      for (int i = 0; i < m_m; ++i)
        if (m_unit_row[i]) step(i) = -f(i);
      if (!step.allFinite()) {
        out.status = FrictionalContactStatus::singular;
        out.message = "non-finite Newton step at step " + std::to_string(it);
        break;
      }
      ++out.iterations;
      // Armijo on psi = 1/2 |S F|^2 (invariant to the scale of B's rows):
      // the Newton direction has slope -|S F|^2.
      const double psi = 0.5 * m_s.cwiseProduct(f).squaredNorm();
      double alpha = 1.0;
      bool accepted = false;
      for (int halving = 0; halving <= 30; ++halving, alpha *= 0.5) {
        trial = lambda + alpha * step;
        evaluate(trial, f_trial, nullptr);
        if (0.5 * m_s.cwiseProduct(f_trial).squaredNorm() <= (1.0 - 2e-4 * alpha) * psi) {
          accepted = true;
          break;
        }
      }
      if (!accepted) {
        // No decrease: accept the full step once if it passes the stopping
        // test (a round-off level F that the line search cannot improve).
        trial = lambda + step;
        if (evaluate(trial, f_trial, nullptr)) {
          lambda = trial;
          out.status = FrictionalContactStatus::converged;
          break;
        }
        out.status = FrictionalContactStatus::no_convergence;
        out.message = "no decrease of |F| along the Newton direction at step " +
                      std::to_string(it) + " (|F| = " + str(f.norm()) + ")";
        break;
      }
      lambda = trial;
    }
    out.lambda = lambda;
    out.q = m_p.gaps_and_slips(lambda);
    return out;
  }

private:
  const FrictionalContactProblem& m_p;
  int m_nc;
  int m_d;
  int m_b;
  int m_m;
  double m_mu;
  Eigen::VectorXd m_r;  ///< r_n per contact
  Eigen::VectorXd m_rt; ///< r_t per contact
  Eigen::VectorXd m_s;  ///< S = diag(W)^1/2 [sqrt(m/N)]
  std::vector<char> m_unit_row; ///< rows of the last Newton matrix that are rows of I
};

} // namespace

FrictionalContactSolver::FrictionalContactSolver(const FrictionalContactSolverOptions& options)
    : m_options(options) {
  if (options.max_iterations < 1)
    throw std::invalid_argument("FrictionalContactSolver: max_iterations = " +
                                std::to_string(options.max_iterations) + ", allowed [1, inf)");
  if (options.max_sweeps < 1)
    throw std::invalid_argument("FrictionalContactSolver: max_sweeps = " +
                                std::to_string(options.max_sweeps) + ", allowed [1, inf)");
}

FrictionalContactSolution FrictionalContactSolver::solve(const FrictionalContactProblem& p) const {
  return solve(p, Eigen::VectorXd::Zero(p.n_unknowns()));
}

namespace {

/// Newton from `start` with r = factor / W_ii, for each factor in turn;
/// the first success, or the first failure with every attempt's message.
FrictionalContactSolution newton_attempts(const FrictionalContactProblem& p,
                                          const Eigen::VectorXd& start,
                                          std::initializer_list<double> factors, int max_iterations,
                                          int& attempts, std::string& messages, bool& singular) {
  FrictionalContactSolution first;
  int iterations = 0;
  bool have_first = false;
  for (double factor : factors) {
    ++attempts;
    AlartCurnierNewton newton(p, factor);
    FrictionalContactSolution s = newton.run(start, max_iterations);
    iterations += s.iterations;
    if (s.ok()) {
      s.iterations = iterations;
      return s;
    }
    if (!have_first) first = s, have_first = true;
    singular = singular || s.status == FrictionalContactStatus::singular;
    messages += (messages.empty() ? "" : "; ") + std::string("Newton, r = ") + str(factor) +
                "/W_ii: " + s.message;
  }
  first.iterations = iterations;
  return first;
}

/// Nonsmooth block Gauss-Seidel (Jean, Moreau): contact by contact, the
/// one-contact problem with the others' multipliers frozen, solved by
/// Newton; sweeps until no multiplier moves by more than 1e-10 Lambda.
/// Returns whether the sweeps settled; lambda holds the last sweep.
bool gauss_seidel(const FrictionalContactProblem& p, Eigen::VectorXd& lambda, int max_sweeps,
                  int& sweeps, std::string& message) {
  const int nc = p.n_contacts(), d = p.n_tangents(), b = p.block_size();
  const Eigen::MatrixXd& w = p.w();
  for (sweeps = 1; sweeps <= max_sweeps; ++sweeps) {
    double change = 0.0;
    for (int c = 0; c < nc; ++c) {
      const Eigen::VectorXd old = lambda.segment(b * c, b);
      Eigen::VectorXd local = p.predicted().segment(b * c, b);
      local.noalias() += w.middleRows(b * c, b) * lambda;
      local.noalias() -= w.block(b * c, b * c, b, b) * old;
      const FrictionalContactProblem one(d, p.friction(), w.block(b * c, b * c, b, b),
                                         local.head(1), local.tail(d));
      int attempts = 0;
      std::string messages;
      bool singular = false;
      const FrictionalContactSolution s =
          newton_attempts(one, old, {1.0, 10.0, 0.1}, 100, attempts, messages, singular);
      if (!s.ok()) {
        message = "Gauss-Seidel: contact " + std::to_string(c) + " alone: " + messages;
        return false;
      }
      change = std::max(change, (s.lambda - old).cwiseAbs().maxCoeff());
      lambda.segment(b * c, b) = s.lambda;
    }
    if (change <= 1e-10 * lambda.cwiseAbs().maxCoeff()) return true;
  }
  message = "Gauss-Seidel: not settled in " + std::to_string(max_sweeps) + " sweeps";
  return false;
}

} // namespace

FrictionalContactSolution
FrictionalContactSolver::solve(const FrictionalContactProblem& p,
                               const Eigen::Ref<const Eigen::VectorXd>& initial) const {
  if (initial.size() != p.n_unknowns())
    throw std::invalid_argument("FrictionalContactSolver: initial has " +
                                std::to_string(initial.size()) + " entries, allowed exactly " +
                                std::to_string(p.n_unknowns()));
  if (!initial.allFinite())
    throw std::invalid_argument("FrictionalContactSolver: initial must be finite");
  const Eigen::VectorXd start = initial;
  int attempts = 0;
  std::string messages;
  bool singular = false;
  FrictionalContactSolution s = newton_attempts(
      p, start, {1.0, 10.0, 0.1}, m_options.max_iterations, attempts, messages, singular);
  int iterations = s.iterations;
  // A singular Newton matrix is reported, not worked around: on closed
  // contacts it means W singular there, the multipliers not unique.
  if (!s.ok() && !singular && p.n_contacts() > 1) {
    // Fallback: Gauss-Seidel towards the solution, then Newton to round-off.
    Eigen::VectorXd lambda = start;
    int sweeps = 0;
    std::string gs_message;
    const bool settled = gauss_seidel(p, lambda, m_options.max_sweeps, sweeps, gs_message);
    messages += "; " + (settled ? "Gauss-Seidel settled in " + std::to_string(sweeps) + " sweeps"
                                : gs_message);
    FrictionalContactSolution polished = newton_attempts(
        p, lambda, {1.0, 10.0, 0.1}, m_options.max_iterations, attempts, messages, singular);
    iterations += polished.iterations;
    polished.sweeps = sweeps;
    s = polished;
  }
  s.iterations = iterations;
  s.attempts = attempts;
  if (!s.ok())
    s.message = "frictional contact: no solution after " + std::to_string(attempts) +
                " Newton attempts (" + messages + ")";
  return s;
}

} // namespace rsi

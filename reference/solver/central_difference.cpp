#include "central_difference.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/SparseCholesky>

namespace rsi {

namespace {

/// M, once K, M and dt are checked to be usable together.
const Eigen::SparseMatrix<double>& checked_mass(const Eigen::SparseMatrix<double>& stiffness,
                                                const Eigen::SparseMatrix<double>& mass,
                                                double dt) {
  if (!(dt > 0.0)) throw std::invalid_argument("CentralDifference: dt must be > 0");
  if (stiffness.rows() != mass.rows() || stiffness.cols() != mass.cols() ||
      mass.rows() != mass.cols())
    throw std::invalid_argument("CentralDifference: K and M must be square and of the same size");
  return mass;
}

/// A = M + dt/2 C = (1 + alpha dt/2) M + (beta dt/2) K, the matrix the
/// damped step inverts; M itself (the same object, bit for bit) undamped.
Eigen::SparseMatrix<double> step_matrix(const Eigen::SparseMatrix<double>& stiffness,
                                        const Eigen::SparseMatrix<double>& mass, double dt,
                                        const RayleighDamping& d) {
  if (!(d.alpha >= 0.0 && d.beta >= 0.0 && std::isfinite(d.alpha) && std::isfinite(d.beta)))
    throw std::invalid_argument(
        "CentralDifference: Rayleigh damping alpha and beta must be finite and >= 0");
  const Eigen::SparseMatrix<double>& m = checked_mass(stiffness, mass, dt);
  if (!d.any()) return m;
  return (1.0 + 0.5 * d.alpha * dt) * m + (0.5 * d.beta * dt) * stiffness;
}

} // namespace

CentralDifference::CentralDifference(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::SparseMatrix<double>& mass, double dt,
                                     const ContactLaw& law, const RayleighDamping& damping)
    : m_dt(dt)
    , m_law(law)
    , m_damping(damping)
    , m_damped(damping.any())
    , m_mass_factor(step_matrix(stiffness, mass, dt, damping))
    , m_position(m_mass_factor.position())
    , m_k(m_mass_factor.permuted(stiffness))
    , m_m(m_mass_factor.permuted(mass))
    , m_k_rows(m_k)
    , m_law_dofs(law.dofs_read(static_cast<int>(mass.rows())))
    , m_inverse_columns(mass.rows()) {
  for (int dof : m_law_dofs) {
    if (dof < 0 || dof >= mass.rows())
      throw std::invalid_argument("CentralDifference: the contact law reads dof " +
                                  std::to_string(dof) + ", outside the system");
    m_law_positions.push_back(m_position(dof));
  }
  if (m_damping.alpha > 0.0) m_m_rows = SparseRows(m_m);
}

void CentralDifference::to_physical(const Eigen::VectorXd& permuted, Eigen::VectorXd& physical,
                                    Eigen::VectorXd& velocity) const {
  const double rate = 1.0 / m_dt;
  for (size_t k = 0; k < m_law_dofs.size(); ++k) {
    const int i = m_law_dofs[k];
    physical(i) = permuted(m_law_positions[k]);
    velocity(i) = (physical(i) - m_x(i)) * rate;
  }
}

const Eigen::VectorXd& CentralDifference::displacement() const {
  if (m_displacement_step != m_n) {
    m_displacement.resize(m_u.size());
    for (Eigen::Index i = 0; i < m_u.size(); ++i)
      m_displacement(i) = m_u(m_position(i));
    m_displacement_step = m_n;
  }
  return m_displacement;
}

const CentralDifference::InverseMassColumn& CentralDifference::inverse_mass_column(int dof) {
  InverseMassColumn& column = m_inverse_columns[dof];
  if (column.values.size() == 0) {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(m_m.rows());
    full(m_position(dof)) = 1.0;
    apply_inverse_mass(full);
    const auto [first, size] = m_mass_factor.block(m_position(dof));
    column.first = first;
    column.values = full.segment(first, size);
  }
  return column;
}

double CentralDifference::contact_flexibility(const SparseRow& gradient,
                                              const SparseRow& direction) {
  double sum = 0.0;
  for (const auto& [b, db] : direction) {
    const InverseMassColumn& column = inverse_mass_column(b);
    for (const auto& [a, ga] : gradient)
      sum += ga * db * column(m_position(a));
  }
  return m_dt * m_dt * sum;
}

double CentralDifference::permuted_dot(const SparseRow& row, const Eigen::VectorXd& u) const {
  double sum = 0.0;
  for (const auto& [dof, c] : row)
    sum += c * u(m_position(dof));
  return sum;
}

double CentralDifference::flops_per_step() const {
  const double nnz_l = m_mass_factor.nonzeros_l();
  const double n = static_cast<double>(m_k.rows());
  double flops = 2.0 * static_cast<double>(m_k.nonZeros()) + 4.0 * nnz_l + 13.0 * n;
  if (m_damped) flops += 8.0 * n;
  if (m_damping.alpha > 0.0) flops += 2.0 * static_cast<double>(m_m.nonZeros());
  return flops;
}

double CentralDifference::energy() const {
  const Eigen::VectorXd v = (m_u - m_u_prev) / m_dt;
  return 0.5 * v.dot(m_m * v) + 0.5 * m_u_prev.dot(m_ku);
}

void CentralDifference::set_force(const Eigen::Ref<const Eigen::VectorXd>& f) {
  if (f.size() != m_m.rows())
    throw std::invalid_argument("CentralDifference: the force must have one entry per dof");
  m_force.resize(f.size());
  for (Eigen::Index i = 0; i < f.size(); ++i)
    m_force(m_position(i)) = f(i);
  m_forced = m_force.any();
}

void CentralDifference::start(const Eigen::Ref<const Eigen::VectorXd>& f0) {
  const int n = static_cast<int>(m_m.rows());
  m_n = 0;
  set_force(f0);
  m_u = Eigen::VectorXd::Zero(n);
  m_u_prev = 0.5 * m_dt * m_dt * m_force;
  if (m_damped) {
    // At rest v_0 = (u_1 - u_{-1}) / (2 dt) = 0 needs u_{-1} = dt^2/2 M^-1 F_0
    // with M itself (then u_1 = u_{-1}: the damping force of step 0 is zero),
    // not A^-1: one solve with a factor of M' made for it.
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> mass{Eigen::SparseMatrix<double>(m_m)};
    if (mass.info() != Eigen::Success || !(mass.vectorD().minCoeff() > 0.0))
      throw IntegrationError("central differences: the mass matrix is not positive definite");
    m_u_prev = mass.solve(m_u_prev).eval();
    if (mass.info() != Eigen::Success || !m_u_prev.allFinite())
      throw IntegrationError("central differences: the start u_{-1} = dt^2/2 M^-1 F_0 failed");
  } else {
    apply_inverse_mass(m_u_prev);
  }
  m_ku = Eigen::VectorXd::Zero(n);
  if (m_damped) {
    // C' u'_0 = 0 and C' u'_{-1}.
    m_cu = Eigen::VectorXd::Zero(n);
    m_cu_prev = Eigen::VectorXd::Zero(n);
    m_cu_next.resize(n);
    m_mu.resize(n);
    if (m_damping.alpha > 0.0) {
      m_m_rows.multiply(m_u_prev, m_mu);
      m_cu_prev += m_damping.alpha * m_mu;
    }
    if (m_damping.beta > 0.0) {
      m_k_rows.multiply(m_u_prev, m_mu);
      m_cu_prev += m_damping.beta * m_mu;
    }
  }
  m_x = Eigen::VectorXd::Zero(n);
  m_x_next = Eigen::VectorXd::Zero(n);
  m_velocity = Eigen::VectorXd::Zero(n);
  m_displacement_step = -1;
  const int nc = m_law.n_constraints();
  m_lambda = Eigen::VectorXd::Zero(nc);
  m_active.assign(nc, 0);
  m_w.resize(nc, nc);
  m_w_step = Eigen::MatrixXi::Constant(nc, nc, -1);
  m_law.evaluate(m_x, m_velocity, 0.0, m_state);
  m_gap = m_state.gap;
  m_initial_energy = energy();
  m_external_work = 0.0;
  m_contact_work = 0.0;
  m_damping_work = 0.0;
}

void CentralDifference::solve_active_set(const ContactState& s, Eigen::VectorXd& lambda,
                                         Eigen::VectorXd& correction) {
  const int nc = m_law.n_constraints();
  lambda.setZero(nc);
  bool any = false;
  for (int k = 0; k < nc; ++k)
    any |= (m_active[k] = s.gap(k) < 0.0);
  if (!any) return;
  // W_ij = dt^2 G_i M^-1 D_j^T for the active pairs met, computed once per step.
  auto entry = [&](int i, int j) {
    if (m_w_step(i, j) != m_n) {
      m_w(i, j) = contact_flexibility(s.gradient[i], s.direction[j]);
      m_w_step(i, j) = m_n;
    }
    return m_w(i, j);
  };
  std::vector<int>& idx = m_active_index;
  for (int iteration = 0; iteration <= 4 * nc + 4; ++iteration) {
    idx.clear();
    for (int k = 0; k < nc; ++k)
      if (m_active[k]) idx.push_back(k);
    const int na = static_cast<int>(idx.size());
    if (na == 0) return;
    m_w_active.resize(na, na);
    m_rhs.resize(na);
    for (int a = 0; a < na; ++a) {
      m_rhs(a) = -s.gap(idx[a]);
      for (int b = 0; b < na; ++b)
        m_w_active(a, b) = entry(idx[a], idx[b]);
    }
    m_lu.compute(m_w_active);
    if (!m_lu.isInvertible())
      throw IntegrationError("central differences: singular contact matrix W (" +
                             std::to_string(na) + " active constraints) at step " +
                             std::to_string(m_n + 1));
    m_lambda_active = m_lu.solve(m_rhs);
    const Eigen::VectorXd& la = m_lambda_active;
    Eigen::Index most_negative = 0;
    if (la.minCoeff(&most_negative) < 0.0) {
      m_active[idx[most_negative]] = false;
      continue;
    }
    // u_{n+1} - u~ = dt^2 M^-1 sum_j lambda_j D_j^T.
    correction.setZero(m_m.rows());
    for (int b = 0; b < na; ++b)
      for (const auto& [dof, c] : s.direction[idx[b]]) {
        const InverseMassColumn& column = inverse_mass_column(dof);
        correction.segment(column.first, column.values.size()) +=
            (m_dt * m_dt * la(b) * c) * column.values;
      }
    // A constraint the correction would close joins the active set:
    // g_k + G_k (u_{n+1} - u~) = g_k + sum_j W_kj lambda_j < 0.
    bool added = false;
    for (int k = 0; k < nc; ++k)
      if (!m_active[k] && s.gap(k) + permuted_dot(s.gradient[k], correction) < 0.0)
        m_active[k] = added = true;
    if (added) continue;
    for (int b = 0; b < na; ++b)
      lambda(idx[b]) = la(b);
    return;
  }
  throw IntegrationError("central differences: the active set did not settle at step " +
                         std::to_string(m_n + 1));
}

void CentralDifference::add_damping_work() {
  // Here m_u = u'_{n+1}, m_predicted = u'_{n-1}, m_ku = K'u'_{n+1},
  // m_cu = C'u'_n, m_cu_prev = C'u'_{n-1}. The damping force of step n is
  // C (u_{n+1} - u_{n-1}) / (2 dt); its work is that force times
  // (u_{n+1} - u_{n-1}) / 2.
  m_cu_next = m_damping.beta * m_ku;
  if (m_damping.alpha > 0.0) {
    m_m_rows.multiply(m_u, m_mu);
    m_cu_next += m_damping.alpha * m_mu;
  }
  m_damping_work += (0.25 / m_dt) * (m_u - m_predicted).dot(m_cu_next - m_cu_prev);
  m_cu_prev.swap(m_cu); // C'u'_n
  m_cu.swap(m_cu_next); // C'u'_{n+1}
}

StepReport CentralDifference::step() {
  const double dt2 = m_dt * m_dt;
  if (m_forced)
    m_predicted = m_force - m_ku;
  else
    m_predicted = -m_ku;
  if (m_damped) m_predicted -= (m_cu - m_cu_prev) / m_dt; // C (u_n - u_{n-1}) / dt
  apply_inverse_mass(m_predicted);                        // A^-1, A = M undamped
  m_predicted = 2.0 * m_u - m_u_prev + dt2 * m_predicted;
  const double t_next = (m_n + 1) * m_dt;
  to_physical(m_predicted, m_x_next, m_velocity);
  m_law.evaluate(m_x_next, m_velocity, t_next, m_predicted_state);
  const ContactState& s = m_predicted_state;
  solve_active_set(s, m_lambda, m_correction);
  const bool corrected = m_lambda.any();

  // Works of step n: (F_n + R_n)^T (u_{n+1} - u_{n-1}) / 2, R_n = sum lambda_k D_k^T;
  // m_predicted becomes u_{n+1}.
  if (corrected) m_predicted += m_correction;
  if (m_forced) m_external_work += 0.5 * (m_force.dot(m_predicted) - m_force.dot(m_u_prev));
  for (int k = 0; k < m_lambda.size(); ++k)
    if (m_lambda(k) != 0.0)
      m_contact_work +=
          0.5 * m_lambda(k) *
          (permuted_dot(s.direction[k], m_predicted) - permuted_dot(s.direction[k], m_u_prev));

  m_u_prev.swap(m_u);
  m_u.swap(m_predicted);
  m_k_rows.multiply(m_u, m_ku);
  if (m_damped) add_damping_work();
  ++m_n;

  // Monitors at the corrected state (SPEC V5).
  // Without a correction u_{n+1} is the prediction: same gaps, same velocities.
  if (corrected) {
    to_physical(m_u, m_x_next, m_velocity);
    m_law.evaluate(m_x_next, m_velocity, t_next, m_state);
  }
  m_x.swap(m_x_next);
  const ContactState& after = corrected ? m_state : s;
  m_gap = after.gap;
  StepReport report;
  const double mu = m_law.friction_coefficient();
  for (int k = 0; k < m_lambda.size(); ++k) {
    report.max_penetration = std::max(report.max_penetration, -m_gap(k));
    report.min_lambda = std::min(report.min_lambda, m_lambda(k));
    report.max_complementarity =
        std::max(report.max_complementarity, std::abs(m_lambda(k) * m_gap(k)));
    if (m_lambda(k) == 0.0) continue;
    ++report.n_active;
    if (mu > 0.0) {
      // The friction force applied is -mu s lambda (s from the prediction); the
      // law wants -mu sign(v_slide) lambda with the corrected sliding velocity.
      const double actual =
          after.sliding_velocity(k) > 0.0 ? 1.0 : (after.sliding_velocity(k) < 0.0 ? -1.0 : 0.0);
      const double residual = mu * m_lambda(k) * std::abs(s.friction_sign(k) - actual);
      report.max_friction_residual = std::max(report.max_friction_residual, residual);
      if (actual != s.friction_sign(k)) ++report.sliding_reversals;
    }
  }
  return report;
}

} // namespace rsi

#include "central_difference.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/SparseCholesky>

namespace rsi {

namespace {

// What to change, for the messages of IntegrationError: the integrator
// serves the paper's case and the components (the CLI names both keys).
const std::string kMassWhy = "; the paper's case checks its M when it loads; a component's M "
                             "must be positive definite for a full-order run";
const FailureAdvice kMassAdvice = remedied_by({Remedy::lumped_mass_or_reduced_method});
const FailureAdvice kStepRemedy = remedied_by({Remedy::smaller_step_unforced});
const FailureAdvice kContactRemedy = remedied_by({Remedy::friction_or_smaller_step});

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
    : CentralDifference(stiffness, mass, dt, &law, nullptr, damping, {}) {}

CentralDifference::CentralDifference(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::SparseMatrix<double>& mass, double dt,
                                     const FrictionalContactLaw& law,
                                     const RayleighDamping& damping,
                                     const FrictionalContactSolverOptions& solver_options)
    : CentralDifference(stiffness, mass, dt, nullptr, &law, damping, solver_options) {}

CentralDifference::CentralDifference(const Eigen::SparseMatrix<double>& stiffness,
                                     const Eigen::SparseMatrix<double>& mass, double dt,
                                     const ContactLaw* law, const FrictionalContactLaw* frictional,
                                     const RayleighDamping& damping,
                                     const FrictionalContactSolverOptions& solver_options)
    : m_dt(dt)
    , m_law(law)
    , m_frictional(frictional)
    , m_solver(solver_options)
    , m_n_tangents(frictional ? frictional->n_tangents() : 0)
    , m_damping(damping)
    , m_damped(damping.any())
    , m_mass_factor(step_matrix(stiffness, mass, dt, damping))
    , m_position(m_mass_factor.position())
    , m_k(m_mass_factor.permuted(stiffness))
    , m_m(m_mass_factor.permuted(mass))
    , m_k_rows(m_k)
    , m_law_dofs(law ? law->dofs_read(static_cast<int>(mass.rows()))
                     : frictional->dofs_read(static_cast<int>(mass.rows())))
    , m_inverse_columns(mass.rows()) {
  if (frictional) {
    if (frictional->n_contacts() < 1)
      throw std::invalid_argument("CentralDifference: the frictional contact law has " +
                                  std::to_string(frictional->n_contacts()) +
                                  " contacts, allowed >= 1");
    if (m_n_tangents != 1 && m_n_tangents != 2)
      throw std::invalid_argument("CentralDifference: the frictional contact law has " +
                                  std::to_string(m_n_tangents) + " tangents, allowed 1 or 2");
    const double mu = frictional->friction_coefficient();
    if (!(mu >= 0.0 && std::isfinite(mu)))
      throw std::invalid_argument("CentralDifference: friction coefficient must be finite and >= 0");
  }
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
      throw IntegrationError(
          "central differences: the mass matrix is not positive definite" + kMassWhy, kMassAdvice);
    m_u_prev = mass.solve(m_u_prev).eval();
    if (mass.info() != Eigen::Success || !m_u_prev.allFinite())
      throw IntegrationError(
          "central differences: the start u_{-1} = dt^2/2 M^-1 F_0 failed" + kMassWhy, kMassAdvice);
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
  if (m_frictional) {
    const int nc = m_frictional->n_contacts();
    const int rows = (1 + m_n_tangents) * nc;
    m_lambda = Eigen::VectorXd::Zero(nc);
    m_lambda_t = Eigen::VectorXd::Zero(m_n_tangents * nc);
    m_in_play.assign(nc, 0);
    m_classes.assign(nc, ContactClass::open);
    m_slip_direction = Eigen::VectorXd::Zero(m_n_tangents * nc);
    m_wf.resize(rows, rows);
    m_wf_step = Eigen::MatrixXi::Constant(rows, rows, -1);
    // The gaps at u_0 = 0, t = 0 (a step of zero increment).
    m_frictional->evaluate(m_x, m_x, 0.0, m_dt, m_geometry);
    m_gap = m_geometry.normal_gap;
  } else {
    const int nc = m_law->n_constraints();
    m_lambda = Eigen::VectorXd::Zero(nc);
    m_active.assign(nc, 0);
    m_w.resize(nc, nc);
    m_w_step = Eigen::MatrixXi::Constant(nc, nc, -1);
    m_law->evaluate(m_x, m_velocity, 0.0, m_state);
    m_gap = m_state.gap;
  }
  m_initial_energy = energy();
  m_external_work = 0.0;
  m_contact_work = 0.0;
  m_damping_work = 0.0;
}

void CentralDifference::solve_active_set(const ContactState& s, Eigen::VectorXd& lambda,
                                         Eigen::VectorXd& correction) {
  const int nc = m_law->n_constraints();
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
                                 std::to_string(m_n + 1),
                             kContactRemedy);
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
                             std::to_string(m_n + 1),
                         kStepRemedy);
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

void CentralDifference::predict() {
  const double dt2 = m_dt * m_dt;
  if (m_forced)
    m_predicted = m_force - m_ku;
  else
    m_predicted = -m_ku;
  if (m_damped) m_predicted -= (m_cu - m_cu_prev) / m_dt; // C (u_n - u_{n-1}) / dt
  apply_inverse_mass(m_predicted);                        // A^-1, A = M undamped
  m_predicted = 2.0 * m_u - m_u_prev + dt2 * m_predicted;
  to_physical(m_predicted, m_x_next, m_velocity);
}

void CentralDifference::advance() {
  if (m_forced) m_external_work += 0.5 * (m_force.dot(m_predicted) - m_force.dot(m_u_prev));
  m_u_prev.swap(m_u);
  m_u.swap(m_predicted);
  m_k_rows.multiply(m_u, m_ku);
  if (m_damped) add_damping_work();
  ++m_n;
}

StepReport CentralDifference::step() {
  if (m_frictional) return step_coulomb();
  predict();
  const double t_next = (m_n + 1) * m_dt;
  m_law->evaluate(m_x_next, m_velocity, t_next, m_predicted_state);
  const ContactState& s = m_predicted_state;
  solve_active_set(s, m_lambda, m_correction);
  const bool corrected = m_lambda.any();

  // Works of step n: (F_n + R_n)^T (u_{n+1} - u_{n-1}) / 2, R_n = sum lambda_k D_k^T;
  // m_predicted becomes u_{n+1}.
  if (corrected) m_predicted += m_correction;
  for (int k = 0; k < m_lambda.size(); ++k)
    if (m_lambda(k) != 0.0)
      m_contact_work +=
          0.5 * m_lambda(k) *
          (permuted_dot(s.direction[k], m_predicted) - permuted_dot(s.direction[k], m_u_prev));
  advance();

  // Monitors at the corrected state (SPEC V5).
  // Without a correction u_{n+1} is the prediction: same gaps, same velocities.
  if (corrected) {
    to_physical(m_u, m_x_next, m_velocity);
    m_law->evaluate(m_x_next, m_velocity, t_next, m_state);
  }
  m_x.swap(m_x_next);
  const ContactState& after = corrected ? m_state : s;
  m_gap = after.gap;
  StepReport report;
  const double mu = m_law->friction_coefficient();
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

void CentralDifference::solve_coulomb(FrictionalContactCertificate& certificate) {
  const int nc = m_frictional->n_contacts();
  const int d = m_n_tangents;
  const int b = 1 + d;
  const FrictionalContactGeometry& geo = m_geometry;
  const double dt2 = m_dt * m_dt;
  // W entries by row pair, once per step (the upper triangle, mirrored).
  auto entry = [&](int i, int j) {
    if (i > j) std::swap(i, j);
    if (m_wf_step(i, j) != m_n) {
      m_wf(i, j) = contact_flexibility(geo.rows[i], geo.rows[j]);
      m_wf_step(i, j) = m_n;
    }
    return m_wf(i, j);
  };
  for (int iteration = 0; iteration <= nc; ++iteration) {
    m_play.clear();
    for (int c = 0; c < nc; ++c)
      if (m_in_play[c]) m_play.push_back(c);
    const int np = static_cast<int>(m_play.size());
    const int m = b * np;
    Eigen::MatrixXd w(m, m);
    Eigen::VectorXd gap(np), slip(d * np), initial(m);
    for (int a = 0; a < np; ++a) {
      const int ca = m_play[a];
      gap(a) = geo.normal_gap(ca);
      slip.segment(d * a, d) = geo.slip.segment(d * ca, d);
      initial(b * a) = m_lambda(ca);
      initial.segment(b * a + 1, d) = m_lambda_t.segment(d * ca, d);
      for (int p = 0; p < b; ++p)
        for (int e = 0; e < np; ++e)
          for (int q = 0; q < b; ++q)
            w(b * a + p, b * e + q) = entry(b * ca + p, b * m_play[e] + q);
    }
    const FrictionalContactProblem problem(d, m_frictional->friction_coefficient(), w, gap, slip);
    const FrictionalContactSolution solution = m_solver.solve(problem, initial);
    if (!solution.ok())
      throw IntegrationError("central differences: the frictional contact solver failed at step " +
                                 std::to_string(m_n + 1) + " (" + std::to_string(np) +
                                 " contacts in play): " + solution.message,
                             kContactRemedy);
    if (!solution.lambda.allFinite())
      throw IntegrationError("central differences: non-finite contact multipliers at step " +
                                 std::to_string(m_n + 1),
                             kStepRemedy);
    // u_{n+1} - u~ = dt^2 A^-1 B^T lambda.
    m_correction.setZero(m_m.rows());
    for (int a = 0; a < np; ++a)
      for (int p = 0; p < b; ++p) {
        const double l = solution.lambda(b * a + p);
        if (l == 0.0) continue;
        for (const auto& [dof, coefficient] : geo.rows[b * m_play[a] + p]) {
          const InverseMassColumn& column = inverse_mass_column(dof);
          m_correction.segment(column.first, column.values.size()) +=
              (dt2 * l * coefficient) * column.values;
        }
      }
    // A contact out of play that the correction would close joins it.
    bool added = false;
    for (int c = 0; c < nc; ++c)
      if (!m_in_play[c] &&
          geo.normal_gap(c) + permuted_dot(geo.rows[b * c], m_correction) < 0.0)
        m_in_play[c] = added = true;
    if (added) continue;
    m_lambda.setZero();
    m_lambda_t.setZero();
    for (int a = 0; a < np; ++a) {
      m_lambda(m_play[a]) = solution.lambda(b * a);
      m_lambda_t.segment(d * m_play[a], d) = solution.lambda.segment(b * a + 1, d);
    }
    certificate = certify(problem, solution.lambda);
    // Slip directions, for the reversal count: -lambda_t / |lambda_t| (in
    // slip lambda_t = -mu lambda_n s^, and unlike s^ it is defined when the
    // contact holds on the cone's edge with a round-off slip).
    for (int a = 0; a < np; ++a) {
      const Eigen::VectorXd lt = solution.lambda.segment(b * a + 1, d);
      const double norm = lt.norm();
      if (certificate.classes[a] == ContactClass::slip && norm > 0.0) {
        const int c = m_play[a];
        const Eigen::VectorXd direction = -lt / norm;
        // m_slip_direction still holds the previous step's direction here.
        if (m_classes[c] == ContactClass::slip &&
            direction.dot(m_slip_direction.segment(d * c, d)) < 0.0)
          m_reversals_this_step++;
        m_slip_direction.segment(d * c, d) = direction;
      }
    }
    return;
  }
  throw IntegrationError(
      "central differences: the set of contacts in play did not settle at step " +
          std::to_string(m_n + 1),
      kStepRemedy);
}

double CentralDifference::liner_contact_work() const {
  if (!m_liner) return m_contact_work;
  return m_contact_work + m_liner->elastic_energy() + m_liner->plastic_work();
}

double CentralDifference::liner_unmatched_work() const {
  if (!m_liner) return 0.0;
  return (m_wall_work - m_normal_work) - (m_liner->elastic_energy() + m_liner->plastic_work());
}

void CentralDifference::attach_liner(LinerSurface& liner) {
  if (m_frictional != &liner.law())
    throw std::invalid_argument("CentralDifference::attach_liner: the liner is on another contact law");
  const int nc = m_frictional->n_contacts();
  const int b = 1 + m_n_tangents;
  // The rows are the undeformed nodes' frames, the same at every step.
  FrictionalContactGeometry geo;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m_m.rows());
  m_frictional->evaluate(zero, zero, 0.0, m_dt, geo);
  // W diagonal with equal entries on a node's rows, to 1e-12 relative (a
  // lumped node block m I gives dt^2/m exactly off round-off of the frame).
  const double tolerance = 1e-12;
  for (int i = 0; i < b * nc; ++i) {
    const double wii = contact_flexibility(geo.rows[i], geo.rows[i]);
    const double wnn = contact_flexibility(geo.rows[b * (i / b)], geo.rows[b * (i / b)]);
    if (!(wii > 0.0) || std::abs(wii - wnn) > tolerance * wnn)
      throw std::invalid_argument("contact node " + std::to_string(i / b) +
                                  ": its normal and tangential compliances differ (the liner's "
                                  "node-by-node solve needs a lumped mass)");
    for (int j = i + 1; j < b * nc; ++j) {
      const double wjj = contact_flexibility(geo.rows[j], geo.rows[j]);
      if (std::abs(contact_flexibility(geo.rows[i], geo.rows[j])) > tolerance * std::sqrt(wii * wjj))
        throw std::invalid_argument(
            (i / b == j / b ? "contact node " + std::to_string(i / b) +
                                  ": its normal and tangential rows are"
                            : "contact nodes " + std::to_string(i / b) + " and " +
                                  std::to_string(j / b) + " are") +
            " coupled through the mass (the liner's node-by-node solve needs a lumped mass, "
            "the same in x, y and z at a node, and no stiffness-proportional damping)");
    }
  }
  m_liner = &liner;
}

void CentralDifference::solve_liner(FrictionalContactCertificate& certificate, double t_next) {
  const int nc = m_frictional->n_contacts();
  const int d = m_n_tangents;
  const int b = 1 + d;
  const FrictionalContactGeometry& geo = m_geometry;
  const double dt2 = m_dt * m_dt;
  const double mu = m_frictional->friction_coefficient();
  m_liner->begin_step();
  m_play.clear();
  m_lambda.setZero();
  m_lambda_t.setZero();
  m_correction.setZero(m_m.rows());
  certificate = FrictionalContactCertificate{};
  for (int c = 0; c < nc; ++c) {
    const double w = contact_flexibility(geo.rows[b * c], geo.rows[b * c]);
    const double force = m_liner->respond(c, t_next, geo.normal_gap(c), w);
    if (!(force > 0.0)) continue;
    m_play.push_back(c);
    m_lambda(c) = force;
    // Coulomb on the disk of radius mu F: the stick multiplier cancels the
    // predicted slip (s~ + W_tt lambda_t = 0); beyond the disk, its
    // projection (the slip law lambda_t = -mu F s~/|s~|).
    Eigen::VectorXd lt = -geo.slip.segment(d * c, d) / w;
    const double norm = lt.norm();
    const double radius = mu * force;
    ContactClass cls = ContactClass::stick;
    if (norm > radius) {
      lt *= norm > 0.0 ? radius / norm : 0.0;
      cls = ContactClass::slip;
    }
    m_lambda_t.segment(d * c, d) = lt;
    certificate.classes.push_back(cls);
    (cls == ContactClass::slip ? certificate.n_slip : certificate.n_stick)++;
    if (cls == ContactClass::slip && lt.norm() > 0.0) {
      const Eigen::VectorXd direction = -lt / lt.norm();
      if (m_classes[c] == ContactClass::slip &&
          direction.dot(m_slip_direction.segment(d * c, d)) < 0.0)
        m_reversals_this_step++;
      m_slip_direction.segment(d * c, d) = direction;
    }
    for (int p = 0; p < b; ++p) {
      const double l = p == 0 ? force : lt(p - 1);
      if (l == 0.0) continue;
      for (const auto& [dof, coefficient] : geo.rows[b * c + p]) {
        const InverseMassColumn& column = inverse_mass_column(dof);
        m_correction.segment(column.first, column.values.size()) +=
            (dt2 * l * coefficient) * column.values;
      }
    }
  }
}

StepReport CentralDifference::step_coulomb() {
  predict();
  const double t_next = (m_n + 1) * m_dt;
  const int nc = m_frictional->n_contacts();
  const int d = m_n_tangents;
  const int b = 1 + d;
  m_frictional->evaluate(m_x, m_x_next, t_next, m_dt, m_geometry);
  const FrictionalContactGeometry& geo = m_geometry;
  if (!geo.normal_gap.allFinite() || !geo.slip.allFinite())
    throw IntegrationError("central differences: non-finite predicted gap or slip at step " +
                               std::to_string(m_n + 1) + " (t = " + std::to_string(t_next) +
                               " s): the state blew up",
                           kStepRemedy);
  bool any = false;
  for (int c = 0; c < nc; ++c) {
    m_in_play[c] = geo.normal_gap(c) < 0.0 || m_lambda(c) != 0.0 ||
                   m_lambda_t.segment(d * c, d).any();
    any |= m_in_play[c] != 0;
  }
  FrictionalContactCertificate certificate;
  m_reversals_this_step = 0;
  if (m_liner) {
    solve_liner(certificate, t_next);
  } else if (any) {
    solve_coulomb(certificate);
  } else {
    m_lambda.setZero();
    m_lambda_t.setZero();
    m_play.clear();
  }
  const bool corrected = m_lambda.any() || m_lambda_t.any();

  // Works of step n: (F_n + R_n)^T (u_{n+1} - u_{n-1}) / 2, R_n = B^T lambda
  // over every row; m_predicted becomes u_{n+1}.
  if (corrected) {
    m_predicted += m_correction;
    for (int c : m_play)
      for (int p = 0; p < b; ++p) {
        const double l = p == 0 ? m_lambda(c) : m_lambda_t(d * c + p - 1);
        if (l == 0.0) continue;
        const SparseRow& row = geo.rows[b * c + p];
        const double work = 0.5 * l * (permuted_dot(row, m_predicted) - permuted_dot(row, m_u_prev));
        m_contact_work += work;
        if (m_liner && p == 0) {
          m_normal_work += work;
          const RigidSurfaceContact& law = m_liner->law();
          m_wall_work -= 0.5 * l * (law.imposed_gap(c, t_next) - law.imposed_gap(c, t_next - 2.0 * m_dt));
        }
      }
  }
  advance();
  if (m_liner) {
    m_liner->commit_step();
    if (!m_liner->worn_through().empty())
      throw IntegrationError("central differences: step " + std::to_string(m_n) + " (t = " +
                                 std::to_string(t_next) + " s): " + m_liner->worn_through(),
                             remedied_by({Remedy::thicker_liner_or_larger_clearance}));
  }

  // Monitors at the corrected state: the law at (u_n, u_{n+1}) (m_x is still
  // u_n on the law's dofs); without a correction u_{n+1} is the prediction.
  if (corrected) {
    to_physical(m_u, m_x_next, m_velocity);
    m_frictional->evaluate(m_x, m_x_next, t_next, m_dt, m_geometry_after);
    m_gap = m_geometry_after.normal_gap;
  } else {
    m_gap = geo.normal_gap;
  }
  m_x.swap(m_x_next);

  StepReport report;
  report.sliding_reversals = m_reversals_this_step;
  std::vector<ContactClass> classes(nc, ContactClass::open);
  for (size_t a = 0; a < m_play.size(); ++a)
    classes[m_play[a]] = certificate.classes[a];
  for (int c = 0; c < nc; ++c) {
    report.max_penetration = std::max(report.max_penetration, -m_gap(c));
    report.min_lambda = std::min(report.min_lambda, m_lambda(c));
    report.max_complementarity =
        std::max(report.max_complementarity, std::abs(m_lambda(c) * m_gap(c)));
    if (m_lambda(c) > 0.0) ++report.n_active;
    if (classes[c] != m_classes[c]) ++report.stick_slip_transitions;
  }
  m_classes.swap(classes);
  if (!m_play.empty()) {
    report.max_cone_violation = certificate.max_cone_violation;
    report.max_stick_slip_residual =
        std::max(certificate.stick_residual, certificate.slip_residual);
    report.max_friction_residual = certificate.max_slip_residual;
    report.n_stick = certificate.n_stick;
    report.n_slip = certificate.n_slip;
  }
  return report;
}

} // namespace rsi

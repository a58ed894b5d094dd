#include "full_casing_part.hpp"

#include <string>

#include "reduced_integrator.hpp"

namespace rsi {

namespace {

const std::string kCasingMassRemedy =
    "; change casing.section or material.density (the loader checks the casing's M: report "
    "this case)";

} // namespace

FullCasingPart::FullCasingPart(const Casing& casing, double dt, const RayleighDamping& damping)
    : CasingPart(casing, dt, damping)
    , m_kc_rows(m_kc) {
  const int nc = casing.n_dofs();
  m_dc = m_kc_c = Eigen::VectorXd::Zero(nc);
  // A_c = M_c + dt/2 (alpha M_c + beta K_c) (M_c undamped).
  const Eigen::SparseMatrix<double> a_c =
      m_damped ? Eigen::SparseMatrix<double>((1.0 + 0.5 * dt * m_damping.alpha) * casing.mass +
                                             (0.5 * dt * m_damping.beta) * casing.stiffness)
               : casing.mass;
  m_factor.compute(a_c);
  // Eigen's LDL^T flags only zero pivots: positive definite means every D_jj > 0.
  if (m_factor.info() != Eigen::Success || !(m_factor.vectorD().minCoeff() > 0.0))
    throw ReducedIntegrationError(std::string("reduced integrator: the casing mass matrix") +
                                  (m_damped ? " plus dt/2 C_c" : "") +
                                  " is not positive definite" + kCasingMassRemedy);
  m_flexibility = m_factor.solve(Eigen::MatrixXd::Identity(nc, nc));
  m_order.resize(nc);
  for (int i = 0; i < nc; ++i)
    m_order[i] = m_factor.permutationP().size() > 0 ? m_factor.permutationP().indices()(i) : i;
  m_inverse_d = m_factor.vectorD().cwiseInverse();
}

double FullCasingPart::flops_per_step() const {
  const auto n = static_cast<double>(m_kc.rows());
  const auto nnz_l = static_cast<double>(m_factor.matrixL().nestedExpression().nonZeros());
  double flops = 2.0 * static_cast<double>(m_kc.nonZeros()) + 4.0 * nnz_l + 5.0 * n;
  if (m_damped) flops += 4.0 * static_cast<double>(m_mc.nonZeros() + m_kc.nonZeros()) + 10.0 * n;
  return flops;
}

double FullCasingPart::energy() const {
  const Eigen::VectorXd vc = (m_c - m_c_prev) / m_dt;
  return 0.5 * vc.dot(m_mc * vc) + 0.5 * m_c_prev.dot(m_kc * m_c);
}

void FullCasingPart::start() {
  m_c = Eigen::VectorXd::Zero(m_kc.rows());
  if (m_damped) {
    // At rest c_{-1} = dt^2/2 M_c^-1 F with M_c itself (not A_c), so c_1 = c_{-1}.
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> mass(m_mc);
    if (mass.info() != Eigen::Success || !(mass.vectorD().minCoeff() > 0.0))
      throw ReducedIntegrationError(
          "reduced integrator: the casing mass matrix is not positive definite" +
          kCasingMassRemedy);
    m_c_prev = 0.5 * m_dt * m_dt * mass.solve(m_force);
  } else {
    m_c_prev = 0.5 * m_dt * m_dt * m_factor.solve(m_force);
  }
}

void FullCasingPart::predict() {
  // With P A_c P^T = L D L^T: y = P (F - K_c c_n), y <- L^-T D^-1 L^-1 y by
  // Eigen's triangular solves on the factor (no permutation in place), and
  // c~(j) = 2 c_n(j) - c_{n-1}(j) + dt^2 y(P(j)).
  const int n = static_cast<int>(m_c.size());
  const double dt2 = m_dt * m_dt;
  m_kc_rows.multiply(m_c, m_kc_c);
  if (m_damped) {
    // K_c c_n + C_c (c_n - c_{n-1}) / dt, C_c = alpha M_c + beta K_c.
    m_c_delta = m_c - m_c_prev;
    m_c_damping.noalias() = m_mc * m_c_delta;
    m_c_damping *= m_damping.alpha;
    m_c_damping.noalias() += m_damping.beta * (m_kc * m_c_delta);
    m_kc_c += m_c_damping / m_dt;
  }
  for (int i = 0; i < n; ++i)
    m_work(m_order[i]) = m_force_zero ? -m_kc_c(i) : m_force(i) - m_kc_c(i);
  m_factor.matrixL().solveInPlace(m_work);
  m_work.array() *= m_inverse_d.array();
  m_factor.matrixU().solveInPlace(m_work);
  for (int j = 0; j < n; ++j)
    m_c_next(j) = 2.0 * m_c(j) - m_c_prev(j) + dt2 * m_work(m_order[j]);
}

void FullCasingPart::add_correction(const TipContact& tip, double f_u, double f_v) {
  // c_u and c_v interleaved per node, as the modal casing sums them.
  for (int b = 0; b < 4; ++b) {
    if (tip.c_u[b] < 0) continue;
    m_dc += (f_u * tip.shape[b]) * m_flexibility.col(tip.c_u[b]);
    if (f_v == 0.0) continue;
    m_dc += (f_v * tip.shape[b]) * m_flexibility.col(tip.c_v[b]);
  }
}

void FullCasingPart::add_sliding_correction(const TipContact& tip, double f, double mu) {
  for (int b = 0; b < 4; ++b)
    if (tip.c_u[b] >= 0)
      m_dc += f * tip.shape[b] *
              (m_flexibility.col(tip.c_u[b]) + mu * tip.sign * m_flexibility.col(tip.c_v[b]));
}

} // namespace rsi

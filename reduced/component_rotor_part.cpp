#include "component_rotor_part.hpp"

#include <cmath>

namespace rsi {

ComponentRotorPart::ComponentRotorPart(const ReducedBasis& basis,
                                       const ComponentIntegratorOptions& options)
    : m_dt(options.dt)
    , m_r(basis.n_reduced())
    , m_boundary(basis.boundary_position)
    , m_shapes(basis.boundary_shapes) {
  m_nb = basis.n_boundary();
  std::vector<char> is_b(m_r, 0);
  for (int b : m_boundary)
    is_b[b] = 1;
  for (int i = 0; i < m_r; ++i)
    if (!is_b[i]) m_interior.push_back(i);
  m_ni = static_cast<int>(m_interior.size());
  if (options.damping.size() != 0 && options.damping.any()) m_c = options.damping;
  m_force = options.force_constant.size() != 0 || options.force_harmonic.size() != 0;
  if (m_force) {
    m_f0 = options.force_constant.size() ? options.force_constant : Eigen::VectorXd::Zero(m_r);
    m_f1 = options.force_harmonic.size() ? options.force_harmonic : Eigen::VectorXd::Zero(m_r);
    m_omega_f = options.force_frequency;
    m_phi_f = options.force_phase;
  }
  m_k = basis.stiffness;
  m_m = basis.mass;
  if (Eigen::MatrixXd(m_m.diagonal().asDiagonal()) == m_m) m_mass_diagonal = m_m.diagonal();
}

FailureAdvice ComponentRotorPart::mass_remedy() {
  return remedied_by({Remedy::lumped_mass_or_fewer_modes});
}

const std::string& ComponentRotorPart::where() {
  static const std::string prefix = "ComponentIntegrator: ";
  return prefix;
}

Eigen::MatrixXd ComponentRotorPart::block(const Eigen::MatrixXd& a, const std::vector<int>& rows,
                                          const std::vector<int>& cols) {
  Eigen::MatrixXd out(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j)
      out(i, j) = a(rows[i], cols[j]);
  return out;
}

Eigen::VectorXd ComponentRotorPart::take(const Eigen::VectorXd& a, const std::vector<int>& rows) {
  Eigen::VectorXd out(rows.size());
  for (size_t i = 0; i < rows.size(); ++i)
    out(i) = a(rows[i]);
  return out;
}

Eigen::VectorXd ComponentRotorPart::boundary_of(const Eigen::VectorXd& x) const {
  if (m_shapes.size() == 0) return take(x, m_boundary);
  return m_shapes * x.tail(m_shapes.cols());
}

Eigen::MatrixXd ComponentRotorPart::boundary_transpose(const Eigen::MatrixXd& rows) const {
  Eigen::MatrixXd bt = Eigen::MatrixXd::Zero(m_r, rows.rows());
  if (m_shapes.size() != 0) {
    bt.bottomRows(m_shapes.cols()) = m_shapes.transpose() * rows.transpose();
    return bt;
  }
  for (int k = 0; k < m_nb; ++k)
    bt.row(m_boundary[k]) = rows.col(k).transpose();
  return bt;
}

Eigen::VectorXd ComponentRotorPart::external_force(double t) const {
  if (!m_force) return Eigen::VectorXd::Zero(m_r);
  return m_f0 + std::cos(m_omega_f * t + m_phi_f) * m_f1;
}

double ComponentRotorPart::energy() const {
  // E_{n-1/2} = 1/2 v^T M^ v + 1/2 x_{n-1}^T K^ x_n, v = (x_n - x_{n-1})/dt.
  Eigen::VectorXd x, xp;
  state_in_basis(x, xp);
  const Eigen::VectorXd v = (x - xp) / m_dt;
  // M^ diagonal (MacNeal's [0, 0; 0, I]): M^ v is m_ii v_i, the same bits as
  // the product, whose other terms are exact zeros.
  if (m_mass_diagonal.size())
    return 0.5 * v.dot(m_mass_diagonal.cwiseProduct(v)) + 0.5 * xp.dot(m_k * x);
  return 0.5 * v.dot(m_m * v) + 0.5 * xp.dot(m_k * x);
}

} // namespace rsi

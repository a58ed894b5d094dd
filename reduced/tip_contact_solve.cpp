#include "tip_contact_solve.hpp"

namespace rsi {

TipContactSolve::TipContactSolve(const DiskPart& disk, const CasingPart& casing, double dt,
                                 double mu)
    : m_disk(disk)
    , m_casing(casing)
    , m_dt(dt)
    , m_mu(mu) {}

void TipContactSolve::start(int n_tips) {
  m_lambda = Eigen::VectorXd::Zero(n_tips);
  m_lambda_t = Eigen::VectorXd::Zero(n_tips);
  m_state.assign(n_tips, ReducedContactState::open);
  m_certificate = ReducedCoulombCertificate{};
}

FailureAdvice TipContactSolve::step_remedy() {
  return remedied_by({Remedy::reduced_smaller_step});
}

FailureAdvice TipContactSolve::contact_remedy() {
  return remedied_by({Remedy::reduced_friction_or_smaller_step});
}

} // namespace rsi

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

const std::string& TipContactSolve::step_remedy() {
  static const std::string remedy =
      "; use a smaller step (time.step, or --time-step and the campaign's time_step of a reduced "
      "run)";
  return remedy;
}

const std::string& TipContactSolve::contact_remedy() {
  static const std::string remedy =
      "; change operating_point.friction_coefficient (friction that cancels the contacts' normal "
      "flexibility) or use a smaller step (time.step, --time-step)";
  return remedy;
}

} // namespace rsi

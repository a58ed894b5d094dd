#include "reference_run.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "casing_forcing.hpp"
#include "central_difference.hpp"
#include "modal_analysis.hpp"
#include "tip_casing_contact.hpp"

namespace rsi {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Eigen::SparseMatrix<double> block_diagonal(const Eigen::SparseMatrix<double>& a,
                                           const Eigen::SparseMatrix<double>& b) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < a.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it)
      t.emplace_back(it.row(), it.col(), it.value());
  for (int j = 0; j < b.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(b, j); it; ++it)
      t.emplace_back(a.rows() + it.row(), a.cols() + it.col(), it.value());
  Eigen::SparseMatrix<double> m(a.rows() + b.rows(), a.cols() + b.cols());
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

void add_row(History& h, const CentralDifference& cd, double energy) {
  h.time.push_back(cd.time());
  h.gap.push_back(cd.gap());
  h.lambda.push_back(cd.lambda());
  h.energy.push_back(energy);
  h.external_work.push_back(cd.external_work());
  h.contact_work.push_back(cd.contact_work());
}

} // namespace

RunResult run_reference(const Case& c, const RunOptions& options) {
  const Clock::time_point start = Clock::now();
  const BladedDisk bd = assemble_bladed_disk(c);
  const Casing casing = assemble_casing(c);
  const Eigen::SparseMatrix<double> k = block_diagonal(bd.stiffness, casing.stiffness);
  const Eigen::SparseMatrix<double> m = block_diagonal(bd.mass, casing.mass);

  RunResult result;
  RunSummary& s = result.summary;
  s.method = "full";
  s.n_dofs = static_cast<int>(k.rows());
  s.dt = c.time.step;
  s.omega_max = std::max(max_angular_frequency(bd.stiffness, bd.mass),
                         max_angular_frequency(casing.stiffness, casing.mass));
  s.critical_dt = 2.0 / s.omega_max;
  if (s.dt >= s.critical_dt && !options.force) {
    std::ostringstream message;
    message.precision(6);
    message << "time.step = " << s.dt
            << " s is not below the central-difference stability limit 2/omega_max = "
            << s.critical_dt << " s (omega_max = " << s.omega_max
            << " rad/s); use a smaller step or --force";
    throw StabilityError(message.str());
  }

  const TipCasingContact law(bd, casing, c);
  const double clearance = c.casing.radius - c.bladed_disk.tip_radius;
  CentralDifference cd(k, m, c.time.step, law);
  Eigen::VectorXd forcing = Eigen::VectorXd::Zero(k.rows());
  forcing.tail(casing.n_dofs()) = casing_forcing(casing, c.forcing);
  const Eigen::VectorXd no_force = Eigen::VectorXd::Zero(k.rows());

  s.steps_requested = static_cast<int>(std::llround(c.time.duration / c.time.step));
  const Clock::time_point integration_start = Clock::now();
  cd.start(forcing_active(c.forcing, 0.0, s.dt) ? forcing : no_force);
  s.initial_energy = cd.initial_energy();
  add_row(result.history, cd, s.initial_energy);
  s.max_energy = s.initial_energy;
  double largest_external_work = 0.0;
  bool in_contact = false;
  s.completed = true;
  s.status = "completed";
  for (int n = 0; n < s.steps_requested; ++n) {
    const StepReport r = cd.step(forcing_active(c.forcing, n * s.dt, s.dt) ? forcing : no_force);
    s.steps = n + 1;
    s.max_penetration = std::max(s.max_penetration, r.max_penetration);
    s.min_lambda = std::min(s.min_lambda, r.min_lambda);
    s.max_lambda = std::max(s.max_lambda, cd.lambda().maxCoeff());
    s.max_complementarity = std::max(s.max_complementarity, r.max_complementarity);
    s.max_friction_residual = std::max(s.max_friction_residual, r.max_friction_residual);
    s.sliding_reversals += r.sliding_reversals;
    s.max_active = std::max(s.max_active, r.n_active);
    if (s.first_contact_step < 0 && r.n_active > 0) {
      s.first_contact_step = n + 1;
      const Eigen::VectorXd all = on_all_nodes(casing, cd.displacement().tail(casing.n_dofs()));
      result.casing_u_at_first_contact =
          Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<4>>(all.data(),
                                                                      casing.n_elements);
      result.casing_v_at_first_contact =
          Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<4>>(all.data() + 2,
                                                                      casing.n_elements);
    }

    const double w_ext = cd.external_work();
    const double w_c = cd.contact_work();
    largest_external_work = std::max(largest_external_work, std::abs(w_ext));

    if (cd.lambda()(0) > 0.0) {
      if (!in_contact) s.contact_intervals_blade_1.emplace_back(cd.time(), cd.time());
      s.contact_intervals_blade_1.back().second = cd.time();
    }
    in_contact = cd.lambda()(0) > 0.0;

    // Every step: a blow-up shows first in the gaps (non-finite, or tips moved
    // by a thousand clearances); the energy is checked on the output steps.
    const double runaway = 1000.0 * clearance;
    if (!cd.gap().allFinite() || cd.gap().cwiseAbs().maxCoeff() > runaway) {
      std::ostringstream message;
      message << "blow-up: a blade tip gap is non-finite or beyond " << runaway
              << " m (1000 clearances) at step " << n + 1 << " (t = " << cd.time() << " s)";
      s.completed = false;
      s.status = message.str();
      add_row(result.history, cd, cd.energy());
      break;
    }
    if (options.progress && (n + 1) % 1000 == 0)
      options.progress(double(n + 1) / s.steps_requested);
    // The energy (a product with M) is checked on the output steps: the
    // balance, the blow-up test and the history row.
    if ((n + 1) % c.time.output_every != 0 && n + 1 != s.steps_requested) continue;
    const double e = cd.energy();
    add_row(result.history, cd, e);
    s.max_energy = std::max(s.max_energy, e);
    s.energy_scale = std::max({s.energy_scale, std::abs(e), std::abs(w_ext), std::abs(w_c)});
    s.energy_balance_error =
        std::max(s.energy_balance_error, std::abs(e - s.initial_energy - w_ext - w_c));
    if (!std::isfinite(e)) {
      s.completed = false;
      s.status = "blow-up: non-finite energy at step " + std::to_string(n + 1) +
                 " (t = " + std::to_string(cd.time()) + " s)";
      break;
    }
    if (largest_external_work > 0.0 && e > options.blowup_factor * largest_external_work) {
      std::ostringstream message;
      message << "blow-up: energy " << e << " J exceeds " << options.blowup_factor
              << " times the largest external work " << largest_external_work << " J at step "
              << n + 1 << " (t = " << cd.time() << " s); contact work " << w_c << " J";
      s.completed = false;
      s.status = message.str();
      break;
    }
  }
  s.integration_seconds = seconds_since(integration_start);
  s.final_external_work = cd.external_work();
  s.final_contact_work = cd.contact_work();
  s.wall_seconds = seconds_since(start);
  return result;
}

} // namespace rsi

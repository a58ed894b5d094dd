// The one full-order loop (reference/solver/full_order_run.hpp) and its one
// energy balance
//   E_n - E_0 - W_ext - W_contact + W_damp = 0 (to round-off)
// for every kind of problem: a component on the rigid casing, pushed by an
// external force (which no case file gives it yet), closes this balance to
// the tolerance its runs are held to, while a balance without W_ext (the
// component runs' own form before the loop was shared) would be off by
// W_ext itself and stop the run.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "calculix_run.hpp"
#include "child_process.hpp"
#include "full_order_run.hpp"
#include "modal_analysis.hpp"
#include "problem.hpp"
#include "rubbing_monitor.hpp"
#include "structure_contact.hpp"

namespace rsi {
namespace {

std::string cache_dir() {
  const char* env = std::getenv("RSI_CCX_CACHE");
  return env && *env ? env : RSI_BINARY_DIR "/ccx-cache";
}

TEST(FullOrderRun, ForcedComponentClosesTheBalanceWithTheExternalWork) {
  if (!executable_on_path("gmsh")) GTEST_SKIP() << "gmsh is not on PATH (Debian package gmsh)";
  try {
    find_ccx();
  } catch (const std::exception& e) {
    GTEST_SKIP() << e.what();
  }
  Problem p = load_problem(RSI_SOURCE_DIR "/data/cases/blade3d-rubbing.json", {"", cache_dir()});
  // 1 N (model units N, mm) along the response dof, held for the first half.
  const int steps = 2000;
  p.forcing.force = Eigen::VectorXd::Zero(p.n_dofs());
  p.forcing.force(p.outputs.response_dof) = 1.0;
  const Eigen::SparseMatrix<double> k = p.stiffness(), m = p.mass();
  const double dt = 0.9 * 2.0 / max_angular_frequency(k, m); // the case's step_safety
  p.forcing.until = 0.5 * steps * dt;
  const StructureContact contact(p);

  RunResult result;
  RunOptions options;
  MonitorRules rules;
  rules.steps_requested = steps;
  rules.output_every = 100;
  rules.energy_every = 100;
  rules.row_at_last_step = false;
  rules.balance_tolerance = rubbing_balance_tolerance; // the component runs'
  RunMonitor monitor(rules, std::make_unique<RubbingMonitor>(*contact.rigid_surface()), options,
                     result);
  FullOrderSystem system;
  system.stiffness = &k;
  system.mass = &m;
  system.dt = dt;
  system.contact = &contact;
  system.forcing = &p.forcing;
  system.failure_is_status = true;
  drive_full_order(system, monitor, result.summary, Clock::now());

  const RunSummary& s = result.summary;
  std::printf("status %s; %d steps; W_ext %.6e, W_contact %.6e, max E %.6e; balance error "
              "%.3e, scale %.3e (relative %.3e)\n",
              s.status.c_str(), s.steps, s.final_external_work, s.final_contact_work,
              s.max_energy, s.energy_balance_error, s.energy_scale,
              s.energy_balance_error / s.energy_scale);
  EXPECT_TRUE(s.completed) << s.status;
  EXPECT_EQ(s.steps, steps);
  // The force did work, so a balance without W_ext would miss all of it.
  EXPECT_GT(s.final_external_work, 0.0);
  EXPECT_GT(s.final_external_work, 1e-8 * s.energy_scale);
  // central_difference.hpp: the discrete balance is exact; what is left is
  // the round-off of summing 2000 steps' works and of E's two products,
  // far below the runs' tolerance 1e-8 x scale.
  EXPECT_LE(s.energy_balance_error, 1e-8 * s.energy_scale);
}

} // namespace
} // namespace rsi

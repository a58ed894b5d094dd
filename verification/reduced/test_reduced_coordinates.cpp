// The reduced integrator's modal bladed disk (reduced_integrator.hpp:
// q = Psi eta, Psi^T M^ Psi = I) is the physical-coordinate scheme written
// in other coordinates: central differences are invariant under a fixed
// linear change of coordinates, so the two paths must give the same
// histories up to round-off, contact included.

#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "bladed_disk.hpp"
#include "casing.hpp"
#include "casing_forcing.hpp"
#include "critical_step.hpp"
#include "reduced_contact.hpp"
#include "reduced_integrator.hpp"
#include "reduction.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

struct Trace {
  std::vector<Eigen::VectorXd> gap;
  std::vector<double> energy;
  Eigen::VectorXd q_last;
};

Trace run(const Case& c, const ReducedBasis& basis, const ReducedModes* modes, int steps) {
  const BladedDisk bd = assemble_bladed_disk(c);
  const Casing casing = assemble_casing(c);
  const ReducedTipContact contact(basis, casing, c);
  ReducedIntegrator integrator(basis, casing, c.time.step, contact, ReducedDamping{}, nullptr,
                               modes);
  EXPECT_EQ(integrator.modal_bladed_disk(), modes != nullptr);
  const Eigen::VectorXd force = casing_forcing(casing, c.forcing);
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(casing.n_dofs());
  integrator.start(force);
  bool on = true;
  Trace t;
  for (int n = 0; n < steps; ++n) {
    if (forcing_active(c.forcing, n * c.time.step, c.time.step) != on) {
      on = !on;
      integrator.set_force(on ? force : none);
    }
    integrator.step();
    if ((n + 1) % c.time.output_every == 0) {
      t.gap.push_back(integrator.gap());
      t.energy.push_back(integrator.energy());
    }
  }
  t.q_last = integrator.q();
  return t;
}

TEST(ReducedCoordinates, ModalPathIsThePhysicalSchemeToRoundOff) {
  for (const char* law : {"sliding_sign", "coulomb"}) {
    Case c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
    c.operating_point.friction_law =
        std::string(law) == "coulomb" ? FrictionLaw::coulomb : FrictionLaw::sliding_sign;
    const ReducedBasis basis = reduce_bladed_disk(assemble_bladed_disk(c), "cb", 44);
    const ReducedModes modes = reduced_modes(basis);
    const int steps = 20000; // 10 ms: both contact episodes of blade 1 start before 7 ms
    const Trace physical = run(c, basis, nullptr, steps);
    const Trace modal = run(c, basis, &modes, steps);
    double difference = 0.0, energy_difference = 0.0, energy_scale = 0.0;
    for (size_t i = 0; i < physical.gap.size(); ++i) {
      difference = std::max(difference, (physical.gap[i] - modal.gap[i]).cwiseAbs().maxCoeff());
      energy_difference =
          std::max(energy_difference, std::abs(physical.energy[i] - modal.energy[i]));
      energy_scale = std::max(energy_scale, std::abs(physical.energy[i]));
    }
    // As test_casing_basis (EveryModeKeptIsTheFullCasing): the gaps are formed
    // from numbers of the size of the radius, eps R_c a step, accumulated at
    // most linearly by a stable scheme: steps * eps * R_c.
    const double bound = steps * eps * c.casing.radius;
    // The energy: the same quadratic form in other coordinates, each
    // evaluation rounding at r eps of its terms (r = 88 + 44 = 132), on
    // states that differ by the gap bound's relative share.
    const double energy_bound = energy_scale * (132 * eps + bound / (c.casing.radius - c.bladed_disk.tip_radius));
    std::printf("%s: max |gap physical - gap modal| = %.2e m (bound %.2e), max |E difference| "
                "= %.2e J (bound %.2e, E up to %.2e J)\n",
                law, difference, bound, energy_difference, energy_bound, energy_scale);
    EXPECT_LE(difference, bound) << law;
    EXPECT_LE(energy_difference, energy_bound) << law;
    EXPECT_TRUE(modal.q_last.allFinite());
  }
}

} // namespace
} // namespace rsi

#include "mode_selection.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <utility>

#include "nodal_diameter.hpp"

namespace rsi {
namespace {

/// Relative tolerance of a degenerate pair's frequencies: SPEC V2 ("double
/// frequencies for nodal diameters 1..10 equal to 1e-8 relative").
constexpr double pair_tolerance = 1e-8;

const char* const selection_names[] = {"lowest", "families", "forced", "participation"};

/// Takes units in `order` while they fit in `modes`; stops at the first one
/// that does not (round down). Returns the kept candidates, ascending.
std::vector<int> take_prefix(const std::vector<CyclicUnit>& units, const std::vector<int>& order,
                             int modes) {
  std::vector<int> kept;
  for (int u : order) {
    const std::vector<int>& members = units[u].members;
    if (static_cast<int>(kept.size() + members.size()) > modes) break;
    kept.insert(kept.end(), members.begin(), members.end());
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

/// Whole families 0 .. K-1, K = min(floor(m / N), families complete in the pool).
std::vector<int> select_families(const std::vector<CyclicUnit>& units, int modes, int n_sectors) {
  const int half = n_sectors / 2;
  // units_per_diameter[n]: how many complete units of diameter n the pool holds.
  std::vector<int> units_per_diameter(half + 1, 0);
  for (const CyclicUnit& u : units)
    ++units_per_diameter[u.nodal_diameter];
  const int complete = *std::min_element(units_per_diameter.begin(), units_per_diameter.end());
  const int families = std::min(modes / n_sectors, complete);
  std::vector<int> kept;
  for (const CyclicUnit& u : units)
    if (u.family < families) kept.insert(kept.end(), u.members.begin(), u.members.end());
  std::sort(kept.begin(), kept.end());
  return kept;
}

std::vector<int> select_forced(const std::vector<CyclicUnit>& units, int modes,
                               const SelectionContext& context) {
  const NodalDiameterOrder nd =
      forced_nodal_diameter_order(context.forcing_nodal_diameter, context.n_sectors);
  std::vector<int> rank(nd.order.size());
  for (size_t r = 0; r < nd.order.size(); ++r)
    rank[nd.order[r]] = static_cast<int>(r);
  auto key = [&](const CyclicUnit& u) { return std::make_pair(u.family, rank[u.nodal_diameter]); };
  std::vector<int> order(units.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return key(units[a]) < key(units[b]); });
  return take_prefix(units, order, modes);
}

std::vector<int> select_participation(const std::vector<CyclicUnit>& units, int modes,
                                      const Eigen::VectorXd& participation) {
  std::vector<double> mean(units.size());
  for (size_t u = 0; u < units.size(); ++u) {
    double sum = 0.0;
    for (int i : units[u].members)
      sum += participation(i);
    mean[u] = sum / static_cast<double>(units[u].members.size());
  }
  std::vector<int> order(units.size());
  std::iota(order.begin(), order.end(), 0);
  // Largest first; equal measures keep the frequency order (stable).
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return mean[a] > mean[b]; });
  return take_prefix(units, order, modes);
}

} // namespace

ModeSelection parse_mode_selection(const std::string& name) {
  for (int s = 0; s < 4; ++s)
    if (name == selection_names[s]) return static_cast<ModeSelection>(s);
  throw ReductionError("mode selection: must be lowest, families, forced or participation, got '" +
                       name + "'");
}

std::string to_string(ModeSelection selection) {
  return selection_names[static_cast<int>(selection)];
}

SelectionContext selection_context(const BladedDisk& bd, int forcing_nodal_diameter) {
  SelectionContext c;
  c.n_sectors = bd.n_sectors;
  c.sector_dofs = bd.dofs_per_sector;
  c.forcing_nodal_diameter = forcing_nodal_diameter;
  return c;
}

void check_context(const SelectionContext& c, int n_dofs) {
  if (c.n_sectors < 1 || c.sector_dofs < 1 ||
      static_cast<long>(c.n_sectors) * c.sector_dofs != n_dofs) {
    std::ostringstream m;
    m << "mode selection: the " << n_dofs << " dofs are not " << c.n_sectors << " sector blocks of "
      << c.sector_dofs << " dofs (a cyclic bladed disk is needed)";
    throw ReductionError(m.str());
  }
  if (c.forcing_nodal_diameter < 0)
    throw ReductionError("mode selection: the forcing's nodal diameter must be >= 0, got " +
                         std::to_string(c.forcing_nodal_diameter));
}

int candidate_pool_size(ModeSelection selection, int modes, int available, int n_sectors) {
  if (selection == ModeSelection::lowest || modes == 0) return modes;
  return std::min(available, std::max(3 * modes, modes + 2 * n_sectors));
}

std::vector<int> nodal_diameters(const Eigen::Ref<const Eigen::MatrixXd>& shapes,
                                 const SelectionContext& context) {
  std::vector<int> nd(shapes.cols());
  for (Eigen::Index j = 0; j < shapes.cols(); ++j)
    nd[j] = nodal_diameter(shapes.col(j), context.n_sectors, context.sector_dofs);
  return nd;
}

int nodal_diameter_multiplicity(int nodal_diameter, int n_sectors) {
  return nodal_diameter == 0 || 2 * nodal_diameter == n_sectors ? 1 : 2;
}

int alias_nodal_diameter(int harmonic, int n_sectors) {
  const int r = ((harmonic % n_sectors) + n_sectors) % n_sectors;
  return std::min(r, n_sectors - r);
}

NodalDiameterOrder forced_nodal_diameter_order(int p, int n_sectors) {
  NodalDiameterOrder out;
  std::vector<bool> seen(n_sectors / 2 + 1, false);
  auto add = [&](int nd) {
    if (!seen[nd]) {
      seen[nd] = true;
      out.order.push_back(nd);
    }
  };
  // m = 1, 0, 2, 3, ..., N: h = m p mod N repeats with a period dividing N.
  add(alias_nodal_diameter(p, n_sectors));
  for (int m = 0; m <= n_sectors; ++m)
    add(alias_nodal_diameter(m * p, n_sectors));
  out.n_excited = static_cast<int>(out.order.size());
  for (int nd = 0; nd <= n_sectors / 2; ++nd)
    add(nd);
  return out;
}

std::vector<CyclicUnit> cyclic_units(const Eigen::Ref<const Eigen::VectorXd>& omega_squared,
                                     const std::vector<int>& nodal_diameter, int n_sectors) {
  const int count = static_cast<int>(omega_squared.size());
  const int half = n_sectors / 2;
  std::vector<std::vector<int>> by_diameter(half + 1);
  for (int i = 0; i < count; ++i)
    by_diameter[nodal_diameter[i]].push_back(i);
  const double omega_top = count > 0 ? std::sqrt(omega_squared(count - 1)) : 0.0;
  std::vector<CyclicUnit> units;
  for (int nd = 0; nd <= half; ++nd) {
    const std::vector<int>& members = by_diameter[nd];
    const size_t multiplicity = nodal_diameter_multiplicity(nd, n_sectors);
    for (size_t first = 0; first < members.size(); first += multiplicity) {
      CyclicUnit u;
      u.nodal_diameter = nd;
      u.family = static_cast<int>(first / multiplicity);
      const double omega_a = std::sqrt(omega_squared(members[first]));
      if (first + multiplicity > members.size()) {
        // A member without partner: its partner must lie above the pool.
        if (omega_top - omega_a > pair_tolerance * omega_top) {
          std::ostringstream m;
          m << "mode selection: mode " << members[first] << " (" << omega_a
            << " rad/s) of nodal diameter " << nd
            << " has no degenerate partner, although it lies below the highest candidate ("
            << omega_top << " rad/s): not a cyclic model, or a misclassified mode";
          throw ReductionError(m.str());
        }
        break;
      }
      for (size_t k = 0; k < multiplicity; ++k)
        u.members.push_back(members[first + k]);
      if (multiplicity == 2) {
        const double omega_b = std::sqrt(omega_squared(members[first + 1]));
        if (std::abs(omega_b - omega_a) > pair_tolerance * omega_b) {
          std::ostringstream m;
          m << "mode selection: modes " << members[first] << " and " << members[first + 1]
            << " of nodal diameter " << nd << " are not a degenerate pair (" << omega_a << " and "
            << omega_b << " rad/s, relative gap above " << pair_tolerance
            << ", SPEC V2): not a cyclic model, or a misclassified mode";
          throw ReductionError(m.str());
        }
      }
      units.push_back(u);
    }
  }
  std::sort(units.begin(), units.end(), [](const CyclicUnit& a, const CyclicUnit& b) {
    return a.members.front() < b.members.front();
  });
  return units;
}

std::vector<int> select_modes(ModeSelection selection, int modes, const Candidates& candidates,
                              const SelectionContext& context) {
  const int count = static_cast<int>(candidates.omega_squared.size());
  if (modes < 0 || modes > count)
    throw ReductionError("mode selection: " + std::to_string(modes) + " modes out of a pool of " +
                         std::to_string(count));
  if (selection == ModeSelection::lowest) {
    std::vector<int> kept(modes);
    std::iota(kept.begin(), kept.end(), 0);
    return kept;
  }
  if (static_cast<int>(candidates.nodal_diameter.size()) != count)
    throw ReductionError("mode selection: every candidate needs its nodal diameter");
  const std::vector<CyclicUnit> units =
      cyclic_units(candidates.omega_squared, candidates.nodal_diameter, context.n_sectors);
  switch (selection) {
  case ModeSelection::families:
    return select_families(units, modes, context.n_sectors);
  case ModeSelection::forced:
    return select_forced(units, modes, context);
  case ModeSelection::participation:
    if (candidates.participation.size() != count)
      throw ReductionError("mode selection: participation needs a measure of every candidate");
    return select_participation(units, modes, candidates.participation);
  case ModeSelection::lowest:
    break;
  }
  return {};
}

} // namespace rsi

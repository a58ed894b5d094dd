// Mode selection for the reduction bases (issue 14 item 3;
// reduced/bases/mode_selection.hpp, participation.hpp) on the paper's
// bladed disk.
//
// - lowest is today's count-based basis bit for bit (==, no tolerance);
// - families never cuts a family: per nodal diameter, the kept frequencies
//   are the lowest ones of that diameter and every dropped one lies above;
// - forced keeps the forcing's diameters (2, 0, 4, ...) first within a
//   family, checked with nodal_diameter on the kept shapes;
// - participation's ranking equals the one of an independent dense
//   computation of the measure (LAPACK dsygvd spectra, dense Cholesky
//   constraint modes, units formed here);
// - every strategy's basis passes the rows of verification/support/reduction_rows
//   that apply (static condensation, CB block diagonal, orthonormal kept
//   fixed-interface modes, Rayleigh-Ritz bounds).
//
// Every reference quantity is computed here from the model's matrices,
// independently of reduced/ (which supplies the bases and the strategy's
// public helpers under test); nodal diameters come from
// reference/solver/nodal_diameter, applied to the basis's own columns.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <lapacke.h>

#include "bladed_disk.hpp"
#include "error_norms.hpp"
#include "mode_selection.hpp"
#include "nodal_diameter.hpp"
#include "partition.hpp"
#include "reduced_run.hpp"
#include "reduction.hpp"
#include "reduction_rows.hpp"
#include "reference_run.hpp"

namespace rsi {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// Relative tolerance on frequencies compared between two eigensolvers:
/// SPEC V2 resolves the bladed-disk frequencies to 1e-8 (pairs "equal to
/// 1e-8 relative"). Both solvers are far more accurate (Lanczos' relative
/// residual 1e-12, rows::lanczos_tol; dsygvd n eps cond), and distinct
/// frequencies of one nodal diameter are 1e-2 apart or more (Fig. 3: one
/// unit per family and diameter, families at 44, 275, 675-771, ... Hz), so
/// 1e-8 matches each mode to itself only.
constexpr double frequency_tolerance = 1e-8;

constexpr int n_sectors = 22;

/// All eigenpairs of A x = lambda B x by LAPACKE dsygvd, B-normalised, ascending.
struct DenseEigen {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};

DenseEigen dense_eigen(const Eigen::Ref<const Eigen::MatrixXd>& a,
                       const Eigen::Ref<const Eigen::MatrixXd>& b) {
  const int n = static_cast<int>(a.rows());
  Eigen::MatrixXd aa = a;
  Eigen::MatrixXd bb = b;
  DenseEigen out;
  out.values.resize(n);
  const lapack_int info = LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'V', 'L', n, aa.data(), n, bb.data(),
                                         n, out.values.data());
  if (info != 0) throw std::runtime_error("dense_eigen: dsygvd info " + std::to_string(info));
  out.vectors = aa;
  return out;
}

/// The block A(rows, cols) of a dense matrix.
Eigen::MatrixXd block(const Eigen::Ref<const Eigen::MatrixXd>& a, const std::vector<int>& rows,
                      const std::vector<int>& cols) {
  Eigen::MatrixXd out(rows.size(), cols.size());
  for (size_t j = 0; j < cols.size(); ++j)
    for (size_t i = 0; i < rows.size(); ++i)
      out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = a(rows[i], cols[j]);
  return out;
}

int multiplicity(int nd) {
  return nd == 0 || 2 * nd == n_sectors ? 1 : 2;
}

/// A spectrum computed here: omega [rad/s] ascending, nodal diameter of
/// each mode, and the per-mode participation measure of the method,
/// q_i = a_i / omega_i^(2 power) with a_i = phi_i^T Q phi_i a quadratic
/// form of the mode (CB: Q = C C^T, C = M_II Psi + M_IB, power 1; CCM:
/// Q = E_B E_B^T, power 3).
struct Spectrum {
  Eigen::VectorXd omega;
  std::vector<int> nd;
  Eigen::VectorXd measure;
  Eigen::VectorXd quadratic; ///< a_i
};

/// Spectra's Lanczos convergence tolerance in lowest_modes (rows::lanczos_tol).
constexpr double lanczos_tol = rows::lanczos_tol;

/// First-order bound of the relative error of the measure q_i of a mode
/// computed by shift-invert Lanczos. Its residual test ||Op x - mu x|| <=
/// tol |mu| (Op = K^-1 M, mu = 1/lambda) leaves a component of at most
/// c_ij = tol lambda_j / |lambda_i - lambda_j| along every other mode j
/// (M-orthonormal expansion; Davis-Kahan, or Parlett, The Symmetric
/// Eigenvalue Problem, §11-7); a quadratic form moves by at most
/// 2 sum_j c_ij |phi_i^T Q phi_j| <= 2 sum_j c_ij sqrt(a_i a_j), and the
/// eigenvalue's own relative error tol enters q through omega^(2 power).
/// The sum runs over every mode outside the unit (`skip`: the pair partner,
/// whose mixing leaves the unit's sum unchanged).
double measure_bound(const Spectrum& s, int i, const std::vector<int>& skip, int power) {
  const double li = s.omega(i) * s.omega(i);
  double sum = 0.0;
  for (int j = 0; j < s.omega.size(); ++j) {
    if (std::find(skip.begin(), skip.end(), j) != skip.end()) continue;
    const double lj = s.omega(j) * s.omega(j);
    sum += lanczos_tol * lj / std::abs(li - lj) * std::sqrt(s.quadratic(j) / s.quadratic(i));
  }
  return 2.0 * sum + power * lanczos_tol;
}

/// Per nodal diameter, the frequencies of a set of modes, ascending.
std::map<int, std::vector<double>> by_diameter(const Eigen::VectorXd& omega,
                                               const std::vector<int>& nd) {
  std::map<int, std::vector<double>> out;
  for (int i = 0; i < omega.size(); ++i)
    out[nd[i]].push_back(omega(i));
  for (auto& [d, w] : out)
    std::sort(w.begin(), w.end());
  return out;
}

/// A unit formed here: a single mode or a degenerate pair (consecutive
/// modes of one diameter of multiplicity 2), ranked by the mean measure.
struct TestUnit {
  int nd = 0;
  int family = 0;
  std::vector<int> members;
  double mean = 0.0;
};

std::vector<TestUnit> test_units(const Spectrum& s, int pool) {
  std::map<int, std::vector<int>> members;
  for (int i = 0; i < pool; ++i)
    members[s.nd[i]].push_back(i);
  std::vector<TestUnit> out;
  for (const auto& [nd, list] : members) {
    const size_t m = multiplicity(nd);
    for (size_t k = 0; k + m <= list.size(); k += m) {
      TestUnit u;
      u.nd = nd;
      u.family = static_cast<int>(k / m);
      for (size_t j = 0; j < m; ++j)
        u.members.push_back(list[k + j]);
      for (int i : u.members)
        u.mean += s.measure.size() > 0 ? s.measure(i) / static_cast<double>(m) : 0.0;
      out.push_back(u);
    }
  }
  return out;
}

class ModeSelectionTest : public ::testing::Test {
protected:
  struct Model {
    Case c;
    BladedDisk bd;
    Partition p;
    SelectionContext context;
    std::unique_ptr<rows::Component> component;
    std::unique_ptr<Modes> full; ///< lowest modes for the Rayleigh-Ritz row
    Spectrum free;               ///< every free-interface mode (dense)
    Spectrum fixed;              ///< every fixed-interface mode (dense)
  };

  static void SetUpTestSuite() {
    auto md = std::make_unique<Model>();
    md->c = load_case(std::string(RSI_SOURCE_DIR) + "/data/cases/batailly2007.json");
    md->bd = assemble_bladed_disk(md->c);
    md->p = make_partition(md->bd.n_dofs(), md->bd.boundary);
    md->context = selection_context(md->bd, md->c.forcing.nodal_diameter);
    md->component =
        std::make_unique<rows::Component>(md->bd.stiffness, md->bd.mass, md->bd.boundary);
    md->full = std::make_unique<Modes>(rows::full_modes(*md->component, 100));
    const Partition& p = md->p;
    const int n = md->bd.n_dofs();
    const Eigen::MatrixXd k = Eigen::MatrixXd(md->bd.stiffness);
    const Eigen::MatrixXd m = Eigen::MatrixXd(md->bd.mass);

    // Free-interface modes, measure ||phi_B||^2 / omega^6 (participation.hpp).
    const DenseEigen fr = dense_eigen(k, m);
    md->free.omega = fr.values.cwiseSqrt();
    md->free.measure.resize(n);
    md->free.quadratic.resize(n);
    for (int i = 0; i < n; ++i) {
      md->free.nd.push_back(nodal_diameter(fr.vectors.col(i), n_sectors, md->bd.dofs_per_sector));
      double b2 = 0.0;
      for (int b : p.boundary)
        b2 += fr.vectors(b, i) * fr.vectors(b, i);
      md->free.quadratic(i) = b2;
      md->free.measure(i) = b2 / std::pow(fr.values(i), 3);
    }

    // Fixed-interface modes and constraint modes (dense Cholesky of K_II),
    // measure ||phi^T (M_II Psi + M_IB)||^2 / omega^2.
    const Eigen::MatrixXd k_ii = block(k, p.interior, p.interior);
    const Eigen::MatrixXd m_ii = block(m, p.interior, p.interior);
    const Eigen::LLT<Eigen::MatrixXd> llt(k_ii);
    if (llt.info() != Eigen::Success) throw std::runtime_error("dense Cholesky of K_II");
    const Eigen::MatrixXd psi = -llt.solve(block(k, p.interior, p.boundary));
    const Eigen::MatrixXd coupling = m_ii * psi + block(m, p.interior, p.boundary);
    const DenseEigen fx = dense_eigen(k_ii, m_ii);
    md->fixed.omega = fx.values.cwiseSqrt();
    const Eigen::MatrixXd l = fx.vectors.transpose() * coupling;
    md->fixed.quadratic = l.rowwise().squaredNorm();
    md->fixed.measure = md->fixed.quadratic.cwiseQuotient(fx.values);
    const Eigen::MatrixXd placed = place_rows(n, p.interior, fx.vectors);
    for (int i = 0; i < p.n_interior(); ++i)
      md->fixed.nd.push_back(nodal_diameter(placed.col(i), n_sectors, md->bd.dofs_per_sector));
    std::printf("bladed disk: n = %d, n_I = %d; forcing nodal diameter %d; lowest free %.4f Hz, "
                "lowest fixed-interface %.4f Hz (dsygvd)\n",
                n, p.n_interior(), md->context.forcing_nodal_diameter,
                md->free.omega(0) / (2 * M_PI), md->fixed.omega(0) / (2 * M_PI));
    s_model = std::move(md);
    s_bases = std::make_unique<std::map<std::tuple<std::string, int, int>, ReducedBasis>>();
  }
  static void TearDownTestSuite() {
    s_bases.reset();
    s_model.reset();
  }

  static const Model& model() { return *s_model; }

  static const ReducedBasis& basis(const std::string& method, ModeSelection s, int modes) {
    const std::tuple<std::string, int, int> key{method, static_cast<int>(s), modes};
    auto it = s_bases->find(key);
    if (it == s_bases->end())
      it = s_bases->emplace(key, reduce_bladed_disk(model().bd, method, modes, s, model().context))
               .first;
    return it->second;
  }

  static const Spectrum& spectrum(const std::string& method) {
    return method == "cb" ? model().fixed : model().free;
  }

  /// The kept modes' columns of T (CB: fixed-interface modes placed on the
  /// interior rows; CCM: phi_i - R(:, B) R_B^-1 phi_iB, which has phi_i's
  /// nodal diameter since the attachment operator commutes with a sector
  /// rotation), classified here.
  static std::vector<int> kept_diameters(const ReducedBasis& b) {
    const int k = b.n_modes;
    const Eigen::MatrixXd cols =
        b.method == "cb" ? b.transformation.leftCols(k) : b.transformation.rightCols(k);
    std::vector<int> nd;
    for (int j = 0; j < k; ++j)
      nd.push_back(nodal_diameter(cols.col(j), n_sectors, model().bd.dofs_per_sector));
    return nd;
  }

  /// Checks that per nodal diameter the kept frequencies are the lowest
  /// `count[nd]` of the dense spectrum, and that the next one (the lowest
  /// dropped) lies above them; returns the largest relative deviation.
  static double expect_lowest_per_diameter(const ReducedBasis& b, const std::string& what) {
    const std::vector<int> nd = kept_diameters(b);
    const std::map<int, std::vector<double>> kept = by_diameter(b.mode_omega, nd);
    const Spectrum& s = spectrum(b.method);
    const std::map<int, std::vector<double>> all = by_diameter(s.omega, s.nd);
    double worst = 0.0;
    for (const auto& [d, w] : kept) {
      const std::vector<double>& ref = all.at(d);
      for (size_t i = 0; i < w.size(); ++i) {
        const double dev = std::abs(w[i] - ref[i]) / ref[i];
        worst = std::max(worst, dev);
        EXPECT_LE(dev, frequency_tolerance)
            << what << ": kept mode " << i << " of nodal diameter " << d << " at " << w[i]
            << " rad/s is not the " << i << "-th lowest (" << ref[i] << ")";
      }
      if (w.size() < ref.size()) {
        EXPECT_GT(ref[w.size()], w.back() * (1.0 + frequency_tolerance))
            << what << ": a dropped mode of nodal diameter " << d << " lies below a kept one";
      }
    }
    return worst;
  }

  static std::unique_ptr<Model> s_model;
  static std::unique_ptr<std::map<std::tuple<std::string, int, int>, ReducedBasis>> s_bases;
};
std::unique_ptr<ModeSelectionTest::Model> ModeSelectionTest::s_model;
std::unique_ptr<std::map<std::tuple<std::string, int, int>, ReducedBasis>>
    ModeSelectionTest::s_bases;

const ModeSelection all_selections[] = {ModeSelection::lowest, ModeSelection::families,
                                        ModeSelection::forced, ModeSelection::participation};

// ---------------------------------------------------------------- pure parts

TEST(ModeSelectionNames, ParseAndPrint) {
  for (ModeSelection s : all_selections)
    EXPECT_EQ(parse_mode_selection(to_string(s)), s);
  EXPECT_EQ(to_string(ModeSelection::participation), "participation");
  try {
    parse_mode_selection("highest");
    ADD_FAILURE() << "no error for an unknown strategy";
  } catch (const ReductionError& e) {
    std::printf("refused: %s\n", e.what());
    const std::string m = e.what();
    for (const char* name : {"lowest", "families", "forced", "participation", "'highest'"})
      EXPECT_NE(m.find(name), std::string::npos) << m;
  }
}

// Aliasing h -> |h mod N| folded into [0, N/2], and the forced order for
// p = 2, N = 22 derived in mode_selection.hpp: m = 1, 0, 2, 3, 4, 5 give
// 2, 0, 4, 6, 8, 10; m = 6, 7, ... alias back (12 -> 10, 14 -> 8); the odd
// diameters follow in ascending order.
TEST(ModeSelectionNames, ForcedOrderAndAliases) {
  EXPECT_EQ(alias_nodal_diameter(12, 22), 10);
  EXPECT_EQ(alias_nodal_diameter(22, 22), 0);
  EXPECT_EQ(alias_nodal_diameter(23, 22), 1);
  EXPECT_EQ(alias_nodal_diameter(-2, 22), 2);
  EXPECT_EQ(alias_nodal_diameter(11, 22), 11);
  const NodalDiameterOrder o = forced_nodal_diameter_order(2, 22);
  EXPECT_EQ(o.order, (std::vector<int>{2, 0, 4, 6, 8, 10, 1, 3, 5, 7, 9, 11}));
  EXPECT_EQ(o.n_excited, 6);
  // p = 3 is prime to 22: its harmonics reach every diameter.
  const NodalDiameterOrder o3 = forced_nodal_diameter_order(3, 22);
  EXPECT_EQ(o3.n_excited, 12);
  EXPECT_EQ(o3.order[0], 3);
  EXPECT_EQ(o3.order[1], 0);
  // A uniform forcing (p = 0) excites diameter 0 only.
  EXPECT_EQ(forced_nodal_diameter_order(0, 22).n_excited, 1);
}

// Units on a synthetic spectrum: a single, a pair, a pair cut by the top of
// the pool (dropped); a split pair and an unpaired mode below the top are
// refused (SPEC V2: pairs equal to 1e-8).
TEST(ModeSelectionNames, CyclicUnitsPairsAndRefusals) {
  auto w2 = [](std::initializer_list<double> w) {
    Eigen::VectorXd v(static_cast<Eigen::Index>(w.size()));
    Eigen::Index i = 0;
    for (double x : w)
      v(i++) = x * x;
    return v;
  };
  const std::vector<CyclicUnit> u =
      cyclic_units(w2({10.0, 11.0, 11.0, 12.0}), {0, 3, 3, 5}, n_sectors);
  ASSERT_EQ(u.size(), 2u); // diameter 5's lone mode is the pool's top: dropped
  EXPECT_EQ(u[0].members, (std::vector<int>{0}));
  EXPECT_EQ(u[1].members, (std::vector<int>{1, 2}));
  EXPECT_EQ(u[1].nodal_diameter, 3);
  EXPECT_THROW(cyclic_units(w2({10.0, 11.0, 11.001}), {0, 3, 3}, n_sectors), ReductionError);
  EXPECT_THROW(cyclic_units(w2({10.0, 11.0, 12.0}), {3, 0, 0}, n_sectors), ReductionError);
}

// --------------------------------------------------------- on the bladed disk

TEST_F(ModeSelectionTest, ContextMustDescribeTheDisk) {
  SelectionContext c = model().context;
  EXPECT_EQ(c.n_sectors, 22);
  EXPECT_EQ(c.forcing_nodal_diameter, 2);
  c.sector_dofs += 1;
  EXPECT_THROW(reduce_bladed_disk(model().bd, "cb", 4, ModeSelection::forced, c), ReductionError);
  EXPECT_THROW(reduce_bladed_disk(model().bd, "macneal", 4, ModeSelection::forced, model().context),
               ReductionError);
}

// lowest is today's count-based basis bit for bit (Lanczos and dense paths,
// 0 to 200 modes), and records its modes.
TEST_F(ModeSelectionTest, LowestIsTodaysBasisBitForBit) {
  for (const char* method : {"cb", "ccm"})
    for (int modes : {0, 4, 10, 44, 64, 88, 200}) {
      const ReducedBasis today = reduce_bladed_disk(model().bd, method, modes);
      const ReducedBasis& b = basis(method, ModeSelection::lowest, modes);
      std::printf("%-3s lowest %3d: T %s, K^ %s, M^ %s, omega %s\n", method, modes,
                  b.transformation == today.transformation ? "==" : "differs",
                  b.stiffness == today.stiffness ? "==" : "differs",
                  b.mass == today.mass ? "==" : "differs",
                  b.mode_omega == today.mode_omega ? "==" : "differs");
      EXPECT_TRUE(b.transformation == today.transformation) << method << " " << modes;
      EXPECT_TRUE(b.stiffness == today.stiffness) << method << " " << modes;
      EXPECT_TRUE(b.mass == today.mass) << method << " " << modes;
      EXPECT_TRUE(b.mode_omega == today.mode_omega) << method << " " << modes;
      EXPECT_EQ(b.selection, "lowest");
      EXPECT_EQ(b.n_modes, modes);
      EXPECT_EQ(b.requested_modes, modes);
      std::vector<int> first(modes);
      std::iota(first.begin(), first.end(), 0);
      EXPECT_EQ(b.mode_index, first);
      EXPECT_EQ(today.mode_index, first);
      if (modes <= 88) {
        EXPECT_EQ(b.mode_nodal_diameter, kept_diameters(b));
      }
    }
}

// families never cuts a family: the count rounds down to whole families of
// 22, every nodal diameter holds as many units as families kept, and per
// diameter the kept frequencies are the lowest (dropped ones lie above).
TEST_F(ModeSelectionTest, FamiliesNeverCutAFamily) {
  for (const char* method : {"cb", "ccm"})
    for (int modes : {10, 22, 32, 44, 50, 66, 88}) {
      const ReducedBasis& b = basis(method, ModeSelection::families, modes);
      const int families = modes / n_sectors;
      const std::vector<int> nd = kept_diameters(b);
      EXPECT_EQ(b.mode_nodal_diameter, nd);
      std::map<int, int> count;
      for (int d : nd)
        ++count[d];
      const double dev = expect_lowest_per_diameter(b, method);
      std::printf("%-3s families %2d: kept %2d (pool %3d), max deviation from the dense "
                  "frequencies %.2e (tolerance %.0e)\n",
                  method, modes, b.n_modes, b.candidate_modes, dev, frequency_tolerance);
      EXPECT_EQ(b.n_modes, families * n_sectors) << method << " " << modes;
      EXPECT_EQ(b.requested_modes, modes);
      EXPECT_EQ(b.selection, "families");
      for (int d = 0; d <= n_sectors / 2; ++d)
        EXPECT_EQ(count[d], families * multiplicity(d))
            << method << " " << modes << ": nodal diameter " << d;
    }
}

// forced keeps the forcing's diameters first: within a family, units in the
// order 2, 0, 4, 6, 8, 10, 1, 3, ...; the count rounds down at the first unit
// that does not fit. The expected counts per diameter are built here from
// that order; the kept shapes are classified by nodal_diameter.
TEST_F(ModeSelectionTest, ForcedKeepsTheForcingDiametersFirst) {
  const std::vector<int> order = {2, 0, 4, 6, 8, 10, 1, 3, 5, 7, 9, 11};
  for (const char* method : {"cb", "ccm"})
    for (int modes : {2, 3, 4, 11, 16, 32, 64}) {
      std::map<int, int> expected;
      int taken = 0;
      bool full = false;
      for (int family = 0; !full; ++family)
        for (int d : order) {
          if (taken + multiplicity(d) > modes) {
            full = true;
            break;
          }
          taken += multiplicity(d);
          expected[d] += multiplicity(d);
        }
      const ReducedBasis& b = basis(method, ModeSelection::forced, modes);
      const std::vector<int> nd = kept_diameters(b);
      std::map<int, int> count;
      for (int d : nd)
        ++count[d];
      std::string kept;
      for (const auto& [d, k] : count)
        kept += " " + std::to_string(d) + "x" + std::to_string(k);
      const double dev = expect_lowest_per_diameter(b, method);
      std::printf("%-3s forced %2d: kept %2d, nodal diameters (d x count):%s; frequencies vs "
                  "dense %.2e\n",
                  method, modes, b.n_modes, kept.c_str(), dev);
      EXPECT_EQ(b.n_modes, taken) << method << " " << modes;
      EXPECT_EQ(count, expected) << method << " " << modes;
      EXPECT_EQ(b.mode_nodal_diameter, nd);
    }
  // Two modes: the pair of the forcing's diameter 2 of the first family.
  EXPECT_EQ(kept_diameters(basis("cb", ModeSelection::forced, 2)), (std::vector<int>{2, 2}));
}

// participation ranks units by the mean measure of participation.hpp. The
// same measure is computed here from dense spectra (dsygvd), dense
// constraint modes and units formed here; each kept mode of the basis is
// matched to a unit here (its nodal diameter from its own column, its
// frequency), and
// - the basis's unit measures equal the ones here within the Lanczos bound
//   (measure_bound);
// - the kept units are the top of the ranking here: no dropped candidate
//   unit ranks above a kept one by more than their two bounds (units closer
//   than that are tied: within a blade family the free modes' measures
//   differ by about 1e-6 between diameters, which no eigensolver's vectors
//   decide);
// - the count: the prefix stops at the first unit that does not fit, so it
//   leaves at most one mode of the budget unused (units hold 1 or 2 modes).
TEST_F(ModeSelectionTest, ParticipationRankingEqualsDenseComputation) {
  for (const char* method : {"cb", "ccm"})
    for (int modes : {4, 8, 20, 32, 64, 88}) {
      const Spectrum& s = spectrum(method);
      const bool cb = std::string(method) == "cb";
      const int available = static_cast<int>(s.omega.size()) - (cb ? 0 : model().p.n_boundary());
      const int pool =
          candidate_pool_size(ModeSelection::participation, modes, available, n_sectors);
      const std::vector<TestUnit> units = test_units(s, pool);
      const int power = cb ? 1 : 3;
      std::vector<double> bound(units.size(), 0.0);
      for (size_t u = 0; u < units.size(); ++u)
        for (int i : units[u].members)
          bound[u] = std::max(bound[u], measure_bound(s, i, units[u].members, power));

      const ReducedBasis& b = basis(method, ModeSelection::participation, modes);
      ASSERT_EQ(b.mode_participation.size(), b.n_modes);
      const std::vector<int> nd = kept_diameters(b);
      // Kept mode -> unit here (same diameter, frequency within tolerance);
      // the basis's measure summed per unit.
      std::map<size_t, double> kept_sum;
      std::map<size_t, int> kept_members;
      double w_dev = 0.0;
      for (int i = 0; i < b.n_modes; ++i) {
        size_t found = units.size();
        for (size_t u = 0; u < units.size() && found == units.size(); ++u)
          for (int j : units[u].members)
            if (units[u].nd == nd[i] &&
                std::abs(b.mode_omega(i) - s.omega(j)) <= frequency_tolerance * s.omega(j)) {
              found = u;
              w_dev = std::max(w_dev, std::abs(b.mode_omega(i) - s.omega(j)) / s.omega(j));
            }
        ASSERT_LT(found, units.size())
            << method << " " << modes << ": kept mode " << i << " (" << b.mode_omega(i)
            << " rad/s, nodal diameter " << nd[i] << ") is no candidate unit here";
        kept_sum[found] += b.mode_participation(i);
        ++kept_members[found];
      }
      double q_dev = 0.0, q_ratio = 0.0;
      for (const auto& [u, sum] : kept_sum) {
        EXPECT_EQ(kept_members[u], static_cast<int>(units[u].members.size()))
            << method << " " << modes << ": a unit kept in part";
        const double mean = sum / static_cast<double>(kept_members[u]);
        const double dev = std::abs(mean - units[u].mean) / units[u].mean;
        q_dev = std::max(q_dev, dev);
        q_ratio = std::max(q_ratio, dev / bound[u]);
      }
      // Top of the ranking: the worst excess of a dropped unit over a kept
      // one, in units of their bounds; and how many such pairs are ties.
      double excess = -std::numeric_limits<double>::infinity();
      int ties = 0;
      for (const auto& [u, sum] : kept_sum)
        for (size_t v = 0; v < units.size(); ++v) {
          if (kept_sum.count(v)) continue;
          const double gap = (units[v].mean - units[u].mean) / units[u].mean;
          if (std::abs(gap) <= bound[u] + bound[v]) ++ties;
          excess = std::max(excess, gap / (bound[u] + bound[v]));
        }
      std::printf("%-3s participation %2d: kept %2d of pool %3d (%zu units, %d kept-dropped "
                  "pairs tied within bounds); frequencies vs dense %.2e; unit measures vs dense "
                  "%.2e (%.2e of the Lanczos bound); worst dropped-over-kept excess %.2e of the "
                  "bounds\n",
                  method, modes, b.n_modes, pool, units.size(), ties, w_dev, q_dev, q_ratio,
                  excess);
      EXPECT_LE(w_dev, frequency_tolerance) << method << " " << modes;
      EXPECT_LE(q_ratio, 1.0) << method << " " << modes;
      EXPECT_LE(excess, 1.0) << method << " " << modes << ": a dropped unit ranks above a kept one";
      EXPECT_LE(b.n_modes, modes);
      EXPECT_GE(b.n_modes, modes - 1) << method << " " << modes;
      EXPECT_EQ(b.selection, "participation");
    }
}

// The rows of reduction_rows.hpp that apply to a basis of chosen modes:
// static boundary loads exact (span T holds K^-1 E_B for any kept modes),
// CB's K^ block diagonal with M_II-orthonormal kept modes, and the
// Rayleigh-Ritz bounds (reduced eigenvalues above the full ones, below
// lambda_max).
TEST_F(ModeSelectionTest, ReductionRowsHoldForEveryStrategy) {
  const rows::Component& c = *model().component;
  std::mt19937 generator(2007);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd loads(c.n_boundary(), 4);
  for (Eigen::Index j = 0; j < loads.cols(); ++j)
    for (Eigen::Index i = 0; i < loads.rows(); ++i)
      loads(i, j) = 1000.0 * uniform(generator); // [N]
  const Partition& p = model().p;
  const Eigen::SparseMatrix<double> k_ii = sparse_block(c.k(), p.interior, p.interior);
  const Eigen::SparseMatrix<double> m_ii = sparse_block(c.m(), p.interior, p.interior);
  for (ModeSelection s : all_selections)
    for (const char* method : {"cb", "ccm"})
      for (int modes : {10, 32, 64}) {
        const ReducedBasis& b = basis(method, s, modes);
        const rows::StaticRow st = rows::static_response(c, b, loads);
        const std::vector<rows::RitzRow> rr =
            rows::rayleigh_ritz(c, {&b}, *model().full, rows::full_modes_by_lanczos(c), 20);
        std::printf("%-13s %-3s %2d (kept %2d): static %.2e (%.2e of bound), S G - I %.2e "
                    "(%.2e); Ritz shortfall %.2e (%.2e), top %.2e (%.2e)",
                    to_string(s).c_str(), method, modes, b.n_modes, st.response.error,
                    st.response.ratio, st.boundary_stiffness.error, st.boundary_stiffness.ratio,
                    rr[0].below.error, rr[0].below.ratio, rr[0].top.error, rr[0].top.ratio);
        EXPECT_LE(st.response.ratio, 1.0);
        EXPECT_LE(st.boundary_stiffness.ratio, 1.0);
        EXPECT_LE(rr[0].below.ratio, 1.0);
        EXPECT_LE(rr[0].top.ratio, 1.0);
        if (std::string(method) == "cb" && b.n_modes > 0) {
          const rows::BlockRow bl = rows::cb_block_diagonal(c, b);
          // The kept fixed-interface modes are T's first columns on the
          // interior rows; Lanczos computed them when the pool was small.
          Modes kept;
          kept.shapes = take_rows(b.transformation.leftCols(b.n_modes), p.interior);
          kept.omega_squared = b.mode_omega.cwiseAbs2();
          const bool lanczos = few_modes(b.candidate_modes, p.n_interior()) == ModalSolver::sparse;
          const rows::ModeRow mr =
              rows::mode_orthogonality(k_ii, m_ii, kept, lanczos, c.lambda_max());
          std::printf("; K^(modal, B) %.2e (%.2e), |Phi^T M Phi - I| %.2e (%.2e), K diagonal "
                      "%.2e (%.2e)",
                      bl.coupling.error, bl.coupling.ratio, mr.mass.error, mr.mass.ratio,
                      mr.stiffness_diag.error, mr.stiffness_diag.ratio);
          EXPECT_LE(bl.coupling.ratio, 1.0);
          EXPECT_LE(bl.modal_mass.ratio, 1.0);
          EXPECT_LE(bl.modal_stiffness_off.ratio, 1.0);
          EXPECT_LE(mr.mass.ratio, 1.0);
          EXPECT_LE(mr.stiffness_off.ratio, 1.0);
          EXPECT_LE(mr.stiffness_diag.ratio, 1.0);
        }
        std::printf("\n");
      }
}

// The e2 study of issue 14 item 3 (not run by ctest: 2 x 4 x 11 reduced
// runs, about 30 s): e2 of the blade-1 gap against the full reference for
// every method, strategy and count. Run with
//   build/verification/test_mode_selection --gtest_also_run_disabled_tests
//     --gtest_filter='*DISABLED_GapErrorStudy*'
TEST_F(ModeSelectionTest, DISABLED_GapErrorStudy) {
  const RunResult reference = run_reference(model().c, RunOptions{});
  std::printf("method,selection,requested,kept,e2,e_inf\n");
  for (const char* method : {"cb", "ccm"})
    for (ModeSelection s : all_selections)
      for (int modes : {4, 8, 10, 16, 20, 22, 32, 44, 64, 66, 88}) {
        const ReducedBasis& b = basis(method, s, modes);
        const ReducedRunResult r = run_reduced(model().c, b, ReducedRunOptions{});
        const GapErrors e = blade1_gap_errors(r.run.history, reference.history);
        std::printf("%s,%s,%d,%d,%.4f,%.4f\n", method, to_string(s).c_str(), modes, b.n_modes, e.e2,
                    e.e_inf);
        std::fflush(stdout);
      }
}

} // namespace
} // namespace rsi

#include "guyan.hpp"

#include <atomic>
#include <chrono>
#include <limits>
#include <mutex>
#include <new>
#include <sstream>
#include <string>
#include <thread>

#include <Eigen/CholmodSupport>

#include "cholmod_handles.hpp"
#include "energy_resolution.hpp"
#include "transpose_product.hpp"
#include "worker_threads.hpp"

namespace rsi {

namespace {

/// CHOLMOD's factorization with its factor readable (Eigen keeps it protected).
/// CHOLMOD out of memory throws std::bad_alloc: Eigen would read a missing
/// factor (a failed analysis) through a null pointer, and a failed
/// factorization or solve as a numerical issue of A.
class CheckedCholmod : public Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>> {
public:
  explicit CheckedCholmod(const Eigen::SparseMatrix<double>& a) {
    // Eigen's compute(a), with the analysis checked before the factorization;
    // METIS's lock held through the analysis (linalg/cholmod_handles.hpp).
    {
      const std::lock_guard<std::mutex> one_at_a_time(metis_generator_lock());
      analyzePattern(a);
    }
    throw_if_out_of_memory();
    if (m_cholmodFactor == nullptr) return; // defect() says so
    factorize(a);
    throw_if_out_of_memory();
  }

  void throw_if_out_of_memory() {
    if (cholmod().status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
  }

  /// Empty if the factor is that of a positive definite matrix `a`, else why not.
  std::string defect(const Eigen::SparseMatrix<double>& a) {
    if (m_cholmodFactor == nullptr) return "CHOLMOD: the analysis failed (no factor)";
    const cholmod_factor& f = *m_cholmodFactor;
    const int n = static_cast<int>(f.n);
    const int* perm = static_cast<const int*>(f.Perm);
    auto column = [&](int j) { return j < n ? std::to_string(perm ? perm[j] : j) : "(none)"; };
    std::ostringstream why;
    if (info() != Eigen::Success) {
      why << "CHOLMOD: not positive definite at column " << column(static_cast<int>(f.minor))
          << " of " << n;
      return why.str();
    }
    // Simplicial LDL^T: D(j) is the first entry of column j (supernodal is always LL^T).
    if (!f.is_super && !f.is_ll) {
      const double* x = static_cast<const double*>(f.x);
      const int* p = static_cast<const int*>(f.p);
      for (int j = 0; j < n; ++j)
        if (!(x[p[j]] > 0.0)) {
          why << "CHOLMOD LDL^T: pivot " << x[p[j]] << " <= 0 at column " << column(j) << " of "
              << n;
          return why.str();
        }
    }
    const DefinitenessCheck lowest =
        lowest_energy(a, {}, [&](const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
          x = solve(rhs);
          throw_if_out_of_memory();
          return info() == Eigen::Success;
        });
    return unresolved(lowest);
  }
};

} // namespace

std::string unresolved(const DefinitenessCheck& lowest) {
  if (!lowest.factorized) return "CHOLMOD: " + lowest.why;
  if (lowest.resolution.resolved()) return {};
  // Replaces the reciprocal condition estimate (min/max pivot)^2 against n
  // eps, which called valid thin-bladed models singular (issue 13: a blade
  // 2e-6 m thick, 3.6e-17, whose lowest mode's energy is resolved to 1e-4).
  std::ostringstream why;
  why.precision(3);
  const EnergyResolution& r = lowest.resolution;
  why << "the lowest mode of its CHOLMOD factor (inverse iteration, eigenvalue "
      << lowest.eigenvalue << ") has the energy x^T A x = " << r.energy
      << ", not above its rounding gamma_p |x|^T |A| |x| = " << r.rounding << ": condition number "
      << r.condition() << ", double precision resolves up to " << r.resolvable_condition();
  return why.str();
}

AccurateMatrix solve_positive_definite(const Eigen::SparseMatrix<double>& a,
                                       const Eigen::MatrixXd& b, const std::string& name,
                                       const std::string& remedy) {
  CheckedCholmod factor(a);
  const std::string defect = factor.defect(a);
  if (!defect.empty())
    throw ReductionError(name + " is singular or indefinite (" + defect + "); " + remedy);
  const WorkingSolve solve = [&](const Eigen::MatrixXd& r) {
    Eigen::MatrixXd x = factor.solve(r);
    factor.throw_if_out_of_memory();
    if (factor.info() != Eigen::Success) throw ReductionError(name + ": CHOLMOD solve failed");
    return x;
  };
  return accurate_solve(a, {}, {b, {}}, solve, name);
}

std::unique_ptr<CholmodShiftInvert> factor_positive_definite(const Eigen::SparseMatrix<double>& a,
                                                             const Eigen::SparseMatrix<double>& mass,
                                                             const std::string& name,
                                                             const std::string& remedy) {
  auto factor = std::make_unique<CholmodShiftInvert>(a, mass);
  factor->set_shift(0.0);
  std::string why;
  if (!factor->factorized())
    why = "CHOLMOD: " + factor->message();
  else
    why = unresolved(lowest_energy(a, mass, [&](const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
      return factor->solve(rhs, x);
    }));
  if (!why.empty())
    throw ReductionError(name + " is singular or indefinite (" + why + "); " + remedy);
  return factor;
}

AccurateMatrix solve_with(const CholmodShiftInvert& factor, const Eigen::SparseMatrix<double>& a,
                          const Eigen::MatrixXd& b, const std::string& name) {
  const WorkingSolve solve = [&](const Eigen::MatrixXd& r) {
    Eigen::MatrixXd x(r.rows(), r.cols());
    if (!factor.solve(r, x)) throw ReductionError(name + ": CHOLMOD solve failed");
    return x;
  };
  return accurate_solve(a, {}, {b, {}}, solve, name);
}

std::string interior_stiffness_name(const Partition& p) {
  return "constraint modes: the interior stiffness K_II (" + std::to_string(p.n_interior()) +
         " x " + std::to_string(p.n_interior()) + ", boundary dofs held)";
}

const char* const interior_stiffness_remedy =
    "the boundary must hold the part against every rigid motion (is the hub clamped?)";

Eigen::MatrixXd constraint_modes(const Eigen::SparseMatrix<double>& stiffness, const Partition& p,
                                 const CyclicBoundary* cyclic) {
  // Every dof on the boundary: no interior to solve for (T = I); CHOLMOD
  // takes no empty matrix.
  if (p.n_interior() == 0) return Eigen::MatrixXd(0, p.n_boundary());
  const Eigen::SparseMatrix<double> k_ii = sparse_block(stiffness, p.interior, p.interior);
  const InteriorSolve solve = [&](const Eigen::MatrixXd& b) {
    return solve_positive_definite(k_ii, b, interior_stiffness_name(p), interior_stiffness_remedy)
        .value;
  };
  if (cyclic != nullptr) return turned_constraint_modes(stiffness, p, *cyclic, solve);
  return solve(-Eigen::MatrixXd(sparse_block(stiffness, p.interior, p.boundary)));
}

Eigen::MatrixXd constraint_modes(const Eigen::SparseMatrix<double>& stiffness, const Partition& p,
                                 const CholmodShiftInvert& k_ii_factor,
                                 const Eigen::SparseMatrix<double>& k_ii,
                                 const CyclicBoundary* cyclic) {
  const InteriorSolve solve = [&](const Eigen::MatrixXd& b) {
    return solve_with(k_ii_factor, k_ii, b, interior_stiffness_name(p)).value;
  };
  if (cyclic != nullptr) return turned_constraint_modes(stiffness, p, *cyclic, solve);
  return solve(-Eigen::MatrixXd(sparse_block(stiffness, p.interior, p.boundary)));
}

void finish_basis(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass, int n_boundary,
                  int first_boundary_position, std::chrono::steady_clock::time_point start,
                  ReducedBasis& basis, const CyclicBoundary* cyclic) {
  for (int b = 0; b < n_boundary; ++b)
    basis.boundary_position.push_back(first_boundary_position + b);
  // K^T T, not K T: equal for the symmetric K and M of a component
  // (linalg/transpose_product gathers it, reading K once for all columns);
  // for a K with round-off asymmetry it gives the transpose of T^T K T,
  // whose symmetric part below is the same up to round-off.
  // The two projections are independent: taken in turn by two threads
  // (linalg/worker_threads: one thread that cannot start leaves both to the
  // other, a failure such as std::bad_alloc is rethrown here after both
  // joined), each the same single-threaded product as alone: the same bits.
  // At once they hold up to 3 n r doubles more (transpose_product's
  // row-major copy of T, its result and the returned copy; n r through the
  // product with T^T).
  const Eigen::MatrixXd& t = basis.transformation;
  Eigen::MatrixXd k;
  Eigen::MatrixXd m;
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  const auto worker = [&] {
    for (int job = next++; job < 2 && !failed; job = next++) {
      const Eigen::SparseMatrix<double>& a = job == 0 ? stiffness : mass;
      (job == 0 ? k : m) = cyclic != nullptr
                               ? cyclic_projection(a, t, first_boundary_position, *cyclic)
                               : Eigen::MatrixXd(t.transpose() * transpose_product(a, t));
    }
  };
  // Below ~2e7 multiply-adds (n r^2, or n r (eta + 3 n_r) by the turns) a
  // thread costs more than it saves.
  const double rows = cyclic != nullptr ? first_boundary_position +
                                              3.0 * cyclic->orbits.n_representatives()
                                        : static_cast<double>(t.cols());
  const double work = static_cast<double>(t.rows()) * static_cast<double>(t.cols()) * rows;
  run_on_threads(work >= 2e7 && std::thread::hardware_concurrency() >= 2 ? 2 : 1, worker, failed);
  basis.stiffness = 0.5 * (k + k.transpose());
  basis.mass = 0.5 * (m + m.transpose());
  basis.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ReducedBasis guyan(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, const Partition& p,
                   const CyclicBoundary* cyclic) {
  const auto start = std::chrono::steady_clock::now();
  ReducedBasis basis;
  basis.method = "guyan";
  const Eigen::MatrixXd psi = constraint_modes(stiffness, p, cyclic);
  basis.transformation =
      place_rows(p.n(), p.interior, psi) +
      place_rows(p.n(), p.boundary, Eigen::MatrixXd::Identity(p.n_boundary(), p.n_boundary()));
  finish_basis(stiffness, mass, p.n_boundary(), 0, start, basis, cyclic);
  return basis;
}

} // namespace rsi

#include "guyan.hpp"

#include <chrono>
#include <limits>
#include <sstream>
#include <string>

#include <Eigen/CholmodSupport>

namespace rsi {

namespace {

/// CHOLMOD's factorization with its factor readable (Eigen keeps it protected).
class CheckedCholmod : public Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>> {
public:
  explicit CheckedCholmod(const Eigen::SparseMatrix<double>& a)
      : Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>>(a) {}

  /// Empty if the factor is that of a positive definite matrix, else why not.
  std::string defect() {
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
    const double rcond = cholmod_rcond(m_cholmodFactor, &cholmod());
    const double floor = n * std::numeric_limits<double>::epsilon();
    if (!(rcond >= floor)) {
      why << "CHOLMOD reciprocal condition estimate (min/max pivot) " << rcond
          << " < n eps = " << floor;
      return why.str();
    }
    return {};
  }
};

} // namespace

AccurateMatrix solve_positive_definite(const Eigen::SparseMatrix<double>& a,
                                       const Eigen::MatrixXd& b, const std::string& name,
                                       const std::string& remedy) {
  CheckedCholmod factor(a);
  const std::string defect = factor.defect();
  if (!defect.empty())
    throw ReductionError(name + " is singular or indefinite (" + defect + "); " + remedy);
  const WorkingSolve solve = [&](const Eigen::MatrixXd& r) {
    Eigen::MatrixXd x = factor.solve(r);
    if (factor.info() != Eigen::Success) throw ReductionError(name + ": CHOLMOD solve failed");
    return x;
  };
  return accurate_solve(a, {}, {b, {}}, solve, name);
}

Eigen::MatrixXd constraint_modes(const Eigen::SparseMatrix<double>& stiffness, const Partition& p) {
  const Eigen::SparseMatrix<double> k_ii = sparse_block(stiffness, p.interior, p.interior);
  const Eigen::SparseMatrix<double> k_ib = sparse_block(stiffness, p.interior, p.boundary);
  return solve_positive_definite(k_ii, -Eigen::MatrixXd(k_ib),
                                 "constraint modes: the interior stiffness K_II (" +
                                     std::to_string(p.n_interior()) + " x " +
                                     std::to_string(p.n_interior()) + ", boundary dofs held)",
                                 "the boundary must hold the part against every rigid motion "
                                 "(is the hub clamped?)")
      .value;
}

void finish_basis(const Eigen::SparseMatrix<double>& stiffness,
                  const Eigen::SparseMatrix<double>& mass, int n_boundary,
                  int first_boundary_position, std::chrono::steady_clock::time_point start,
                  ReducedBasis& basis) {
  for (int b = 0; b < n_boundary; ++b)
    basis.boundary_position.push_back(first_boundary_position + b);
  const Eigen::MatrixXd& t = basis.transformation;
  const Eigen::MatrixXd k = t.transpose() * (stiffness * t);
  const Eigen::MatrixXd m = t.transpose() * (mass * t);
  basis.stiffness = 0.5 * (k + k.transpose());
  basis.mass = 0.5 * (m + m.transpose());
  basis.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ReducedBasis guyan(const Eigen::SparseMatrix<double>& stiffness,
                   const Eigen::SparseMatrix<double>& mass, const Partition& p) {
  const auto start = std::chrono::steady_clock::now();
  ReducedBasis basis;
  basis.method = "guyan";
  const Eigen::MatrixXd psi = constraint_modes(stiffness, p);
  basis.transformation =
      place_rows(p.n(), p.interior, psi) +
      place_rows(p.n(), p.boundary, Eigen::MatrixXd::Identity(p.n_boundary(), p.n_boundary()));
  finish_basis(stiffness, mass, p.n_boundary(), 0, start, basis);
  return basis;
}

} // namespace rsi

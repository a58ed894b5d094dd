#include "symmetric_inertia.hpp"

#include <cmath>
#include <mutex>
#include <new>
#include <optional>
#include <stdexcept>
#include <vector>

#include <cholmod.h>
#include <lapacke.h>
#include <umfpack.h>

#include "cholmod_handles.hpp"

namespace rsi {

namespace {

void count(double d, Inertia& inertia) {
  if (d < 0.0)
    ++inertia.negative;
  else if (d > 0.0)
    ++inertia.positive;
  else
    ++inertia.zero;
}

/// The inertia of the pivots of an L D L^T (or of U = D L^T), counted by
/// `method`. A zero (or NaN) pivot makes no count: tau is an eigenvalue to
/// working precision.
Inertia pivot_signs(const std::vector<double>& pivots, const std::string& method,
                    const std::string& pivot) {
  Inertia inertia;
  inertia.method = method;
  for (size_t j = 0; j < pivots.size(); ++j) {
    const double d = pivots[j];
    if (!std::isfinite(d) || d == 0.0) {
      inertia = Inertia{};
      inertia.method = method;
      inertia.why = pivot + " " + std::to_string(d) + " at step " + std::to_string(j);
      return inertia;
    }
    count(d, inertia);
  }
  inertia.factorized = true;
  return inertia;
}

/// UMFPACK's Symbolic and Numeric objects, freed on every path.
struct UmfpackObjects {
  void* symbolic = nullptr;
  void* numeric = nullptr;
  UmfpackObjects() = default;
  UmfpackObjects(const UmfpackObjects&) = delete;
  UmfpackObjects& operator=(const UmfpackObjects&) = delete;
  ~UmfpackObjects() {
    if (numeric != nullptr) umfpack_di_free_numeric(&numeric);
    if (symbolic != nullptr) umfpack_di_free_symbolic(&symbolic);
  }
};

/// The count from UMFPACK's multifrontal LU of the whole symmetric matrix B,
/// symmetric strategy, no scaling: when every pivot was a diagonal entry
/// (the row order P equal to the column order Q), P B P^T = L U is the LU of
/// a symmetric matrix without pivoting, U = D L^T with D of its L D L^T, and
/// the signs of diag(U) are B's inertia (P = Q is the test: UMFPACK counts in
/// NOFF_DIAG only some off-diagonal pivots). nullopt when UMFPACK pivoted off
/// the diagonal (a zero diagonal entry met) or failed (out of memory, its int
/// indices too small for a large LU, METIS): no count from it.
std::optional<Inertia> multifrontal_inertia(const Eigen::SparseMatrix<double>& lower) {
  Eigen::SparseMatrix<double> whole = lower.selfadjointView<Eigen::Lower>();
  whole.makeCompressed();
  const int n = static_cast<int>(whole.rows());
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  umfpack_di_defaults(control);
  control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
  control[UMFPACK_SCALE] = UMFPACK_SCALE_NONE;
  control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  // Threshold 0: every nonzero diagonal entry is taken as it comes, as
  // CHOLMOD's L D L^T without pivoting does (a zero one, with nonzeros left
  // in its column, is not: UMFPACK pivots off the diagonal there).
  control[UMFPACK_SYM_PIVOT_TOLERANCE] = 0.0;
  UmfpackObjects u;
  Inertia inertia;
  inertia.method = "UMFPACK LU, diagonal pivots";
  // UMFPACK orders by METIS as CHOLMOD does: the same process-wide lock
  // (cholmod_handles.hpp), or two analyses at once draw each other's numbers.
  int status = 0;
  {
    const std::lock_guard<std::mutex> one_at_a_time(metis_generator_lock());
    status = umfpack_di_symbolic(n, n, whole.outerIndexPtr(), whole.innerIndexPtr(),
                                 whole.valuePtr(), &u.symbolic, control, info);
  }
  if (status != UMFPACK_OK) return std::nullopt;
  status = umfpack_di_numeric(whole.outerIndexPtr(), whole.innerIndexPtr(), whole.valuePtr(),
                              u.symbolic, &u.numeric, control, info);
  if (status == UMFPACK_WARNING_singular_matrix) {
    inertia.why = "LU pivot exactly zero (UMFPACK)";
    return inertia;
  }
  if (status != UMFPACK_OK || info[UMFPACK_NOFF_DIAG] != 0.0) return std::nullopt;
  std::vector<int> rows(static_cast<size_t>(n)), columns(static_cast<size_t>(n));
  std::vector<double> diagonal(static_cast<size_t>(n));
  int reciprocal = 0;
  status = umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, rows.data(),
                                  columns.data(), diagonal.data(), &reciprocal, nullptr, u.numeric);
  if (status != UMFPACK_OK) return std::nullopt;
  if (rows != columns) return std::nullopt;
  return pivot_signs(diagonal, inertia.method, "LU pivot");
}

} // namespace

Inertia sparse_inertia(const Eigen::SparseMatrix<double>& lower) {
  if (lower.rows() != lower.cols() || !lower.isCompressed())
    throw std::invalid_argument("sparse_inertia: the lower triangle must be square and compressed");
  if (lower.rows() == 0) {
    Inertia inertia;
    inertia.factorized = true;
    return inertia;
  }
  if (std::optional<Inertia> multifrontal = multifrontal_inertia(lower)) return *multifrontal;
  return simplicial_inertia(lower);
}

Inertia simplicial_inertia(const Eigen::SparseMatrix<double>& lower) {
  if (lower.rows() != lower.cols() || !lower.isCompressed())
    throw std::invalid_argument(
        "simplicial_inertia: the lower triangle must be square and compressed");
  Inertia inertia;
  inertia.method = "CHOLMOD simplicial L D L^T";
  if (lower.rows() == 0) {
    inertia.factorized = true;
    return inertia;
  }
  CholmodHandles c;
  c.common.print = 0;
  c.common.supernodal = CHOLMOD_SIMPLICIAL;
  c.common.final_ll = 0; // keep L D L^T
  cholmod_sparse a = cholmod_lower_view(lower);
  c.factor = cholmod_analyze_serialized(&a, &c.common);
  if (c.common.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
  if (c.factor == nullptr) {
    inertia.why = "CHOLMOD analysis failed (status " + std::to_string(c.common.status) + ")";
    return inertia;
  }
  cholmod_factorize(&a, c.factor, &c.common);
  if (c.common.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
  const cholmod_factor& f = *c.factor;
  if (f.is_ll || f.is_super) {
    inertia.why = "CHOLMOD did not keep an L D L^T factor";
    return inertia;
  }
  // A zero (or NaN) pivot stops the count: tau is an eigenvalue to working
  // precision. A negative pivot is what the count is for (the LDL^T
  // factorization goes on past it; CHOLMOD reports only a zero one).
  const auto* p = static_cast<const int*>(f.p);
  const auto* x = static_cast<const double*>(f.x);
  std::vector<double> pivots(f.n);
  for (size_t j = 0; j < f.n; ++j)
    pivots[j] = x[p[j]]; // D_jj: the first entry of column j
  return pivot_signs(pivots, inertia.method, "L D L^T pivot");
}

Inertia dense_inertia(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  if (a.rows() != a.cols()) throw std::invalid_argument("dense_inertia: the matrix must be square");
  const int n = static_cast<int>(a.rows());
  Inertia inertia;
  inertia.method = "LAPACK dsytrf";
  if (n == 0) {
    inertia.factorized = true;
    return inertia;
  }
  Eigen::MatrixXd f = a;
  std::vector<lapack_int> pivots(static_cast<size_t>(n));
  const lapack_int info = LAPACKE_dsytrf(LAPACK_COL_MAJOR, 'L', n, f.data(), n, pivots.data());
  if (info == LAPACK_WORK_MEMORY_ERROR || info == LAPACK_TRANSPOSE_MEMORY_ERROR)
    throw std::bad_alloc();
  if (info < 0) {
    inertia.why = "LAPACKE_dsytrf failed (info " + std::to_string(info) + ")";
    return inertia;
  }
  if (info > 0) { // D(info, info) exactly zero: singular
    inertia.why = "LAPACKE_dsytrf: D is exactly singular at " + std::to_string(info);
    return inertia;
  }
  // ipiv(k) > 0: a 1x1 block D(k, k); ipiv(k) = ipiv(k+1) < 0: a 2x2 block
  // [d11 d21; d21 d22] in rows k, k+1 (LAPACK's dsytrf, UPLO = 'L').
  for (int k = 0; k < n;) {
    if (pivots[static_cast<size_t>(k)] > 0) {
      count(f(k, k), inertia);
      ++k;
      continue;
    }
    const double d11 = f(k, k);
    const double d21 = f(k + 1, k);
    const double d22 = f(k + 1, k + 1);
    // Eigenvalues of the 2x2 block: their product is the determinant, their sum the trace.
    const double determinant = d11 * d22 - d21 * d21;
    if (determinant < 0.0) {
      ++inertia.negative;
      ++inertia.positive;
    } else if (determinant > 0.0) {
      count(d11 + d22, inertia);
      count(d11 + d22, inertia);
    } else {
      inertia.zero += 1;
      count(d11 + d22, inertia);
    }
    k += 2;
  }
  if (inertia.zero > 0) {
    inertia.factorized = false;
    inertia.why = "LAPACKE_dsytrf: a zero block of D";
    return inertia;
  }
  inertia.factorized = true;
  return inertia;
}

} // namespace rsi

#include "symmetric_inertia.hpp"

#include <cmath>
#include <new>
#include <stdexcept>
#include <vector>

#include <cholmod.h>
#include <lapacke.h>

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

} // namespace

Inertia sparse_inertia(const Eigen::SparseMatrix<double>& lower) {
  if (lower.rows() != lower.cols() || !lower.isCompressed())
    throw std::invalid_argument("sparse_inertia: the lower triangle must be square and compressed");
  Inertia inertia;
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
  const auto n = static_cast<Eigen::Index>(f.n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double d = x[p[j]]; // D_jj: the first entry of column j
    if (!std::isfinite(d) || d == 0.0) {
      inertia = Inertia{};
      inertia.why = "L D L^T pivot " + std::to_string(d) + " at column " + std::to_string(j);
      return inertia;
    }
    count(d, inertia);
  }
  inertia.factorized = true;
  return inertia;
}

Inertia dense_inertia(const Eigen::Ref<const Eigen::MatrixXd>& a) {
  if (a.rows() != a.cols()) throw std::invalid_argument("dense_inertia: the matrix must be square");
  const int n = static_cast<int>(a.rows());
  Inertia inertia;
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

#pragma once
// What every CHOLMOD caller of rsi needs around the library's C interface:
// a view of an Eigen lower triangle as CHOLMOD's symmetric sparse matrix
// (no copy), and a cholmod_common with one factor released on every way
// out.

#include <Eigen/SparseCore>
#include <cholmod.h>

namespace rsi {

/// The lower triangle `lower` (compressed column storage, int indices) as a
/// CHOLMOD symmetric matrix (stype = -1), viewing Eigen's arrays.
inline cholmod_sparse cholmod_lower_view(const Eigen::SparseMatrix<double>& lower) {
  cholmod_sparse a{};
  a.nrow = static_cast<size_t>(lower.rows());
  a.ncol = static_cast<size_t>(lower.cols());
  a.nzmax = static_cast<size_t>(lower.nonZeros());
  a.p = const_cast<int*>(lower.outerIndexPtr());
  a.i = const_cast<int*>(lower.innerIndexPtr());
  a.x = const_cast<double*>(lower.valuePtr());
  a.stype = -1; // the lower triangle of a symmetric matrix
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

/// A cholmod_common (cholmod_start'ed, CHOLMOD's defaults) and one factor,
/// freed and finished by the destructor. Not copyable.
struct CholmodHandles {
  CholmodHandles() { cholmod_start(&common); }
  ~CholmodHandles() {
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  CholmodHandles(const CholmodHandles&) = delete;
  CholmodHandles& operator=(const CholmodHandles&) = delete;

  cholmod_common common;
  cholmod_factor* factor = nullptr;
};

} // namespace rsi

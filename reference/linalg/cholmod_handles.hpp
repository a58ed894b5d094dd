#pragma once
// What every CHOLMOD caller of rsi needs around the library's C interface:
// a view of an Eigen lower triangle as CHOLMOD's symmetric sparse matrix
// (no copy), a cholmod_common with one factor released on every way out,
// and the symbolic analysis one thread at a time.

#include <Eigen/SparseCore>
#include <cholmod.h>

#include <mutex>

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

/// The lock rsi's analyses that may order by METIS hold (CHOLMOD's below
/// and in reduced/bases/guyan.cpp, UMFPACK's in symmetric_inertia.cpp):
/// METIS's one generator (see below).
inline std::mutex& metis_generator_lock() {
  static std::mutex lock;
  return lock;
}

/// cholmod_analyze(a, common), never two at once in the process. CHOLMOD's
/// default analysis tries METIS besides AMD when AMD's fill is large (3D
/// solids) and keeps the better ordering; METIS 5 draws from one random
/// generator per process (GKlib's, reseeded at each call), so two
/// analyses at once interleave their draws and return other orderings,
/// hence other factors to rounding. Measured: a 27-point 20^3 matrix
/// (METIS chosen), two threads analysing at once, 20 of 20 permutations
/// differed from the serial one, none with this lock; in rsi sweep the
/// Rotor 37 speed subspace's bases, built two at a time, moved its
/// Campbell frequencies by up to 1.5e-9 from run to run
/// (test_cholmod_factor.ConcurrentAnalysesAreTheSerialOne). The lock is
/// process-wide because the generator is.
inline cholmod_factor* cholmod_analyze_serialized(cholmod_sparse* a, cholmod_common* common) {
  const std::lock_guard<std::mutex> one_at_a_time(metis_generator_lock());
  return cholmod_analyze(a, common);
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

#include "cholmod_factor.hpp"

#include <algorithm>
#include <new>
#include <stdexcept>

#include <cholmod.h>

#include "cholmod_handles.hpp"

namespace rsi {

struct CholmodFactor::Cholmod {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  // cholmod_solve2's result and workspace, kept between solves of equal width.
  cholmod_dense* x = nullptr;
  cholmod_dense* y = nullptr;
  cholmod_dense* e = nullptr;
};

namespace {

cholmod_dense view(const Eigen::Ref<const Eigen::MatrixXd>& b) {
  cholmod_dense d{};
  d.nrow = static_cast<size_t>(b.rows());
  d.ncol = static_cast<size_t>(b.cols());
  d.nzmax = d.nrow * d.ncol;
  d.d = static_cast<size_t>(b.outerStride());
  d.x = const_cast<double*>(b.data());
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

/// CHOLMOD reports a failed allocation as a status; rsi's callers would
/// read a failed factorization or solve as a property of the matrix (not
/// positive definite, singular). Memory is no property of the matrix:
/// throw what operator new throws.
void throw_if_out_of_memory(const cholmod_common& c) {
  if (c.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
}

} // namespace

CholmodFactor::CholmodFactor(Method method)
    : m_cholmod(std::make_unique<Cholmod>())
    , m_method(method) {
  cholmod_start(&m_cholmod->common);
  m_cholmod->common.print = 0; // silent: the status and message() carry the failures
  m_cholmod->common.supernodal =
      method == Method::supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  m_cholmod->common.final_ll = 1; // L L^T for both methods
}

CholmodFactor::~CholmodFactor() {
  cholmod_common* c = &m_cholmod->common;
  cholmod_free_dense(&m_cholmod->x, c);
  cholmod_free_dense(&m_cholmod->y, c);
  cholmod_free_dense(&m_cholmod->e, c);
  cholmod_free_factor(&m_cholmod->factor, c);
  cholmod_finish(c);
}

CholmodFactor::Status CholmodFactor::factorize(const Eigen::SparseMatrix<double>& lower) {
  if (lower.rows() != lower.cols() || !lower.isCompressed())
    throw std::invalid_argument("CholmodFactor: the lower triangle must be square and compressed");
  cholmod_common* c = &m_cholmod->common;
  cholmod_sparse a = cholmod_lower_view(lower);
  if (m_cholmod->factor == nullptr) {
    m_n = lower.rows();
    m_pattern_nonzeros = lower.nonZeros();
    m_cholmod->factor = cholmod_analyze_serialized(&a, c);
    throw_if_out_of_memory(*c);
    if (m_cholmod->factor == nullptr || c->status < CHOLMOD_OK) {
      m_status = Status::failed;
      m_message = "CHOLMOD analysis failed (status " + std::to_string(c->status) + ")";
      return m_status;
    }
    m_nonzeros_l = c->lnz;
    m_flops = c->fl;
  } else if (lower.rows() != m_n || lower.nonZeros() != m_pattern_nonzeros) {
    throw std::invalid_argument("CholmodFactor: factorize() needs the pattern of the first call");
  }
  m_message.clear();
  const int ok = cholmod_factorize(&a, m_cholmod->factor, c);
  throw_if_out_of_memory(*c);
  const cholmod_factor& f = *m_cholmod->factor;
  if (ok && c->status == CHOLMOD_OK && f.minor == f.n) {
    m_status = Status::successful;
  } else if (c->status == CHOLMOD_NOT_POSDEF || f.minor < f.n) {
    m_status = Status::not_positive_definite;
    const int* perm = static_cast<const int*>(f.Perm);
    const size_t column = f.minor < f.n && perm ? static_cast<size_t>(perm[f.minor]) : f.minor;
    m_message = "not positive definite: pivot <= 0 at column " + std::to_string(column) + " of " +
                std::to_string(f.n) + " (CHOLMOD)";
  } else {
    m_status = Status::failed;
    m_message = "CHOLMOD factorization failed (status " + std::to_string(c->status) + ")";
  }
  return m_status;
}

bool CholmodFactor::solve(System system, const Eigen::Ref<const Eigen::MatrixXd>& b,
                          Eigen::Ref<Eigen::MatrixXd> x) const {
  if (m_status != Status::successful || b.rows() != m_n || x.rows() != m_n ||
      x.cols() != b.cols() || b.cols() < 1)
    return false;
  cholmod_common* c = &m_cholmod->common;
  const cholmod_dense rhs = view(b);
  // A^-1 b directly; the half solves through CHOLMOD's permutation systems.
  const int first = system == System::a     ? CHOLMOD_A
                    : system == System::l_p ? CHOLMOD_P
                                            : CHOLMOD_Lt;
  const int solved =
      cholmod_solve2(first, m_cholmod->factor, const_cast<cholmod_dense*>(&rhs), nullptr,
                     &m_cholmod->x, nullptr, &m_cholmod->y, &m_cholmod->e, c);
  throw_if_out_of_memory(*c);
  if (!solved || c->status != CHOLMOD_OK) return false;
  if (system != System::a) {
    // cholmod_solve2 may reuse its result as workspace: copy it out first.
    const Eigen::MatrixXd half = Eigen::Map<const Eigen::MatrixXd>(
        static_cast<const double*>(m_cholmod->x->x), m_n, b.cols());
    const cholmod_dense rhs2 = view(half);
    const int second = system == System::l_p ? CHOLMOD_L : CHOLMOD_Pt;
    const int solved2 =
        cholmod_solve2(second, m_cholmod->factor, const_cast<cholmod_dense*>(&rhs2), nullptr,
                       &m_cholmod->x, nullptr, &m_cholmod->y, &m_cholmod->e, c);
    throw_if_out_of_memory(*c);
    if (!solved2 || c->status != CHOLMOD_OK) return false;
  }
  x = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(m_cholmod->x->x), m_n, b.cols());
  return true;
}

double CholmodFactor::rcond() const {
  if (m_status != Status::successful) return 0.0;
  return cholmod_rcond(m_cholmod->factor, &m_cholmod->common);
}

} // namespace rsi

#include "mass_factor.hpp"

#include <algorithm>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cholmod_handles.hpp"

namespace rsi {

namespace {

/// What to change (issue 13, class 8): the paper's case checks its M when it
/// loads, a component's M may be singular (a consistent C3D15 mass).
const std::string kMassWhy =
    "; a full-order run needs M positive definite (the paper's case checks it when it loads)";
const FailureAdvice kMassAdvice = remedied_by({Remedy::component_lumped_mass_or_reduced_method});

/// The level of each column of L (CHOLMOD's simplicial LDL^T, AMD order):
/// 0 for a column no other precedes (l_jk = 0 for all k < j), else one more
/// than the highest column its row reads.
std::vector<int> column_levels(const cholmod_factor& f) {
  const int n = static_cast<int>(f.n);
  const auto* p = static_cast<const int*>(f.p);
  const auto* nz = static_cast<const int*>(f.nz);
  const auto* row = static_cast<const int*>(f.i);
  std::vector<int> level(n, 0);
  for (int j = 0; j < n; ++j) // l_ij != 0 (i > j): row i waits for column j
    for (int k = p[j] + 1; k < p[j] + nz[j]; ++k)
      level[row[k]] = std::max(level[row[k]], level[j] + 1);
  return level;
}

/// The connected component of each column of L (AMD order), numbered in the
/// order their first columns come: the trees of L's elimination forest,
/// parent(j) = the first row below j in column j.
std::vector<int> components(const cholmod_factor& f) {
  const int n = static_cast<int>(f.n);
  const auto* p = static_cast<const int*>(f.p);
  const auto* nz = static_cast<const int*>(f.nz);
  const auto* row = static_cast<const int*>(f.i);
  std::vector<int> root(n);
  for (int j = n - 1; j >= 0; --j) { // a parent comes after its children
    int parent = n;
    for (int k = p[j] + 1; k < p[j] + nz[j]; ++k)
      parent = std::min(parent, row[k]);
    root[j] = parent == n ? j : root[parent];
  }
  std::vector<int> number(n, -1);
  std::vector<int> component(n);
  int count = 0;
  for (int j = 0; j < n; ++j) {
    if (number[root[j]] < 0) number[root[j]] = count++;
    component[j] = number[root[j]];
  }
  return component;
}

/// 0..n-1 sorted by key(i), stably.
template <class Key> std::vector<int> sorted_by(int n, Key key) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  return order;
}

} // namespace

MassFactor::MassFactor(const Eigen::SparseMatrix<double>& mass) {
  const auto n = static_cast<int>(mass.rows());
  CholmodHandles c;
  c.common.supernodal = CHOLMOD_SIMPLICIAL;
  c.common.final_ll = 0; // keep LDL^T
  Eigen::SparseMatrix<double> lower = mass.triangularView<Eigen::Lower>();
  lower.makeCompressed();
  cholmod_sparse a = cholmod_lower_view(lower);
  c.factor = cholmod_analyze_serialized(&a, &c.common);
  const bool factorized = c.factor != nullptr && cholmod_factorize(&a, c.factor, &c.common);
  // Out of memory is no property of M: thrown as operator new would.
  if (c.common.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
  if (!factorized || c.common.status != CHOLMOD_OK || c.factor->minor < c.factor->n ||
      c.factor->is_ll || c.factor->is_super)
    throw MassFactorError(
        "the mass matrix is not positive definite (CHOLMOD factorization failed, status " +
            std::to_string(c.common.status) + ")" + kMassWhy,
        kMassAdvice);
  // Simplicial LDL^T: D_jj is the first entry of column j (AMD order), then L's.
  const cholmod_factor& f = *c.factor;
  const auto* p = static_cast<const int*>(f.p);
  const auto* nz = static_cast<const int*>(f.nz);
  const auto* row = static_cast<const int*>(f.i);
  const auto* x = static_cast<const double*>(f.x);
  const auto* perm = static_cast<const int*>(f.Perm);
  for (int j = 0; j < n; ++j)
    if (!(x[p[j]] > 0.0))
      throw MassFactorError("the mass matrix is not positive definite (LDL^T pivot " +
                                std::to_string(x[p[j]]) + " at dof " + std::to_string(perm[j]) +
                                ")" + kMassWhy,
                            kMassAdvice);

  // P: AMD, then the columns sorted by component and level (ties kept in
  // AMD order), so that each component is a contiguous block.
  const std::vector<int> level_of_column = column_levels(f);
  const std::vector<int> component_of_column = components(f);
  const std::vector<int> new_order = sorted_by(
      n, [&](int j) { return std::make_pair(component_of_column[j], level_of_column[j]); });
  std::vector<int> level(n); // level[i]: of the column now at position i
  std::vector<int> to(n);    // AMD column j -> position to[j]
  m_block_start.assign(1, 0);
  for (int k = 0; k < n; ++k) {
    to[new_order[k]] = k;
    level[k] = level_of_column[new_order[k]];
    if (k > 0 && component_of_column[new_order[k]] != component_of_column[new_order[k - 1]])
      m_block_start.push_back(k);
  }
  m_block_start.push_back(n);
  m_block_of.resize(n);
  for (size_t b = 0; b + 1 < m_block_start.size(); ++b)
    m_block_of.segment(m_block_start[b], m_block_start[b + 1] - m_block_start[b])
        .setConstant(static_cast<int>(b));
  m_position.resize(n);
  for (int k = 0; k < n; ++k)
    m_position(perm[k]) = to[k];
  m_inverse_d.resize(n);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(p[n]));
  for (int j = 0; j < n; ++j) {
    m_inverse_d(to[j]) = 1.0 / x[p[j]];
    for (int k = p[j] + 1; k < p[j] + nz[j]; ++k)
      entries.emplace_back(to[row[k]], to[j], x[k]);
  }
  m_l_rows.resize(n, n);
  m_l_rows.setFromTriplets(entries.begin(), entries.end());
  m_l_rows.makeCompressed();
  const RowMajorMatrix lt_rows = m_l_rows.transpose();
  // Forward: level by level upward; backward: downward. Within a level the
  // rows are independent, so they are taken shortest first (longer runs of
  // one length).
  m_forward = SparseRows(
      m_l_rows,
      sorted_by(n, [&](int i) { return std::make_pair(level[i], m_l_rows.row(i).nonZeros()); }),
      level);
  m_backward = SparseRows(
      lt_rows,
      sorted_by(n, [&](int i) { return std::make_pair(-level[i], lt_rows.row(i).nonZeros()); }),
      level);
}

Eigen::SparseMatrix<double> MassFactor::permuted(const Eigen::SparseMatrix<double>& a) const {
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p(m_position);
  return p * a * p.inverse();
}

void MassFactor::solve_in_place(Eigen::Ref<Eigen::VectorXd> r) const {
  if (r.size() != n_dofs())
    throw std::invalid_argument("MassFactor: the vector must have one entry per dof");
  double* x = r.data();
  const double* inverse_d = m_inverse_d.data();
  // L y = r: y_i = r_i - sum_{j<i} l_ij y_j, each row after those it reads.
  m_forward.for_each_row(x, [x](int i, double sum) { x[i] -= sum; });
  // L^T x = D^-1 y: x_j = y_j / D_jj - sum_{i>j} l_ij x_i, from the top level down.
  m_backward.for_each_row(x,
                          [x, inverse_d](int j, double sum) { x[j] = x[j] * inverse_d[j] - sum; });
}

} // namespace rsi

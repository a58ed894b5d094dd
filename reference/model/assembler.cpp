#include "assembler.hpp"

#include <cassert>

namespace rsi {

void Assembler::add(const Eigen::Ref<const Eigen::MatrixXd>& ke,
                    const Eigen::Ref<const Eigen::MatrixXd>& me,
                    const std::vector<DofCombination>& map) {
  assert(ke.rows() == static_cast<Eigen::Index>(map.size()) && me.rows() == ke.rows());
  scatter(ke, map, m_k);
  scatter(me, map, m_m);
}

void Assembler::scatter(const Eigen::Ref<const Eigen::MatrixXd>& e,
                        const std::vector<DofCombination>& map, Triplets& out) {
  const int n = static_cast<int>(map.size());
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (const auto& [ga, ca] : map[a])
        for (const auto& [gb, cb] : map[b])
          out.emplace_back(ga, gb, ca * cb * e(a, b));
}

Eigen::SparseMatrix<double> Assembler::build(const Triplets& t) const {
  Eigen::SparseMatrix<double> m(m_n, m_n);
  m.setFromTriplets(t.begin(), t.end());
  // The sums for (i, j) and (j, i) add the same terms in other orders (and
  // rotated element matrices are symmetric only to round-off): make the
  // matrix exactly symmetric, 0.5 (a_ij + a_ji) being the same double both
  // ways, so one stored triangle (Matrix Market, dsygvd) is the whole matrix.
  const Eigen::SparseMatrix<double> transposed = m.transpose();
  Eigen::SparseMatrix<double> symmetric = 0.5 * (m + transposed);
  // The coefficients make exact zeros only by cancellation; drop those.
  symmetric.prune(0.0);
  return symmetric;
}

Eigen::SparseMatrix<double> block_diagonal(const Eigen::SparseMatrix<double>& a,
                                           const Eigen::SparseMatrix<double>& b) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < a.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it)
      t.emplace_back(it.row(), it.col(), it.value());
  for (int j = 0; j < b.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(b, j); it; ++it)
      t.emplace_back(a.rows() + it.row(), a.cols() + it.col(), it.value());
  Eigen::SparseMatrix<double> m(a.rows() + b.rows(), a.cols() + b.cols());
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

} // namespace rsi

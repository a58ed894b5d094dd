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
  // The coefficients make exact zeros only by cancellation; drop those.
  m.prune(0.0);
  return m;
}

} // namespace rsi

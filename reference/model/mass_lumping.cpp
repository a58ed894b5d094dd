#include "mass_lumping.hpp"

#include <map>

namespace rsi {

Eigen::SparseMatrix<double> hrz_lumped_mass(const Component& component) {
  const Eigen::SparseMatrix<double>& m = component.mass;
  std::map<std::string, double> total, diagonal;
  for (int j = 0; j < m.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, j); it; ++it) {
      const std::string& kind = component.dofs[static_cast<int>(it.row())].kind;
      if (kind != component.dofs[j].kind) continue;
      total[kind] += it.value();
      if (it.row() == j) diagonal[kind] += it.value();
    }
  Eigen::SparseMatrix<double> lumped(m.rows(), m.cols());
  lumped.reserve(Eigen::VectorXi::Constant(m.cols(), 1));
  for (int j = 0; j < m.cols(); ++j) {
    const std::string& kind = component.dofs[j].kind;
    if (!(total[kind] > 0.0))
      throw ImportError(component.name + ": the mass of direction " + kind +
                        " (sum of its block of M) is not positive; HRZ lumping needs it");
    lumped.insert(j, j) = m.coeff(j, j) * total[kind] / diagonal[kind];
  }
  lumped.makeCompressed();
  return lumped;
}

} // namespace rsi

#include "turned_constraint_modes.hpp"

#include <cstddef>
#include <vector>

#include "transpose_product.hpp"

namespace rsi {

CyclicBoundary cyclic_boundary(const Component& c, int sectors, const Partition& p) {
  CyclicBoundary out{cyclic_symmetry(c, sectors), {}};
  out.orbits = boundary_orbits(out.symmetry, p);
  return out;
}

Eigen::MatrixXd turned_constraint_modes(const Eigen::SparseMatrix<double>& stiffness,
                                        const Partition& p, const CyclicBoundary& cyclic,
                                        const InteriorSolve& solve) {
  const BoundaryOrbits& o = cyclic.orbits;
  const std::vector<int> positions = o.representative_positions();
  std::vector<int> dofs;
  for (int j : positions)
    dofs.push_back(p.boundary[static_cast<size_t>(j)]);
  const Eigen::MatrixXd k_ib = Eigen::MatrixXd(sparse_block(stiffness, p.interior, dofs));
  // The representatives' whole fields: interior rows solved, boundary rows
  // the unit displacements.
  Eigen::MatrixXd unit =
      Eigen::MatrixXd::Zero(p.n_boundary(), static_cast<Eigen::Index>(dofs.size()));
  for (size_t i = 0; i < positions.size(); ++i)
    unit(positions[i], static_cast<Eigen::Index>(i)) = 1.0;
  const Eigen::MatrixXd psi_r = solve(-k_ib);
  const Eigen::MatrixXd fields =
      place_rows(p.n(), p.interior, psi_r) + place_rows(p.n(), p.boundary, unit);
  Eigen::MatrixXd out(p.n_interior(), p.n_boundary());
  for (int k = 0; k < o.sectors; ++k) {
    const Eigen::MatrixXd turned =
        k == 0 ? psi_r : take_rows(turn_fields(cyclic.symmetry, k, fields), p.interior);
    const Eigen::Matrix3d r = turn_rotation(cyclic.symmetry, k);
    for (int rep = 0; rep < o.n_representatives(); ++rep)
      for (int c = 0; c < 3; ++c) {
        const int at =
            o.position[static_cast<size_t>(rep)][static_cast<size_t>(k)][static_cast<size_t>(c)];
        if (k == 0) {
          out.col(at) = psi_r.col(3 * rep + c);
          continue;
        }
        // Direction e_c at the turned node: sum_d (R^k)_cd R^k e_d = e_c.
        out.col(at) = r(c, 0) * turned.col(3 * rep) + r(c, 1) * turned.col(3 * rep + 1) +
                      r(c, 2) * turned.col(3 * rep + 2);
      }
  }
  return out;
}

Eigen::MatrixXd cyclic_projection(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& t,
                                  int eta, const CyclicBoundary& cyclic) {
  const BoundaryOrbits& o = cyclic.orbits;
  const int n_r = o.n_representatives();
  const Eigen::Index r = t.cols();
  Eigen::MatrixXd w(t.rows(), eta + 3 * n_r);
  w.leftCols(eta) = t.leftCols(eta);
  const std::vector<int> positions = o.representative_positions();
  for (size_t i = 0; i < positions.size(); ++i)
    w.col(eta + static_cast<Eigen::Index>(i)) = t.col(eta + positions[i]);
  // W^T A T as finish_basis forms T^T A T (guyan.cpp): A^T W gathered.
  const Eigen::MatrixXd rows = transpose_product(a, w).transpose() * t;
  Eigen::MatrixXd out(r, r);
  out.topRows(eta) = rows.topRows(eta);
  out.bottomLeftCorner(r - eta, eta) = rows.topRightCorner(eta, r - eta).transpose();
  out.bottomRightCorner(r - eta, r - eta) =
      turned_boundary_block(rows.bottomRightCorner(3 * n_r, r - eta), cyclic);
  return out;
}

Eigen::MatrixXd turned_boundary_block(const Eigen::MatrixXd& rows, const CyclicBoundary& cyclic) {
  const BoundaryOrbits& o = cyclic.orbits;
  const int n_r = o.n_representatives();
  const Eigen::Index nb = rows.cols();
  Eigen::MatrixXd out(nb, nb);
  const int n = o.sectors;
  Eigen::Matrix3d block;
  for (int k = 0; k < n; ++k) {
    const Eigen::Matrix3d turn = turn_rotation(cyclic.symmetry, k);
    for (int rep = 0; rep < n_r; ++rep) {
      const auto& row = o.position[static_cast<size_t>(rep)][static_cast<size_t>(k)];
      for (int rep2 = 0; rep2 < n_r; ++rep2)
        for (int k2 = 0; k2 < n; ++k2) {
          // The column triple turned back by k: P^-k(P^k2 r2) = P^(k2-k) r2.
          const auto& back =
              o.position[static_cast<size_t>(rep2)][static_cast<size_t>((k2 - k + n) % n)];
          const auto& col = o.position[static_cast<size_t>(rep2)][static_cast<size_t>(k2)];
          for (int d = 0; d < 3; ++d)
            for (int e = 0; e < 3; ++e)
              block(d, e) = rows(3 * rep + d, back[static_cast<size_t>(e)]);
          const Eigen::Matrix3d turned =
              k == 0 ? block : Eigen::Matrix3d(turn * block * turn.transpose());
          for (int c = 0; c < 3; ++c)
            for (int c2 = 0; c2 < 3; ++c2)
              out(row[static_cast<size_t>(c)], col[static_cast<size_t>(c2)]) = turned(c, c2);
        }
    }
  }
  return out;
}

} // namespace rsi

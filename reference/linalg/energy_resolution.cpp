#include "energy_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "cholmod_factor.hpp"

namespace rsi {

EnergyResolution energy_resolution(const Eigen::SparseMatrix<double>& a,
                                   const Eigen::Ref<const Eigen::VectorXd>& x) {
  EnergyResolution r;
  const Eigen::VectorXd ax = a * x;
  r.energy = x.dot(ax);
  r.magnitude = x.cwiseAbs().dot(a.cwiseAbs() * x.cwiseAbs());
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) // symmetric: a column's entries are a row's
    r.row_terms =
        std::max(r.row_terms, static_cast<int>(a.outerIndexPtr()[j + 1] - a.outerIndexPtr()[j]));
  // gamma_p = p eps / (1 - p eps) (Higham, eq. 3.5).
  const double pe = r.row_terms * std::numeric_limits<double>::epsilon();
  r.rounding = pe / (1.0 - pe) * r.magnitude;
  return r;
}

DefinitenessCheck lowest_energy(const Eigen::SparseMatrix<double>& a,
                                const Eigen::SparseMatrix<double>& b, const FactorSolve& solve) {
  DefinitenessCheck check;
  const Eigen::Index n = a.rows();
  const bool identity = b.rows() == 0;
  const auto b_times = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    return identity ? v : Eigen::VectorXd(b * v);
  };
  // A fixed pseudo-random start (as block_shift_invert's): no special
  // structure to be orthogonal to the lowest mode.
  std::mt19937_64 generator(20070904);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i)
    x(i) = static_cast<double>(generator() >> 11) * 0x1.0p-52 - 0.5;
  Eigen::VectorXd y(n);
  double previous = std::numeric_limits<double>::quiet_NaN();
  for (int step = 1; step <= 100; ++step) {
    check.iterations = step;
    if (!solve(b_times(x), y)) {
      check.why = "the solve with the factor failed";
      return check;
    }
    const double norm = std::sqrt(y.dot(b_times(y)));
    if (!(norm > 0.0) || !std::isfinite(norm)) break;
    x = y / norm;
    check.eigenvalue = x.dot(a * x);
    // 1 % on the energy (energy_resolution.hpp); an energy <= 0 is decided.
    if (!(check.eigenvalue > 0.0) ||
        std::abs(check.eigenvalue - previous) < 0.01 * std::abs(check.eigenvalue))
      break;
    previous = check.eigenvalue;
  }
  check.factorized = true;
  check.motion = x;
  check.resolution = energy_resolution(a, x);
  return check;
}

DefinitenessCheck check_positive_definite(const Eigen::SparseMatrix<double>& a,
                                          const Eigen::SparseMatrix<double>& b) {
  // Simplicial: no BLAS, no threads; the matrices checked here are the
  // banded 2D parts (a ring, a chain of sectors), quick either way.
  CholmodFactor factor(CholmodFactor::Method::simplicial);
  Eigen::SparseMatrix<double> lower = a.triangularView<Eigen::Lower>();
  lower.makeCompressed();
  if (factor.factorize(lower) != CholmodFactor::Status::successful) {
    DefinitenessCheck check;
    check.why = factor.message();
    return check;
  }
  return lowest_energy(a, b, [&](const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
    return factor.solve(CholmodFactor::System::a, rhs, x);
  });
}

} // namespace rsi

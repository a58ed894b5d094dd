#include "largest_eigenvalue_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/SparseCholesky>

namespace rsi {
namespace {

/// x^T K x / x^T M x lowered by its rounding bound (the header); 0 if the
/// rounding could reach the quotient itself.
double guaranteed_quotient(const Eigen::SparseMatrix<double>& k,
                           const Eigen::SparseMatrix<double>& m, const Eigen::VectorXd& x) {
  const Eigen::VectorXd ax = x.cwiseAbs();
  const double ek = x.dot(k * x);
  const double em = x.dot(m * x);
  if (!(ek > 0.0) || !(em > 0.0)) return 0.0;
  Eigen::Index p = 0;
  for (Eigen::Index j = 0; j < k.outerSize(); ++j)
    p = std::max<Eigen::Index>(p, std::max(k.outerIndexPtr()[j + 1] - k.outerIndexPtr()[j],
                                           m.outerIndexPtr()[j + 1] - m.outerIndexPtr()[j]));
  const double gamma = static_cast<double>(p + x.size()) * std::numeric_limits<double>::epsilon();
  const double ck = ax.dot(k.cwiseAbs() * ax) / ek;
  const double cm = ax.dot(m.cwiseAbs() * ax) / em;
  const double lowered = 1.0 - gamma * (ck + cm);
  return lowered > 0.0 ? ek / em * lowered : 0.0;
}

} // namespace

LargestEigenvalueBound largest_eigenvalue_lower_bound(const Eigen::SparseMatrix<double>& stiffness,
                                                      const Eigen::SparseMatrix<double>& mass) {
  LargestEigenvalueBound bound;
  const Eigen::Index n = stiffness.rows();
  // e_i^T K e_i / e_i^T M e_i: one multiplication each, exact but for its rounding (1 ulp).
  for (Eigen::Index i = 0; i < n; ++i)
    bound.one_dof = std::max(bound.one_dof, stiffness.coeff(i, i) / mass.coeff(i, i));
  bound.value = bound.one_dof * (1.0 - std::numeric_limits<double>::epsilon());
  if (n == 0) return bound;

  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(mass);
  if (factor.info() != Eigen::Success || !(factor.vectorD().minCoeff() > 0.0))
    return bound; // M not positive definite: the runs' own mass checks say so
  std::mt19937_64 generator(20070904);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i)
    x(i) = static_cast<double>(generator() >> 11) * 0x1.0p-52 - 0.5;
  Eigen::VectorXd best = x;
  double best_quotient = 0.0;
  for (int step = 1; step <= 100; ++step) {
    x = factor.solve(stiffness * x);
    const double norm = std::sqrt(x.dot(mass * x));
    if (!(norm > 0.0) || !std::isfinite(norm)) break;
    x /= norm;
    bound.iterations = step;
    const double quotient = x.dot(stiffness * x); // x^T M x = 1
    if (quotient > best_quotient) {
      best_quotient = quotient;
      best = x;
    }
  }
  if (bound.iterations > 0)
    bound.value = std::max(bound.value, guaranteed_quotient(stiffness, mass, best));
  return bound;
}

} // namespace rsi

#include "speed_subspace.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SparseCore>

#include "reduction.hpp"
#include "worker_threads.hpp"

namespace rsi {
namespace {

using Clock = std::chrono::steady_clock;

/// Columns whose pivoted-QR diagonal falls below this fraction of the
/// largest (the columns scaled to unit length first) add nothing new: the
/// bases at neighbouring speeds share most of their span.
constexpr double new_direction_tolerance = 1e-10;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// T^T A T for a sparse A.
Eigen::MatrixXd projected(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& t) {
  const Eigen::MatrixXd at = a * t;
  Eigen::MatrixXd p = t.transpose() * at;
  return 0.5 * (p + p.transpose()); // symmetric to the rounding of the products
}

/// The method's basis at each speed, in the speeds' order, built on up to
/// `threads` threads taking speeds in turn (run_on_threads). Each basis is
/// one reduce() on its own K(Omega) (its own CHOLMOD factor and workspace),
/// so a basis has the same bits whichever thread builds it. The first
/// exception of a build is rethrown once every thread has joined.
std::vector<ReducedBasis> bases_at_speeds(const RotationFit& fit, const std::string& method,
                                          int modes, const std::vector<double>& speeds,
                                          int threads) {
  const std::vector<int>& boundary = fit.rest.boundary;
  const size_t n = speeds.size();
  std::vector<std::optional<ReducedBasis>> built(n);
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  const auto worker = [&]() {
    for (size_t i = next++; i < n && !failed; i = next++) {
      const RotatingComponent at = rotating_component_at(fit, speeds[i]);
      built[i] = reduce(at.component.stiffness, at.component.mass, boundary, method, modes);
    }
  };
  run_on_threads(static_cast<int>(std::min(n, static_cast<size_t>(std::max(threads, 1)))), worker,
                 failed);
  std::vector<ReducedBasis> bases;
  for (size_t i = 0; i < n; ++i) {
    if (!built[i]) throw std::logic_error("speed_subspace: a basis speed was not built");
    bases.push_back(std::move(*built[i]));
  }
  return bases;
}

} // namespace

SpeedSubspace speed_subspace(const RotationFit& fit, const std::string& method, int modes,
                             const std::vector<double>& basis_speeds, int threads) {
  const Clock::time_point start = Clock::now();
  if (basis_speeds.empty())
    throw std::invalid_argument("speed_subspace: no basis speed");
  const std::vector<int>& boundary = fit.rest.boundary;
  const int n = fit.rest.n_dofs();
  const int nb = static_cast<int>(boundary.size());
  SpeedSubspace s;
  s.method = method;
  s.modes = modes;
  s.basis_speeds = basis_speeds;
  s.n_boundary = nb;
  const std::vector<ReducedBasis> bases = bases_at_speeds(fit, method, modes, basis_speeds, threads);
  Eigen::MatrixXd psi;                 // Psi_0, n x n_B
  std::vector<Eigen::MatrixXd> others; // every column, its boundary part removed
  for (const ReducedBasis& b : bases) {
    const Eigen::MatrixXd& t = b.transformation;
    if (psi.size() == 0) {
      psi.resize(n, nb);
      for (int k = 0; k < nb; ++k)
        psi.col(k) = t.col(b.boundary_position[static_cast<size_t>(k)]);
      for (int k = 0; k < nb; ++k)
        for (int l = 0; l < nb; ++l)
          if (psi(boundary[static_cast<size_t>(l)], k) != (k == l ? 1.0 : 0.0))
            throw std::logic_error("speed_subspace: the " + method + " basis does not keep the "
                                   "boundary dofs as physical coordinates");
    }
    Eigen::MatrixXd w = t;
    for (int k = 0; k < nb; ++k) {
      const Eigen::RowVectorXd on_boundary = t.row(boundary[static_cast<size_t>(k)]);
      w -= psi.col(k) * on_boundary;
    }
    for (int k : boundary) w.row(k).setZero();
    others.push_back(std::move(w));
  }
  Eigen::Index columns = 0;
  for (const Eigen::MatrixXd& w : others) columns += w.cols();
  Eigen::MatrixXd candidates(n, columns);
  columns = 0;
  for (const Eigen::MatrixXd& w : others) {
    for (Eigen::Index j = 0; j < w.cols(); ++j) {
      const double norm = w.col(j).norm();
      candidates.col(columns++) = norm > 0.0 ? Eigen::VectorXd(w.col(j) / norm)
                                             : Eigen::VectorXd::Zero(n);
    }
  }
  others.clear();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(candidates);
  qr.setThreshold(new_direction_tolerance);
  const Eigen::Index rank = qr.rank();
  candidates.resize(0, 0);
  s.transformation.resize(n, nb + rank);
  s.transformation.leftCols(nb) = psi;
  s.transformation.rightCols(rank) = qr.householderQ() * Eigen::MatrixXd::Identity(n, rank);
  for (int k : boundary) s.transformation.row(k).tail(rank).setZero();
  s.rest_stiffness = projected(fit.rest.stiffness, s.transformation);
  for (const Eigen::SparseMatrix<double>& c : fit.terms)
    s.terms.push_back(projected(c, s.transformation));
  s.mass = projected(fit.rest.mass, s.transformation);
  s.build_seconds = seconds_since(start);
  return s;
}

Eigen::MatrixXd subspace_stiffness(const SpeedSubspace& subspace, const RotationFit& fit,
                                   double speed) {
  Eigen::MatrixXd k = subspace.rest_stiffness;
  if (speed != 0.0) {
    const Eigen::VectorXd u = rotation_fit_deflection(fit, speed);
    const Eigen::VectorXd f = rotation_fit_features(fit.shapes.transpose() * u, speed);
    for (size_t q = 0; q < subspace.terms.size(); ++q)
      k += f(static_cast<Eigen::Index>(q)) * subspace.terms[q];
  }
  return k;
}

Eigen::VectorXd subspace_eigenvalues(const SpeedSubspace& subspace, const RotationFit& fit,
                                     double speed, int count) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> e(
      subspace_stiffness(subspace, fit, speed), subspace.mass, Eigen::EigenvaluesOnly);
  if (e.info() != Eigen::Success)
    throw std::runtime_error("speed subspace: the dense eigensolver failed at " +
                             std::to_string(speed) + " rad/s");
  return e.eigenvalues().head(std::min<Eigen::Index>(count, e.eigenvalues().size()));
}

ReducedBasis reduce_at_speed(const SpeedSubspace& subspace, const RotationFit& fit, double speed) {
  const Clock::time_point start = Clock::now();
  std::vector<int> boundary(static_cast<size_t>(subspace.n_boundary));
  for (int i = 0; i < subspace.n_boundary; ++i) boundary[static_cast<size_t>(i)] = i;
  const Eigen::SparseMatrix<double> ks = subspace_stiffness(subspace, fit, speed).sparseView();
  const Eigen::SparseMatrix<double> ms = subspace.mass.sparseView();
  ReducedBasis basis = reduce(ks, ms, boundary, subspace.method, subspace.modes);
  basis.transformation = subspace.transformation * basis.transformation;
  basis.build_seconds = seconds_since(start);
  return basis;
}

} // namespace rsi

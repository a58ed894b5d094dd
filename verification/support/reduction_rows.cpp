#include "reduction_rows.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymEigsSolver.h>
#include <lapacke.h>

#include "critical_step.hpp"
#include "dense_norms.hpp"

namespace rsi::rows {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double lowest_double = std::numeric_limits<double>::lowest();

using Cholmod = Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>>;

/// ||A||_inf of a sparse matrix (max row sum of |a_ij|).
/// The coordinates of q that are not boundary coordinates (modal ones).
std::vector<int> modal_positions(const ReducedBasis& b) {
  std::vector<bool> is_boundary(b.n_reduced(), false);
  for (int i : b.boundary_position)
    is_boundary[i] = true;
  std::vector<int> out;
  for (int i = 0; i < b.n_reduced(); ++i)
    if (!is_boundary[i]) out.push_back(i);
  return out;
}

/// A CHOLMOD factor of a sparse symmetric positive definite matrix, status checked.
void factorize(Cholmod& factor, const Eigen::SparseMatrix<double>& a, const char* what) {
  factor.compute(a);
  if (factor.info() != Eigen::Success)
    throw std::runtime_error(std::string("reduction rows: CHOLMOD factorization of ") + what +
                             " failed (not positive definite?)");
}

Eigen::MatrixXd checked_solve(const Cholmod& factor, const Eigen::Ref<const Eigen::MatrixXd>& f) {
  Eigen::MatrixXd x = factor.solve(f);
  if (factor.info() != Eigen::Success)
    throw std::runtime_error("reduction rows: CHOLMOD solve failed");
  return x;
}

/// x -> A^-1 x through a factor, as a Spectra operation.
class InverseProduct {
public:
  using Scalar = double;
  InverseProduct(const Cholmod& factor, Eigen::Index n)
      : m_factor(factor)
      , m_n(n) {}
  Eigen::Index rows() const { return m_n; }
  Eigen::Index cols() const { return m_n; }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<Eigen::VectorXd>(y_out, m_n) =
        checked_solve(m_factor, Eigen::Map<const Eigen::VectorXd>(x_in, m_n));
  }

private:
  const Cholmod& m_factor;
  Eigen::Index m_n;
};

/// Largest eigenvalue of a symmetric operation (Spectra's Lanczos).
template <class Op> double largest_eigenvalue(Op& op, Eigen::Index n) {
  Spectra::SymEigsSolver<Op> solver(op, 1, static_cast<int>(std::min<Eigen::Index>(n, 30)));
  solver.init();
  solver.compute(Spectra::SortRule::LargestAlge, 10000, lanczos_tol);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("reduction rows: Lanczos for an extreme eigenvalue did not converge");
  return solver.eigenvalues()(0);
}

/// lambda_min of a sparse symmetric positive definite matrix: 1 / lambda_max(A^-1).
double lowest_eigenvalue(const Cholmod& factor, Eigen::Index n) {
  InverseProduct op(factor, n);
  return 1.0 / largest_eigenvalue(op, n);
}

/// Dense generalized eigenpairs of a reduced basis (M^ positive definite),
/// eigenvectors M^-normalised, and the bound of each eigenvalue: the dense
/// solve, r eps (||K^|| + |w2| ||M^||) ||x||^2 (in the coordinates the
/// solver saw), and the rounding of K^, M^,
/// n eps ((|T||x|)^T |K| (|T||x|) + |w2| (|T||x|)^T |M| (|T||x|)).
struct ReducedEigen {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  Eigen::VectorXd bound;
};

/// Adds the rounding of K^ and M^ to out.bound, which holds the dense
/// solve's bound of each eigenvalue.
void add_forming_bounds(const Component& c, const ReducedBasis& b, ReducedEigen& out) {
  const Eigen::MatrixXd shapes = b.transformation.cwiseAbs() * out.vectors.cwiseAbs();
  const Eigen::MatrixXd k_shapes = c.k_abs() * shapes;
  const Eigen::MatrixXd m_shapes = c.m_abs() * shapes;
  for (int i = 0; i < b.n_reduced(); ++i) {
    const double w2 = std::abs(out.values(i));
    out.bound(i) += c.n() * eps *
                    (shapes.col(i).dot(k_shapes.col(i)) + w2 * shapes.col(i).dot(m_shapes.col(i)));
  }
}

ReducedEigen reduced_eigen(const Component& c, const ReducedBasis& b) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(b.stiffness, b.mass);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("reduction rows: dense reduced eigenproblem failed (" + b.method +
                             ")");
  ReducedEigen out;
  out.values = solver.eigenvalues();
  out.vectors = solver.eigenvectors();
  const int r = b.n_reduced();
  const double k_hat = norm_inf(b.stiffness);
  const double m_hat = norm_inf(b.mass);
  out.bound.resize(r);
  for (int i = 0; i < r; ++i)
    out.bound(i) =
        r * eps * (k_hat + std::abs(out.values(i)) * m_hat) * out.vectors.col(i).squaredNorm();
  add_forming_bounds(c, b, out);
  return out;
}

/// The same by LAPACK's dsygvd (divide and conquer: seconds where Eigen's
/// solver takes minutes at r = 4,000), on the pencil scaled by
/// D = diag(2^-round(log2(M^_jj) / 2)): powers of two, so D K^ D and D M^ D
/// are exact and have the same eigenvalues, and D M^ D has a diagonal in
/// [0.5, 2). The scaling matters for the bound, not the result: unscaled,
/// ||K^|| (the highest fixed-interface omega^2) times ||x||^2 (large on
/// coordinates of small mass) bounds the lowest eigenvalue of a complete CB
/// basis of the gmsh blade only to 6,000 times itself; scaled, x_s = D^-1 x
/// has ||x_s||^2 near x^T M^ x = 1 and the bound is r eps ||D K^ D||, about
/// r eps lambda_max: the absolute accuracy of any dense solver, a relative
/// one of r eps lambda_max / lambda_i for the lowest.
ReducedEigen reduced_eigen_lapack(const Component& c, const ReducedBasis& b) {
  const int r = b.n_reduced();
  Eigen::VectorXd d(r);
  for (int j = 0; j < r; ++j)
    d(j) = std::ldexp(1.0, -std::ilogb(b.mass(j, j)) / 2);
  ReducedEigen out;
  out.vectors = d.asDiagonal() * b.stiffness * d.asDiagonal();
  Eigen::MatrixXd m = d.asDiagonal() * b.mass * d.asDiagonal();
  const double k_s = norm_inf(out.vectors);
  const double m_s = norm_inf(m);
  out.values.resize(r);
  const lapack_int info = LAPACKE_dsygvd(LAPACK_COL_MAJOR, 1, 'V', 'L', r, out.vectors.data(), r,
                                         m.data(), r, out.values.data());
  if (info != 0)
    throw std::runtime_error("reduction rows: LAPACKE_dsygvd of (K^, M^) failed for " + b.method +
                             " (info " + std::to_string(info) + ")");
  out.bound.resize(r);
  for (int i = 0; i < r; ++i)
    out.bound(i) =
        r * eps * (k_s + std::abs(out.values(i)) * m_s) * out.vectors.col(i).squaredNorm();
  out.vectors = d.asDiagonal() * out.vectors; // x = D x_s, M^-normalised
  add_forming_bounds(c, b, out);
  return out;
}

/// Largest |a_ij - b_ij| in units of the spacing of doubles at |b_ij|.
double max_ulps(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double worst = 0.0;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      const double ulp = std::nextafter(std::abs(b(i, j)), HUGE_VAL) - std::abs(b(i, j));
      worst = std::max(worst, std::abs(a(i, j) - b(i, j)) / ulp);
    }
  return worst;
}

} // namespace

// ---------------------------------------------------------------- Component

struct Component::Factor {
  Cholmod llt;
};

Component::Component(const Eigen::SparseMatrix<double>& stiffness,
                     const Eigen::SparseMatrix<double>& mass, const std::vector<int>& boundary)
    : m_k(stiffness)
    , m_m(mass)
    , m_k_abs(stiffness.cwiseAbs())
    , m_m_abs(mass.cwiseAbs())
    , m_p(make_partition(static_cast<int>(stiffness.rows()), boundary))
    , m_k_norm(norm_inf(stiffness))
    , m_m_norm(norm_inf(mass))
    , m_factor(std::make_unique<Factor>()) {
  factorize(m_factor->llt, stiffness, "K");
}

Component::~Component() = default;

Eigen::MatrixXd Component::solve(const Eigen::Ref<const Eigen::MatrixXd>& f) const {
  return checked_solve(m_factor->llt, f);
}

const Eigen::MatrixXd& Component::boundary_flexibility() const {
  if (m_boundary_flexibility.size() == 0) {
    const int nb = n_boundary();
    m_boundary_flexibility = take_rows(
        solve(place_rows(n(), m_p.boundary, Eigen::MatrixXd::Identity(nb, nb))), m_p.boundary);
  }
  return m_boundary_flexibility;
}

double Component::cond_k() const {
  if (m_cond_k == 0.0) {
    Spectra::SparseSymMatProd<double> product(m_k);
    m_cond_k = largest_eigenvalue(product, n()) / lowest_eigenvalue(m_factor->llt, n());
  }
  return m_cond_k;
}

double Component::lambda_max() const {
  if (m_lambda_max == 0.0) {
    try {
      const double omega = max_angular_frequency(m_k, m_m);
      m_lambda_max = omega * omega;
    } catch (const ModalError&) {
      // M not positive definite (Rotor 37's is singular): massless
      // directions are infinite eigenvalues.
      m_lambda_max = std::numeric_limits<double>::infinity();
    }
  }
  return m_lambda_max;
}

// ------------------------------------------------- precondition: M > 0

MassRow mass_definiteness(const Component& c, int count) {
  const int n = c.n();
  MassRow row;
  Cholmod m_factor;
  m_factor.compute(c.m());
  row.cholesky = m_factor.info() == Eigen::Success;
  Spectra::SparseSymMatProd<double> product(c.m());
  row.lambda_max = largest_eigenvalue(product, n);
  row.floor = n * eps * row.lambda_max;
  if (count == 0) return row;
  const double shift = std::sqrt(eps) * row.lambda_max;
  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  Cholmod shifted;
  factorize(shifted, c.m() + shift * identity, "M + sqrt(eps) lambda_max(M) I");
  InverseProduct op(shifted, n);
  Spectra::SymEigsSolver<InverseProduct> solver(op, count,
                                                std::min(n, std::max(2 * count + 1, count + 20)));
  solver.init();
  solver.compute(Spectra::SortRule::LargestAlge, 10000, lanczos_tol);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("reduction rows: Lanczos for the lowest eigenvalues of M did not "
                             "converge");
  row.lowest = (1.0 / solver.eigenvalues().array() - shift).matrix();
  std::sort(row.lowest.data(), row.lowest.data() + row.lowest.size());
  row.n_below_floor = static_cast<int>((row.lowest.array() < row.floor).count());
  return row;
}

// ------------------------------------------------------------- V3: modes

ModeRow mode_orthogonality(const Eigen::SparseMatrix<double>& k,
                           const Eigen::SparseMatrix<double>& m, const Modes& modes, bool lanczos,
                           double lambda_max) {
  const int n = static_cast<int>(k.rows());
  const int count = modes.n_modes();
  const Eigen::MatrixXd& phi = modes.shapes;
  const Eigen::MatrixXd k_phi = k * phi;
  const Eigen::MatrixXd m_phi = m * phi;
  const Eigen::MatrixXd kk = phi.transpose() * k_phi;
  const Eigen::MatrixXd mm = phi.transpose() * m_phi;
  const Eigen::VectorXd length = phi.colwise().norm();
  const double k_norm = norm_inf(k);
  const double m_norm = norm_inf(m);
  const double tol = lanczos ? lanczos_tol : 0.0;
  const double w2_top = modes.omega_squared(count - 1);
  ModeRow row;
  row.n_modes = count;
  row.lanczos = lanczos;
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < count; ++i) {
      const double cross = length(i) * length(j);
      const double dm = std::abs(mm(i, j) - (i == j ? 1.0 : 0.0));
      row.mass.error = std::max(row.mass.error, dm);
      row.mass.ratio = std::max(row.mass.ratio, dm / (n * eps * m_norm * cross));
      if (i != j) {
        const double bound = n * eps * k_norm * cross + tol * tol * lambda_max;
        row.stiffness_off.error = std::max(row.stiffness_off.error, std::abs(kk(i, j)) / w2_top);
        row.stiffness_off.ratio = std::max(row.stiffness_off.ratio, std::abs(kk(i, j)) / bound);
      } else {
        const double w2 = modes.omega_squared(i);
        const double bound = 2.0 * n * eps * (k_norm + w2 * m_norm) * cross + tol * w2;
        const double err = std::abs(kk(i, i) - w2);
        row.stiffness_diag.error = std::max(row.stiffness_diag.error, err / w2);
        row.stiffness_diag.ratio = std::max(row.stiffness_diag.ratio, err / bound);
      }
    }
  for (int i = 0; i < count; ++i)
    row.residual =
        std::max(row.residual, (k_phi.col(i) - modes.omega_squared(i) * m_phi.col(i)).norm() /
                                   k_phi.col(i).norm());
  return row;
}

bool full_modes_by_lanczos(const Component& c) {
  return c.n() > dense_limit;
}

Modes full_modes(const Component& c, int count) {
  return lowest_modes(c.k(), c.m(), count, ModalSolver::automatic);
}

ModeRow full_mode_row(const Component& c, const Modes& full) {
  return mode_orthogonality(c.k(), c.m(), full, full_modes_by_lanczos(c), c.lambda_max());
}

ModeRow fixed_interface_row(const Component& c, int eta) {
  const Partition& p = c.partition();
  const Eigen::SparseMatrix<double> k_ii = sparse_block(c.k(), p.interior, p.interior);
  const Eigen::SparseMatrix<double> m_ii = sparse_block(c.m(), p.interior, p.interior);
  const ModalSolver solver = few_modes(eta, p.n_interior());
  const Modes fixed = lowest_modes(k_ii, m_ii, eta, solver);
  // Cauchy interlacing: lambda_max(K_II, M_II) <= lambda_max(K, M).
  return mode_orthogonality(k_ii, m_ii, fixed, solver == ModalSolver::sparse, c.lambda_max());
}

Eigen::VectorXd eigenvalue_bounds(const Component& c, const Modes& modes, bool lanczos) {
  Eigen::VectorXd bound(modes.n_modes());
  for (int i = 0; i < modes.n_modes(); ++i) {
    const double w2 = std::abs(modes.omega_squared(i));
    bound(i) = c.n() * eps * (c.k_norm() + w2 * c.m_norm()) * modes.shapes.col(i).squaredNorm() +
               (lanczos ? lanczos_tol * w2 : 0.0);
  }
  return bound;
}

FreeModeRow free_mode_row(const Component& c, int psi, const Modes& full) {
  const ModalSolver solver = few_modes(psi, c.n());
  const bool lanczos = solver == ModalSolver::sparse;
  const Modes free = lowest_modes(c.k(), c.m(), psi, solver);
  FreeModeRow row;
  row.modes = mode_orthogonality(c.k(), c.m(), free, lanczos, c.lambda_max());
  const Eigen::VectorXd free_bound = eigenvalue_bounds(c, free, lanczos);
  const Eigen::VectorXd full_bound = eigenvalue_bounds(c, full, full_modes_by_lanczos(c));
  for (int i = 0; i < std::min(psi, full.n_modes()); ++i) {
    const double err = std::abs(free.omega_squared(i) - full.omega_squared(i));
    row.eigenvalues.error = std::max(row.eigenvalues.error, err / full.omega_squared(i));
    row.eigenvalues.ratio = std::max(row.eigenvalues.ratio, err / (free_bound(i) + full_bound(i)));
  }
  return row;
}

// ------------------------------------------------------ V3: CB structure

BlockRow cb_block_diagonal(const Component& c, const ReducedBasis& cb) {
  const int n = c.n();
  const std::vector<int> modal = modal_positions(cb);
  const std::vector<int>& boundary = cb.boundary_position;
  const Eigen::VectorXd length = cb.transformation.colwise().norm();
  const double k_hat = norm_inf(cb.stiffness);
  const bool lanczos =
      few_modes(static_cast<int>(modal.size()), c.partition().n_interior()) == ModalSolver::sparse;
  const double tol = lanczos ? lanczos_tol : 0.0;
  BlockRow row;
  for (int i : modal) {
    for (int b : boundary) {
      const double v = std::abs(cb.stiffness(i, b));
      row.coupling.error = std::max(row.coupling.error, v / k_hat);
      row.coupling.ratio =
          std::max(row.coupling.ratio, v / (2.0 * n * eps * c.k_norm() * length(i) * length(b)));
    }
    for (int j : modal) {
      const double cross = length(i) * length(j);
      const double dm = std::abs(cb.mass(i, j) - (i == j ? 1.0 : 0.0));
      row.modal_mass.error = std::max(row.modal_mass.error, dm);
      row.modal_mass.ratio = std::max(row.modal_mass.ratio, dm / (n * eps * c.m_norm() * cross));
      if (i == j) continue;
      const double v = std::abs(cb.stiffness(i, j));
      row.modal_stiffness_off.error = std::max(row.modal_stiffness_off.error, v / k_hat);
      row.modal_stiffness_off.ratio =
          std::max(row.modal_stiffness_off.ratio,
                   v / (n * eps * c.k_norm() * cross + tol * tol * c.lambda_max()));
    }
  }
  return row;
}

// ------------------------------------------------------ V4: static loads

Eigen::MatrixXd random_boundary_loads(int n_boundary) {
  std::mt19937 generator(2007);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd loads(n_boundary, 4);
  for (Eigen::Index j = 0; j < loads.cols(); ++j)
    for (Eigen::Index i = 0; i < loads.rows(); ++i)
      loads(i, j) = uniform(generator); // [N]
  return loads;
}

StaticRow static_response(const Component& c, const ReducedBasis& basis,
                          const Eigen::Ref<const Eigen::MatrixXd>& boundary_loads) {
  const int n = c.n();
  const int nb = c.n_boundary();
  const Eigen::MatrixXd& t = basis.transformation;
  const Eigen::MatrixXd f = place_rows(n, c.partition().boundary, boundary_loads);
  const Eigen::MatrixXd u = c.solve(f);
  const Eigen::LLT<Eigen::MatrixXd> k_hat(basis.stiffness);
  if (k_hat.info() != Eigen::Success)
    throw std::runtime_error("reduction rows: K^ of " + basis.method + " is not positive definite");
  const Eigen::MatrixXd u_red = t * k_hat.solve(t.transpose() * f);
  StaticRow row;
  const double bound = 2.0 * n * eps * c.cond_k() + nb * eps * basis.cond_rb;
  for (Eigen::Index l = 0; l < f.cols(); ++l) {
    const double err = (u_red.col(l) - u.col(l)).norm() / u.col(l).norm();
    row.response.error = std::max(row.response.error, err);
  }
  row.response.ratio = row.response.error / bound;

  // S = K^_bb - K^_bo K^_oo^-1 K^_ob (o: the modal coordinates).
  const std::vector<int>& b = basis.boundary_position;
  const std::vector<int> o = modal_positions(basis);
  Eigen::MatrixXd s = dense_block(basis.stiffness, b, b);
  if (!o.empty()) {
    const Eigen::LLT<Eigen::MatrixXd> k_oo(dense_block(basis.stiffness, o, o));
    if (k_oo.info() != Eigen::Success)
      throw std::runtime_error("reduction rows: K^_oo of " + basis.method +
                               " is not positive definite");
    const Eigen::MatrixXd k_ob = dense_block(basis.stiffness, o, b);
    s -= k_ob.transpose() * k_oo.solve(k_ob);
  }
  const Eigen::MatrixXd& g = c.boundary_flexibility();
  const std::pair<double, double> eg = extreme_eigenvalues(g);
  const std::pair<double, double> es = extreme_eigenvalues(s);
  row.cond_g = eg.second / eg.first;
  row.boundary_stiffness.error = norm2(s * g - Eigen::MatrixXd::Identity(nb, nb));
  row.boundary_stiffness.ratio =
      row.boundary_stiffness.error / (row.cond_g * (bound + nb * eps * es.second / es.first));
  return row;
}

// ------------------------------------------- V4: CB(0) = CCM(0) = Guyan

std::vector<ZeroModeRow> zero_mode_limits(const Component& c, const ReducedBasis& guyan,
                                          const ReducedBasis& cb0, const ReducedBasis& ccm0) {
  const int n = c.n();
  const int nb = c.n_boundary();
  const Partition& p = c.partition();
  Cholmod k_ii;
  factorize(k_ii, sparse_block(c.k(), p.interior, p.interior), "K_II");
  const double lambda_min_ii = lowest_eigenvalue(k_ii, p.n_interior());
  const double psi_norm = norm2(take_rows(guyan.transformation, p.interior));
  const double t_norm = norm2(guyan.transformation);
  const double k_hat = norm2(guyan.stiffness);
  const double m_hat = norm2(guyan.mass);
  const double dpsi = n * eps * c.k_norm() / lambda_min_ii * (1.0 + psi_norm);
  std::vector<ZeroModeRow> rows;
  for (const ReducedBasis* other : {&cb0, &ccm0}) {
    ZeroModeRow row;
    row.method = other->method;
    const double dt = 2.0 * dpsi + nb * eps * other->cond_rb * (1.0 + psi_norm);
    const double k_bound = 2.0 * n * eps * c.k_norm() * t_norm * t_norm +
                           2.0 * dt * n * eps * c.k_norm() * (1.0 + psi_norm) +
                           c.k_norm() * dt * dt;
    const double m_bound = 2.0 * n * eps * c.m_norm() * t_norm * t_norm +
                           2.0 * c.m_norm() * t_norm * dt + c.m_norm() * dt * dt;
    row.t_ulps = max_ulps(other->transformation, guyan.transformation);
    row.transformation.error = norm2(other->transformation - guyan.transformation);
    row.transformation.ratio = row.transformation.error / dt;
    row.stiffness.error = norm2(other->stiffness - guyan.stiffness) / k_hat;
    row.stiffness.ratio = row.stiffness.error * k_hat / k_bound;
    row.mass.error = norm2(other->mass - guyan.mass) / m_hat;
    row.mass.ratio = row.mass.error * m_hat / m_bound;
    rows.push_back(row);
  }
  return rows;
}

// ------------------------------------------------- V4: Rayleigh-Ritz

std::vector<RitzRow> rayleigh_ritz(const Component& c,
                                   const std::vector<const ReducedBasis*>& nested,
                                   const Modes& full, bool full_by_lanczos, int lowest) {
  const Eigen::VectorXd full_bound = eigenvalue_bounds(c, full, full_by_lanczos);
  const double lambda_max = c.lambda_max();
  std::vector<RitzRow> rows;
  Eigen::VectorXd previous, previous_bound;
  for (const ReducedBasis* b : nested) {
    const ReducedEigen red = reduced_eigen(c, *b);
    const int r = b->n_reduced();
    const int compared = std::min(r, full.n_modes());
    const int lows = std::min(lowest, compared);
    RitzRow row;
    row.method = b->method;
    row.n_modes = b->n_modes;
    row.n_reduced = r;
    row.below = {lowest_double, lowest_double};
    for (int i = 0; i < compared; ++i) {
      const double w2 = full.omega_squared(i);
      const double shortfall = w2 - red.values(i);
      row.below.error = std::max(row.below.error, shortfall / w2);
      row.below.ratio = std::max(row.below.ratio, shortfall / (red.bound(i) + full_bound(i)));
      if (i < lows) row.lowest_error = std::max(row.lowest_error, std::abs(shortfall) / w2);
    }
    // A singular M (Rotor 37's: massless directions) makes lambda_max(full)
    // infinite: every finite reduced eigenvalue lies below it, the row holds
    // trivially (ratio 0, error -1: "below by all of it").
    const double excess = red.values(r - 1) - lambda_max;
    row.top =
        std::isfinite(lambda_max)
            ? Measure{excess / lambda_max, excess / (red.bound(r - 1) + lanczos_tol * lambda_max)}
            : Measure{-1.0, 0.0};
    if (previous.size() > 0) {
      row.rise = {lowest_double, lowest_double};
      for (int i = 0; i < std::min<int>(lows, static_cast<int>(previous.size())); ++i) {
        const double d = red.values(i) - previous(i);
        row.rise.error = std::max(row.rise.error, d / previous(i));
        row.rise.ratio = std::max(row.rise.ratio, d / (red.bound(i) + previous_bound(i)));
      }
    }
    row.omega_max = std::sqrt(std::max(red.values(r - 1), 0.0));
    rows.push_back(row);
    previous = red.values.head(lows);
    previous_bound = red.bound.head(lows);
  }
  return rows;
}

// ------------------------------------------ V4: a complete basis = full

CompleteRow complete_basis_row(const Component& c, const ReducedBasis& basis,
                               const Modes& full_dense, int lowest) {
  const int r = basis.n_reduced();
  if (r != c.n() || full_dense.n_modes() != c.n())
    throw std::invalid_argument("complete_basis_row: needs r = n = " + std::to_string(c.n()) +
                                " and every full mode, got r = " + std::to_string(r) + " and " +
                                std::to_string(full_dense.n_modes()) + " modes");
  const auto start = std::chrono::steady_clock::now();
  const ReducedEigen red = reduced_eigen_lapack(c, basis);
  const Eigen::VectorXd full_bound = eigenvalue_bounds(c, full_dense, false);
  CompleteRow row;
  row.n_reduced = r;
  for (int i = 0; i < r; ++i) {
    const double w2 = full_dense.omega_squared(i);
    const double err = std::abs(red.values(i) - w2);
    row.eigenvalues.error = std::max(row.eigenvalues.error, err / w2);
    row.eigenvalues.ratio = std::max(row.eigenvalues.ratio, err / (red.bound(i) + full_bound(i)));
    if (i < lowest) {
      row.lowest_error = std::max(row.lowest_error, err / w2);
      row.lowest_bound = std::max(row.lowest_bound, (red.bound(i) + full_bound(i)) / w2);
    }
  }
  row.omega_max = std::sqrt(std::max(red.values(r - 1), 0.0));
  row.omega_max_full = std::sqrt(std::max(full_dense.omega_squared(r - 1), 0.0));
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return row;
}

// ------------------------------------------------------------- MacNeal

MacNealRow macneal_row(const Component& c, const ReducedBasis& macneal, const ReducedBasis& ccm,
                       const ReducedBasis& cb, const Modes& full, bool full_by_lanczos) {
  const int n = c.n();
  const int nb = c.n_boundary();
  const int psi = macneal.n_modes;
  if (full.n_modes() < psi)
    throw std::invalid_argument("macneal_row: needs the lowest psi = " + std::to_string(psi) +
                                " full modes, got " + std::to_string(full.n_modes()));
  const Eigen::MatrixXd& t = macneal.transformation;
  const std::vector<int>& b = macneal.boundary_position;
  const std::vector<int> o = modal_positions(macneal);
  MacNealRow row;

  for (int i : b)
    row.boundary_mass = std::max({row.boundary_mass, macneal.mass.row(i).cwiseAbs().maxCoeff(),
                                  macneal.mass.col(i).cwiseAbs().maxCoeff()});
  row.modal_mass = (dense_block(macneal.mass, o, o) -
                    Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(o.size()),
                                              static_cast<Eigen::Index>(o.size())))
                       .cwiseAbs()
                       .maxCoeff();
  row.t_vs_ccm = (t - ccm.transformation).cwiseAbs().maxCoeff();

  // K^ = T^T K T, entry by entry (a different summation order from GEMM's).
  const Eigen::MatrixXd k_t = c.k() * t;
  const Eigen::MatrixXd t_abs = t.cwiseAbs();
  const Eigen::MatrixXd k_bound = 2.0 * n * eps * t_abs.transpose() * (c.k_abs() * t_abs);
  for (Eigen::Index j = 0; j < t.cols(); ++j)
    for (Eigen::Index i = 0; i < t.cols(); ++i) {
      const double err = std::abs(macneal.stiffness(i, j) - t.col(i).dot(k_t.col(j)));
      row.stiffness.error = std::max(row.stiffness.error, err);
      row.stiffness.ratio = std::max(row.stiffness.ratio, err / k_bound(i, j));
    }

  // The condensed problem again, here with eigenvectors for the bounds:
  // x_b = -K^_bb^-1 K^_bo x_o, z = (x_b, x_o) in q.
  const Eigen::MatrixXd k_bb = dense_block(macneal.stiffness, b, b);
  const Eigen::LLT<Eigen::MatrixXd> k_bb_llt(k_bb);
  if (k_bb_llt.info() != Eigen::Success)
    throw std::runtime_error("macneal_row: K^_bb not positive definite");
  const Eigen::MatrixXd y = k_bb_llt.solve(dense_block(macneal.stiffness, b, o));
  Eigen::MatrixXd k_c =
      dense_block(macneal.stiffness, o, o) - dense_block(macneal.stiffness, o, b) * y;
  k_c = 0.5 * (k_c + k_c.transpose());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> condensed(
      k_c, dense_block(macneal.mass, o, o));
  if (condensed.info() != Eigen::Success)
    throw std::runtime_error("macneal_row: condensed eigenproblem failed");
  const Eigen::MatrixXd x_o = condensed.eigenvectors();
  const Eigen::MatrixXd x_b = -y * x_o;
  const Eigen::MatrixXd z =
      place_rows(macneal.n_reduced(), o, x_o) + place_rows(macneal.n_reduced(), b, x_b);
  const Eigen::MatrixXd shapes = t_abs * z.cwiseAbs();
  const Eigen::MatrixXd k_shapes = c.k_abs() * shapes;
  const std::pair<double, double> ebb = extreme_eigenvalues(k_bb);
  const double cond_bb = ebb.second / ebb.first;
  const Eigen::MatrixXd kbb_xb = k_bb.cwiseAbs() * x_b.cwiseAbs();
  const double kc_norm = norm_inf(k_c);
  const Eigen::VectorXd full_bound = eigenvalue_bounds(c, full, full_by_lanczos);
  const bool free_lanczos = few_modes(psi, n) == ModalSolver::sparse;

  const Eigen::VectorXd finite = reduced_eigenvalues(macneal); // what the suite uses
  if (finite.size() != psi)
    throw std::runtime_error("macneal_row: " + std::to_string(finite.size()) +
                             " finite eigenvalues, expected psi = " + std::to_string(psi));
  Eigen::VectorXd bound(psi);
  for (int i = 0; i < psi; ++i) {
    const double w2 = full.omega_squared(i);
    bound(i) = n * eps * shapes.col(i).dot(k_shapes.col(i)) +
               nb * eps * cond_bb * x_b.col(i).cwiseAbs().dot(kbb_xb.col(i)) + psi * eps * kc_norm +
               (free_lanczos ? lanczos_tol * w2 : 0.0) + 2.0 * full_bound(i);
    const double err = std::abs(finite(i) - w2);
    row.eigenvalues.error = std::max(row.eigenvalues.error, err / w2);
    row.eigenvalues.ratio = std::max(row.eigenvalues.ratio, err / bound(i));
  }

  row.omega_max = reduced_omega_max(macneal);
  row.omega_psi = std::sqrt(full.omega_squared(psi - 1));
  row.omega_max_ccm = reduced_omega_max(ccm);
  row.omega_max_cb = reduced_omega_max(cb);
  const ReducedEigen ccm_eigen = reduced_eigen(c, ccm);
  const double top_ccm = ccm_eigen.values(ccm.n_reduced() - 1);
  const double d = row.omega_max * row.omega_max - top_ccm;
  row.below_ccm = {d / top_ccm, d / (bound(psi - 1) + ccm_eigen.bound(ccm.n_reduced() - 1))};
  return row;
}

} // namespace rsi::rows

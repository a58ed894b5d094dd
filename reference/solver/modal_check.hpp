#pragma once
// What a modal solver returns is checked before anyone uses it, on every
// path (dense and sparse, rsi modes and the reductions' own modal solves),
// and each eigenvalue carries the uncertainty the input and the solver
// leave on it.
//
// Given K and M (symmetric, full storage; M positive semi-definite), a
// shift sigma with K - sigma M positive definite (0 for a supported part,
// below 0 for a free one) and the returned pairs (lambda_i, phi_i),
// phi_i M-normalised, i = 1..m:
//
// 1. Residuals. r_i = |K phi - lambda M phi| / (|K phi| + |lambda| |M phi|)
//    (2-norms) must not exceed
//        tau_r + gamma_n kappa_i,
//    kappa_i = (|K|_1 + |lambda_i| |M|_1) |phi_i| / (|K phi_i| + |lambda_i| |M phi_i|),
//    gamma_n = n eps. The second term is the conditioning of the residual
//    itself: a pair exact for K + dK, M + dM with |dK| <= n eps |K|_1,
//    |dM| <= n eps |M|_1 (normwise backward stable to the dense solver's
//    bound p(n) eps, p(n) = n: LAPACK Users' Guide, 3rd ed., §4.7, §4.10)
//    passes; so does a null vector of a free part's K, whose |K phi| is
//    rounding. tau_r = 1e-8 sits ten times above the iterative solvers' own
//    stopping tests (block method 1e-9 on this residual, Lanczos 1e-12 on
//    its Ritz estimates) and, for a well separated eigenvalue, already
//    confines the solver's part of its error to about r^2 relative (below).
//    A pair above it still passes if its solver bound b_i (first order,
//    below) is within the input's rounding a_i: it is as good as the data
//    (a rigid-body mode from shift-invert: its K phi is what is left of the
//    other modes in it, its residual of order one, its eigenvalue 0 to
//    far below a_i).
// 2. M-orthonormality: max_ij |(Phi^T M Phi - I)_ij| <= tau_o + gamma_n |M|_1
//    max_i |phi_i|^2, tau_o = 1e-8: the vectors of a backward stable solver
//    pass; a mode returned twice (a Lanczos ghost) or a vector that is no
//    eigenvector does not.
// 3. Sturm count (symmetric_inertia): with lambda_top the highest returned
//    eigenvalue and w = max(2 u_top, 1e-12 (|lambda_top| + |sigma|)) (u
//    below), the number N+ of negative pivots of an L D L^T of
//    K - (lambda_top + w) M is the number of eigenvalues below
//    lambda_top + w. N+ < m: the solver returned more modes there than
//    exist (a mode twice). N+ = m: nothing was missed. N+ > m: either a
//    mode below lambda_top was missed, or the next eigenvalue lies within w
//    of lambda_top (a multiple eigenvalue that the count cuts): then
//    K - (lambda_top - w) M must have exactly as many negative pivots as
//    modes returned below lambda_top - w.
// Dense inertia (LAPACKE_dsytrf) up to dense_check_limit dofs, above it
// UMFPACK's LU with diagonal pivots, or CHOLMOD's simplicial L D L^T when
// UMFPACK pivoted off the diagonal (linalg/symmetric_inertia.hpp).
//
// Uncertainty of each eigenvalue (absolute, u_i = a_i + b_i):
//  - a_i, the rounding of the input: entries of K and M rounded to eps_in
//    relative (stored_digits: the digits the matrices carry; CalculiX's
//    .sti/.mas have 14, eps_in = 5e-14; a double 2^-53) move a simple
//    eigenvalue by phi^T dK phi - lambda phi^T dM phi (first order,
//    M-normalised phi), at most
//        a_i = (eps_in + gamma_p) (|phi|^T |K| |phi| + |lambda| |phi|^T |M| |phi|),
//    gamma_p = p eps / (1 - p eps) with p the most entries in a row: the
//    rounding of the products K phi and M phi themselves (Higham, Accuracy
//    and Stability of Numerical Algorithms, 2nd ed., eq. 3.5);
//  - b_i, the solver's: with A = K - sigma M (positive definite) the pencil
//    (M, A) has the eigenvalues mu = 1 / (lambda - sigma) of the symmetric
//    C = A^-1/2 M A^-1/2, and y = A^1/2 phi has the residual
//    C y - mu y = -mu A^-1/2 (K phi - lambda M phi); so some eigenvalue of C
//    lies within delta_i = mu_i e_i of mu_i, e_i = sqrt(res^T A^-1 res /
//    (lambda_i - sigma)), and within delta_i^2 / g_i when the other
//    eigenvalues are at least g_i > delta_i away (the residual and gap
//    bounds of a Hermitian eigenpair: Bai, Demmel, Dongarra, Ruhe, van der
//    Vorst, Templates for the Solution of Algebraic Eigenvalue Problems,
//    SIAM 2000, §4.8); g_i from the other returned modes and, above them,
//    from the Sturm count (no unreturned eigenvalue below lambda_top + w).
//    Mapped back, b_i = (lambda_i - sigma) d_i / (1 - d_i), d_i the bound
//    on |mu - mu_j| / mu_i (d_i >= 1: no bound, the pair fails).
// A mode with |lambda_i| <= u_i is zero to the precision of the input: a
// rigid-body motion of a free part (or a mode too stiff for double
// precision to tell from one); a frequency is claimed to within
// u_i / (2 lambda_i) relative (f is proportional to sqrt(lambda)).
// A negative eigenvalue beyond its uncertainty, -lambda_i > u_i, fails the
// check (K not positive semi-definite).
//
// Failure is the `failure` text (which check, the measured value, its
// bound), thrown by require_passed() as ModalCheckError (a ModalError:
// exit status 3 in the CLI).

#include <optional>
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "modal_analysis.hpp"

namespace rsi {

/// The returned modes failed their check (numerical failure).
class ModalCheckError : public ModalError {
public:
  using ModalError::ModalError;
};

/// Above this size the Sturm count and the solver bound use CHOLMOD, below
/// it dense LAPACK (the dense solver's own limit).
constexpr int dense_check_limit = dense_limit;

struct ModalCheckTolerances {
  double residual = 1e-8;        ///< tau_r
  double orthonormality = 1e-8;  ///< tau_o
};

/// Checks `modes` (omega_squared ascending, shapes M-normalised) of (K, M);
/// fills modes.accuracy and returns whether it passed. `sigma`: the shift
/// the solver used, K - sigma M positive definite to working precision as
/// the solver established; none (a solver without a shift, the dense one on
/// (K, M)): 0 if K is positive definite to working precision
/// (check_positive_definite: its CHOLMOD factor and the energy of its lowest
/// mode), shift_below_spectrum otherwise. Throws std::invalid_argument for
/// sizes that do not match.
bool check_modes(const Eigen::SparseMatrix<double>& stiffness,
                 const Eigen::SparseMatrix<double>& mass, std::optional<double> sigma, Modes& modes,
                 const ModalCheckTolerances& tolerances = {});

/// Throws ModalCheckError naming `what` (the solver) and the failed check
/// unless modes.check passed.
void require_passed(const Modes& modes, const std::string& what);

} // namespace rsi

#pragma once
// Participation of component modes in the boundary (the contact dofs), the
// measures of the `participation` mode selection (mode_selection.hpp).
//
// What a measure should rank. The reduced model meets the rest of the
// system (contact, the casing) only through its boundary: what matters is
// its boundary operator, the dynamic stiffness or the receptance at the
// boundary dofs as a function of omega. Expanded in omega^2, some of its
// coefficients are exact for ANY choice of kept modes; the first one that
// is not is the one a selection decides, and a mode's share of that
// coefficient is its participation.
//
// Craig-Bampton (fixed-interface modes phi_i, M_II-normalised; constraint
// modes Psi). In q = (u_eta, q_B) the kept mode i couples to the boundary
// only through the mass, M^(i, B) = L_i = phi_i^T (M_II Psi + M_IB) (a row
// of n_B; K^(i, B) = 0). Eliminating u_eta for a harmonic boundary motion:
//   S(omega) = K^_BB - omega^2 M^_BB - sum_kept omega^4 L_i^T L_i / (omega_i^2 - omega^2)
//            = K^_BB - omega^2 M^_BB - omega^4 sum_kept L_i^T L_i / omega_i^2 + O(omega^6).
// K^_BB and M^_BB (the constraint modes' Guyan matrices) do not depend on
// the kept modes; the omega^4 coefficient does, and the full model's holds
// every mode. L_i^T L_i is Kammer and Triller's effective interface mass
// (ASME J. Vib. Acoust. 118, 1996, 264-270: the mass mode i carries with
// the boundary below omega_i and lets go above it); its share of the
// omega^4 coefficient is L_i^T L_i / omega_i^2. The measure is its trace,
//   p_i = ||L_i||^2 / omega_i^2   [kg s^2].
// Ranking by ||L_i||^2 alone (Kammer and Triller's own criterion, meant for
// a frequency band fixed beforehand) reaches past the band: on the paper's
// disk it keeps 13 kHz modes in a CB-88 basis.
//
// Craig-Chang-Martinez (free-interface modes phi_i, M-normalised). The
// boundary receptance is H(omega) = sum_i phi_iB phi_iB^T / (omega_i^2 -
// omega^2) = sum_k omega^2k sum_i phi_iB phi_iB^T / omega_i^(2k+2). The
// Rayleigh-Ritz model on any basis V containing the attachment modes
// K^-1 E_B reproduces the moments k = 0 and k = 1 exactly: with
// x = K^-1 E_B = V c, E_B^T V (V^T K V)^-1 V^T E_B = E_B^T x and the
// omega^2 term is c^T V^T M V c = x^T M x = E_B^T K^-1 M K^-1 E_B (moment
// matching of Krylov projections: Bai, Appl. Numer. Math. 43, 2002, 9-44;
// this is why residual flexibility plus the attachment modes' mass, paper
// eqs. 14-20, is exact to first order in omega^2 whatever the kept modes).
// The first moment a selection decides is k = 2: a kept mode carries its
// term phi_iB phi_iB^T / omega_i^6 exactly, a dropped one only through the
// n_B attachment vectors. The measure is the trace of that term,
//   p_i = ||phi_iB||^2 / omega_i^6   [m/N s^4].
// (The static share ||phi_iB||^2 / omega_i^2 ranks modes for a moment that
// is exact anyway.)
//
// Both boundary dof kinds of the bladed disk are translations (tip u and
// v), so the traces add like units. A pair's sum does not depend on the
// rotation the eigensolver chose; mode_selection ranks a pair by its mean.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "partition.hpp"

namespace rsi {

/// ||L_i||^2 [kg], L_i = phi_i^T (M_II Psi + M_IB), for each column phi_i of
/// `fixed_shapes` (n_I x P, M_II-normalised fixed-interface modes);
/// `constraint` = Psi (n_I x n_B).
Eigen::VectorXd effective_interface_mass(const Eigen::SparseMatrix<double>& mass,
                                         const Partition& p,
                                         const Eigen::Ref<const Eigen::MatrixXd>& constraint,
                                         const Eigen::Ref<const Eigen::MatrixXd>& fixed_shapes);

/// Craig-Bampton's measure ||L_i||^2 / omega_i^2 (omega_squared of the
/// fixed-interface modes, > 0).
Eigen::VectorXd craig_bampton_participation(const Eigen::SparseMatrix<double>& mass,
                                            const Partition& p,
                                            const Eigen::Ref<const Eigen::MatrixXd>& constraint,
                                            const Eigen::Ref<const Eigen::MatrixXd>& fixed_shapes,
                                            const Eigen::Ref<const Eigen::VectorXd>& omega_squared);

/// Craig-Chang-Martinez's measure ||phi_iB||^2 / omega_i^6 for each column
/// of `free_shapes` (n x P, M-normalised free-interface modes, omega_i^2 > 0).
Eigen::VectorXd
craig_chang_martinez_participation(const Partition& p,
                                   const Eigen::Ref<const Eigen::MatrixXd>& free_shapes,
                                   const Eigen::Ref<const Eigen::VectorXd>& omega_squared);

} // namespace rsi

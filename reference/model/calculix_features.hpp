#pragma once
// Which element types and keywords of a CalculiX deck rsi takes as a
// linear structural component: K and M of ccx's `*FREQUENCY,
// SOLVER=MATRIXSTORAGE` step, in which ccx leaves out what is not linear
// elasticity and inertia. Taken: every structural element ccx has (solids
// C3D4 ... C3D20R, C3D8I; plane stress, plane strain and axisymmetric
// CPS*, CPE*, CAX*; shells S3 ... S8R; beams B31, B32(R); trusses T3D*;
// springs SPRINGA, SPRING1/2; MASS), *EQUATION, *MPC, *TIE, *RIGID BODY,
// *COUPLING, *TRANSFORM (ccx writes the matrices in global directions),
// *BOUNDARY, materials (their elastic constants and density; plasticity,
// creep and expansion do not enter a linear frequency step), sections.
// Refused, naming the element type or keyword, where it is, and what to
// use instead, because ccx's linear matrices cannot hold it and would
// silently drop it:
//   - heat-transfer (DC3D*, DC2D*, DCAX*), network (D) and fluid (F3D*)
//     elements: not structural;
//   - *CONTACT PAIR and gap elements (GAPUNI, GAPUNIELL): contact is not
//     linear; ccx leaves it open (no stiffness across the surfaces);
//   - dashpots (DASHPOTA, *DASHPOT) and material *DAMPING: not part of K
//     or M; the case's damping holds the component's damping;
//   - *CYCLIC SYMMETRY MODEL: a sector's matrices are not the component.
// Throws ImportError (exit 2) naming the first one: keywords, then
// element types, each in deck order.

#include "calculix_deck.hpp"

namespace rsi {

void check_calculix_features(const CalculixDeck& deck);

} // namespace rsi

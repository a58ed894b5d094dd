#pragma once
// The abradable liner on a rigid casing (SPEC §9): a layer of thickness h
// behind the surface the blade tips meet, cut into cells, each cell a
// massless 1D elasto-plastic bar with linear isotropic hardening whose
// plastic shortening is the wear (the bar model of Legrand, Batailly,
// Pierre, "Numerical investigation of abradable coating removal in aircraft
// engines through plastic constitutive law", J. Comput. Nonlinear Dyn. 7
// (2012) 011010).
//
// Geometry. The unworn liner surface is the rigid casing surface of today's
// rubbing laws (a cylinder of radius r about the rotation axis: the
// imposed gap g0 is measured to it); the bars run radially outward from it
// to the rigid backing at r + h. Cells:
//   around   n_theta equal sectors of dtheta = 2 pi / n_theta; sector i
//            holds the angles [i dtheta, (i + 1) dtheta) of the casing
//            frame (the angle measured on the casing, which the caller
//            forms from the tip's polar angle and the rotation), any
//            finite angle taken modulo 2 pi;
//   along    n_axial rows of dz = (z_max - z_min) / n_axial over the axial
//            coordinate; row j holds [z_min + j dz, z_min + (j + 1) dz),
//            the last row also z_max; an axial coordinate outside
//            [z_min, z_max] is refused (std::invalid_argument): a tip
//            node that is not over the liner is a set-up error, and
//            clamping it would put its wear into a row it never touched;
//   index    cell = j n_theta + i.
// Each bar: length h, area A = r dtheta dz (the cell's face on the unworn
// surface; h << r so the face at r + h differs by h / r), Young's modulus
// E, yield stress sigma_y, hardening modulus H:
//   k = E A / h (elastic stiffness), k_H = H A / h, k_t = k E_t / E with
//   E_t = E H / (E + H) (the tangent on yield; 0 for H = 0).
//
// State per cell: the wear p >= 0 (plastic shortening [length], never
// decreasing) and the hardening variable alpha >= 0 (accumulated plastic
// strain [-]); the yield stress is sigma_Y = sigma_y + H alpha. The worn
// surface is the unworn one moved outward by p: a gap g0 to the unworn
// surface is g0 + p to the worn one.
//
// The bar law. delta: the tip's indentation past the cell's current
// (worn, unloaded) surface, compression > 0. The bar cannot pull (the tip
// only pushes it), so for delta <= 0 the force is 0 and nothing changes.
// Otherwise the elastic strain is delta / h and one return mapping (exact
// for linear hardening; Simo and Hughes, Computational Inelasticity, 1998,
// chapter 1) gives
//   sigma_tr = E delta / h,  f = sigma_tr - (sigma_y + H alpha)
//   f <= 0:  sigma = sigma_tr                          (elastic)
//   f  > 0:  dgamma = f / (E + H),  sigma = sigma_tr - E dgamma,
//            alpha += dgamma,  p += h dgamma           (plastic)
//   F = A sigma >= 0
// and the plastic work of the step, W_p = integral of F dp along the yield
// line F = A (sigma_y + H alpha), exactly
//   W_p = A h dgamma (sigma_y + H (alpha_n + dgamma / 2)).
// As a function of delta the force is piecewise linear, continuous and
// nondecreasing: 0, then k delta up to delta_Y = sigma_Y h / E, then
// F_Y + k_t (delta - delta_Y) with F_Y = A sigma_Y.
//
// The compliant solve. A node whose predicted indentation is delta_pred and
// whose own force moves it back by c F (c = dt^2 (M^-1)_nn >= 0, its normal
// Delassus compliance) needs F = bar_force(delta_pred - c F). The right
// side is nonincreasing in F and the left increasing, so the root is unique,
// and on each branch it is closed form:
//   delta_pred <= 0                          F = 0
//   0 < delta_pred <= delta_Y (1 + c k)      F = k delta_pred / (1 + c k)
//   delta_pred > delta_Y (1 + c k)           F = (F_Y + k_t (delta_pred - delta_Y)) / (1 + c k_t)
// after which the bar law at delta = delta_pred - c F gives the state and
// W_p; the force returned is the root F itself (the bar's force at
// delta_pred - c F would carry eps c k of F from forming that difference).
// With c = 0 it is the bar law itself, bit for bit.
//
// Assumptions: massless bars (the liner adds no mass or inertia), radial
// only (the bar carries the normal force; no friction in the bar: the
// tangential force is the contact law's, mu F), small displacements,
// compression only.
//
// Units: those of the model (Rotor 37: mm, N, MPa = N/mm^2, s). Ranges:
// r, h, E, sigma_y finite and > 0 with h < r; H finite and >= 0;
// z_min < z_max finite; n_theta, n_axial >= 1. Bad parameters throw
// std::invalid_argument naming the parameter and its range. Owns the cells'
// states.

#include <vector>

namespace rsi {

struct LinerGeometry {
  double radius = 0.0;    ///< r of the unworn surface [length], > 0
  double thickness = 0.0; ///< h [length], 0 < h < r
  int n_theta = 1;        ///< cells around, >= 1
  int n_axial = 1;        ///< rows along the axis, >= 1
  double z_min = 0.0;     ///< axial extent [length], z_min < z_max
  double z_max = 0.0;
};

struct LinerMaterial {
  double young = 0.0;     ///< E [stress], > 0
  double yield = 0.0;     ///< sigma_y [stress], > 0
  double hardening = 0.0; ///< H [stress], >= 0
};

/// One cell's bar: the wear p (plastic shortening) and the hardening
/// variable alpha (accumulated plastic strain).
struct LinerCellState {
  double wear = 0.0;      ///< p >= 0 [length]
  double hardening = 0.0; ///< alpha >= 0 [-]
};

/// What one application of the bar law gives.
struct LinerBarResponse {
  double force = 0.0;        ///< F >= 0 [force], compression
  double indentation = 0.0;  ///< delta the law was applied at [length]
  LinerCellState state;      ///< the state after it
  double plastic_work = 0.0; ///< W_p of this application, >= 0 [force * length]
  bool plastic = false;      ///< the bar yielded (dgamma > 0)
};

class AbradableLiner {
public:
  /// Throws std::invalid_argument naming the bad parameter and its range.
  AbradableLiner(const LinerGeometry& geometry, const LinerMaterial& material);

  int n_theta() const { return m_geometry.n_theta; }
  int n_axial() const { return m_geometry.n_axial; }
  int n_cells() const { return m_geometry.n_theta * m_geometry.n_axial; }
  const LinerGeometry& geometry() const { return m_geometry; }
  const LinerMaterial& material() const { return m_material; }

  /// Sector of a finite angle [rad] of the casing frame (any turn):
  /// floor((theta mod 2 pi) / dtheta); an angle that rounds to 2 pi after
  /// the modulo (a tiny negative one) is in the last sector.
  int angular_cell(double theta) const;
  /// Row of an axial coordinate in [z_min, z_max]; throws
  /// std::invalid_argument otherwise (or for a non-finite z).
  int axial_row(double z) const;
  /// j n_theta + i for the point (theta, z).
  int cell(double theta, double z) const;

  double pitch() const { return m_pitch; }               ///< dtheta = 2 pi / n_theta
  double row_width() const { return m_row_width; }       ///< dz = (z_max - z_min) / n_axial
  double cell_area() const { return m_area; }            ///< A = r dtheta dz
  double stiffness() const { return m_stiffness; }       ///< k = E A / h
  double tangent_stiffness() const { return m_tangent; } ///< k_t = k H / (E + H)
  /// F_Y = A (sigma_y + H alpha), the force at which the bar yields.
  double yield_force(const LinerCellState& state) const;

  /// The bar law at indentation delta from `state` (header). delta finite;
  /// state finite with p, alpha >= 0; throws std::invalid_argument otherwise.
  LinerBarResponse bar_force(const LinerCellState& state, double delta) const;
  /// The root of F = bar_force(state, delta_pred - c F).F (header), c >= 0
  /// finite; the response is the bar law's at delta_pred - c F.
  LinerBarResponse compliant_force(const LinerCellState& state, double delta_pred,
                                   double compliance) const;

  /// Stored state of a cell (0 <= cell < n_cells()).
  const LinerCellState& state(int cell) const;
  /// The wear p of a cell: the outward shift of its surface.
  double wear(int cell) const { return state(cell).wear; }
  /// delta = d - p: the indentation past the cell's worn surface of a tip
  /// at depth d past the unworn one (d = -g0 for a gap g0 to it).
  double indentation(int cell, double depth) const { return depth - wear(cell); }
  /// Keeps `response` as the cell's state and adds its plastic work to the
  /// total. Throws std::invalid_argument if the wear or the hardening would
  /// decrease (a response computed from another state).
  void commit(int cell, const LinerBarResponse& response);
  /// Sum of the committed plastic work.
  double plastic_work() const { return m_plastic_work; }

private:
  LinerGeometry m_geometry;
  LinerMaterial m_material;
  double m_pitch;     ///< dtheta
  double m_row_width; ///< dz
  double m_area;
  double m_stiffness;
  double m_tangent;
  std::vector<LinerCellState> m_states;
  double m_plastic_work = 0.0;
};

} // namespace rsi

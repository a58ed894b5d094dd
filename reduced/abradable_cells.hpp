#pragma once
// The abradable liner's cells as the reduced solver sees them (SPEC §9;
// issue 26 item 2), written apart from reference/contact/abradable_liner:
// the same physical model, derived here in force variables.
//
// Cells. The unworn liner surface is the rigid casing's (the imposed gap is
// measured to it). n_theta equal sectors of the casing-frame angle (sector
// i holds [i dtheta, (i + 1) dtheta), any finite angle taken mod 2 pi),
// n_axial equal rows of the axial coordinate over [z_min, z_max] (the last
// row also holds z_max; outside is refused); cell = row n_theta + sector.
// Each cell is a massless radial bar of length h and area
// A = r dtheta dz, with E, sigma_y and the linear hardening modulus H:
//   k = E A / h,  k_H = H A / h  (the force per unit of wear on the yield line).
//
// State: the wear p >= 0 (plastic shortening, never decreasing) and the
// yield force F_Y = A sigma_y + k_H p (linear isotropic hardening: the
// hardening variable is the plastic strain p / h, so A H p / h = k_H p).
// The worn surface lies p outward of the unworn one.
//
// The bar in force variables. delta: the indentation past the worn surface
// (compression > 0). delta <= 0: F = 0 (the bar does not pull). Else the
// trial force k delta; if it exceeds F_Y the bar flows by dp with the force
// back on the (moved) yield line,
//   k (delta - dp) = F_Y + k_H dp   =>   dp = (k delta - F_Y) / (k + k_H),
// and F = k (delta - dp). The plastic work of the flow is the area under
// the yield line from p to p + dp: dp (F_Y + k_H dp / 2).
//
// Compliant form. If the node's own force moves it back by c F (c >= 0, its
// normal Delassus compliance), the force solves F = bar(delta~ - c F); with
// delta = delta~ - c F in the two formulas above, D = k + k_H + c k k_H,
//   elastic:  F = k delta~ / (1 + c k)              while that is <= F_Y,
//   plastic:  F = k (k_H delta~ + F_Y) / D,
//             dp = (k delta~ - F_Y (1 + c k)) / D   (= (k delta - F_Y) / (k + k_H)),
// the root unique because the bar force is nondecreasing in delta. Both are
// formed from delta~, never from delta = delta~ - c F: for a stiff bar
// (c k >> 1) that difference cancels and would leave F wrong by eps c k of
// itself, a noise an iterated solve (liner_contact_solve.hpp) cannot get
// below.
//
// Units: the model's. Bad parameters throw std::invalid_argument naming the
// parameter and its range.

#include <vector>

namespace rsi {

struct AbradableCellsGeometry {
  double radius = 0.0;    ///< r of the unworn surface [length], > h
  double thickness = 0.0; ///< h [length], > 0
  int n_theta = 1;        ///< sectors, >= 1
  int n_axial = 1;        ///< rows, >= 1
  double z_min = 0.0;     ///< axial extent [length], z_min < z_max
  double z_max = 0.0;
};

struct AbradableCellsMaterial {
  double young = 0.0;     ///< E [stress], > 0
  double yield = 0.0;     ///< sigma_y [stress], > 0
  double hardening = 0.0; ///< H [stress], >= 0
};

/// The state of one bar.
struct BarState {
  double wear = 0.0;        ///< p >= 0 [length]
  double yield_force = 0.0; ///< F_Y [force]
};

/// One evaluation of the bar law.
struct BarResponse {
  double force = 0.0;        ///< F >= 0 [force]
  BarState state;            ///< after it
  double plastic_work = 0.0; ///< >= 0 [force * length]
};

class AbradableCells {
public:
  AbradableCells(const AbradableCellsGeometry& geometry, const AbradableCellsMaterial& material);

  int n_theta() const { return m_geometry.n_theta; }
  int n_axial() const { return m_geometry.n_axial; }
  int n_cells() const { return m_geometry.n_theta * m_geometry.n_axial; }
  double area() const { return m_area; }          ///< A
  double stiffness() const { return m_k; }        ///< k
  double hardening_stiffness() const { return m_kh; } ///< k_H
  const AbradableCellsGeometry& geometry() const { return m_geometry; }
  double pitch() const { return m_pitch; }    ///< dtheta = 2 pi / n_theta [rad]
  double row_height() const { return m_row; } ///< dz = (z_max - z_min) / n_axial [length]

  /// Sector of a finite angle [rad].
  int sector(double theta) const;
  /// Row of an axial coordinate in [z_min, z_max]; throws
  /// std::invalid_argument otherwise.
  int row(double z) const;

  /// The bar law at indentation delta from `state` (header). Inline: the
  /// tip patch evaluates it for every bar of a patch at every sweep.
  BarResponse bar(const BarState& state, double delta) const {
    BarResponse r;
    r.state = state;
    if (!(delta > 0.0)) return r;
    const double trial = m_k * delta;
    if (trial <= state.yield_force) {
      r.force = trial;
      return r;
    }
    const double dp = (trial - state.yield_force) / (m_k + m_kh);
    r.force = m_k * (delta - dp);
    r.state.wear = state.wear + dp;
    r.state.yield_force = state.yield_force + m_kh * dp;
    r.plastic_work = dp * (state.yield_force + 0.5 * m_kh * dp);
    return r;
  }
  /// bar(state, delta).force, the same operations (so the same bits)
  /// without the state and plastic work: the tip patch's root search
  /// evaluates it for every bar of the patch at each probe.
  double bar_force(const BarState& state, double delta) const {
    if (!(delta > 0.0)) return 0.0;
    const double trial = m_k * delta;
    if (trial <= state.yield_force) return trial;
    return m_k * (delta - (trial - state.yield_force) / (m_k + m_kh));
  }
  /// The root of F = bar(state, delta~ - c F).force, c >= 0 (header), with
  /// the state and plastic work of the bar at delta~ - c F, in closed form.
  BarResponse compliant(const BarState& state, double delta_pred, double compliance) const;

  const BarState& state(int cell) const { return m_state[static_cast<size_t>(cell)]; }
  /// Keeps `r` as the cell's state, adds its plastic work; throws
  /// std::logic_error if the wear would decrease.
  void commit(int cell, const BarResponse& r);
  double plastic_work() const { return m_plastic_work; }
  /// The wear p of every cell, in cell order.
  std::vector<double> wear() const;

private:
  AbradableCellsGeometry m_geometry;
  double m_pitch = 0.0, m_row = 0.0, m_area = 0.0, m_k = 0.0, m_kh = 0.0;
  std::vector<BarState> m_state;
  double m_plastic_work = 0.0;
};

} // namespace rsi

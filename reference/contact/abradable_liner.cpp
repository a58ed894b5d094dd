#include "abradable_liner.hpp"

#include <climits>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rsi {

namespace {

constexpr double two_pi = 2.0 * M_PI;

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument("abradable liner: " + what);
}

std::string number(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

void require_positive(double value, const char* name) {
  if (!(std::isfinite(value) && value > 0.0))
    refuse(std::string(name) + " = " + number(value) + " must be finite and > 0");
}

} // namespace

AbradableLiner::AbradableLiner(const LinerGeometry& geometry, const LinerMaterial& material)
    : m_geometry(geometry)
    , m_material(material) {
  require_positive(geometry.radius, "radius r");
  require_positive(geometry.thickness, "thickness h");
  if (!(geometry.thickness < geometry.radius))
    refuse("thickness h = " + number(geometry.thickness) +
           " must be < radius r = " + number(geometry.radius));
  if (geometry.n_theta < 1)
    refuse("n_theta = " + std::to_string(geometry.n_theta) + " must be >= 1");
  if (geometry.n_axial < 1)
    refuse("n_axial = " + std::to_string(geometry.n_axial) + " must be >= 1");
  // The cell index j n_theta + i is an int.
  if (static_cast<long long>(geometry.n_theta) * geometry.n_axial > INT_MAX)
    refuse("n_theta * n_axial = " + std::to_string(geometry.n_theta) + " * " +
           std::to_string(geometry.n_axial) + " must be <= " + std::to_string(INT_MAX));
  if (!(std::isfinite(geometry.z_min) && std::isfinite(geometry.z_max) &&
        geometry.z_min < geometry.z_max))
    refuse("axial extent [z_min, z_max] = [" + number(geometry.z_min) + ", " +
           number(geometry.z_max) + "] must be finite with z_min < z_max");
  require_positive(material.young, "Young's modulus E");
  require_positive(material.yield, "yield stress sigma_y");
  if (!(std::isfinite(material.hardening) && material.hardening >= 0.0))
    refuse("hardening modulus H = " + number(material.hardening) + " must be finite and >= 0");

  m_pitch = two_pi / geometry.n_theta;
  m_row_width = (geometry.z_max - geometry.z_min) / geometry.n_axial;
  m_area = geometry.radius * m_pitch * m_row_width;
  m_stiffness = material.young * m_area / geometry.thickness;
  m_tangent = m_stiffness * material.hardening / (material.young + material.hardening);
  // Finite inputs can still over- or underflow here.
  if (!(std::isfinite(m_row_width) && m_row_width > 0.0 && std::isfinite(m_area) && m_area > 0.0 &&
        std::isfinite(m_stiffness) && m_stiffness > 0.0))
    refuse("the cell area r dtheta dz = " + number(m_area) +
           " and stiffness E A / h = " + number(m_stiffness) +
           " must be finite and > 0 (radius, thickness, axial extent, "
           "counts and E out of scale)");
  m_states.assign(static_cast<std::size_t>(n_cells()), LinerCellState{});
}

int AbradableLiner::angular_cell(double theta) const {
  if (!std::isfinite(theta)) refuse("angle theta = " + number(theta) + " must be finite");
  // fmod is exact; a tiny negative angle becomes 2 pi after the shift and
  // belongs to the last sector.
  double a = std::fmod(theta, two_pi);
  if (a < 0.0) a += two_pi;
  const int i = static_cast<int>(std::floor(a / m_pitch));
  return i >= m_geometry.n_theta ? m_geometry.n_theta - 1 : i;
}

int AbradableLiner::axial_row(double z) const {
  if (!(z >= m_geometry.z_min && z <= m_geometry.z_max))
    refuse("axial coordinate z = " + number(z) + " must lie in [z_min, z_max] = [" +
           number(m_geometry.z_min) + ", " + number(m_geometry.z_max) +
           "] (the point is not over the liner)");
  const int j = static_cast<int>(std::floor((z - m_geometry.z_min) / m_row_width));
  return j >= m_geometry.n_axial ? m_geometry.n_axial - 1 : j;
}

int AbradableLiner::cell(double theta, double z) const {
  return axial_row(z) * m_geometry.n_theta + angular_cell(theta);
}

double AbradableLiner::yield_force(const LinerCellState& state) const {
  return m_area * (m_material.yield + m_material.hardening * state.hardening);
}

LinerBarResponse AbradableLiner::bar_force(const LinerCellState& state, double delta) const {
  if (!(std::isfinite(state.wear) && state.wear >= 0.0 && std::isfinite(state.hardening) &&
        state.hardening >= 0.0))
    refuse("cell state (wear " + number(state.wear) + ", hardening " + number(state.hardening) +
           ") must be finite and >= 0");
  if (!std::isfinite(delta)) refuse("indentation delta = " + number(delta) + " must be finite");
  LinerBarResponse out;
  out.indentation = delta;
  out.state = state;
  if (!(delta > 0.0)) return out; // the tip is off the surface: the bar cannot pull
  const double E = m_material.young;
  const double H = m_material.hardening;
  const double h = m_geometry.thickness;
  const double sigma_trial = E * delta / h;
  const double sigma_yield = m_material.yield + H * state.hardening;
  const double f = sigma_trial - sigma_yield;
  if (!(f > 0.0)) {
    out.force = m_area * sigma_trial;
    return out;
  }
  const double dgamma = f / (E + H);
  out.force = m_area * (sigma_trial - E * dgamma);
  out.state.hardening = state.hardening + dgamma;
  out.state.wear = state.wear + h * dgamma;
  // The integral of F dp along the yield line F = A (sigma_Y + H (alpha - alpha_n)).
  out.plastic_work = m_area * h * dgamma * (sigma_yield + 0.5 * H * dgamma);
  out.plastic = true;
  return out;
}

LinerBarResponse AbradableLiner::compliant_force(const LinerCellState& state, double delta_pred,
                                                 double compliance) const {
  if (!(std::isfinite(compliance) && compliance >= 0.0))
    refuse("compliance c = " + number(compliance) + " must be finite and >= 0");
  if (!std::isfinite(delta_pred))
    refuse("predicted indentation = " + number(delta_pred) + " must be finite");
  double force = 0.0;
  if (delta_pred > 0.0) {
    const double k = m_stiffness;
    const double force_yield = yield_force(state);
    const double delta_yield = force_yield / k;
    // The elastic root k delta_pred / (1 + c k) keeps delta <= delta_Y up to
    // delta_pred = delta_Y (1 + c k) = delta_Y + c F_Y.
    if (delta_pred <= delta_yield + compliance * force_yield)
      force = k * delta_pred / (1.0 + compliance * k);
    else
      force =
          (force_yield + m_tangent * (delta_pred - delta_yield)) / (1.0 + compliance * m_tangent);
  }
  LinerBarResponse r = bar_force(state, delta_pred - compliance * force);
  // The force is the root itself: the bar's own at delta_pred - c F carries
  // the rounding of that difference times k, eps c k of F for a stiff bar
  // (c k >> 1: 2e-12 mm of gap against F / k measured on the gmsh blade at
  // E = 1e12 MPa). The state and W_p keep the bar's (their rounding is of a
  // length, eps delta_pred).
  if (compliance > 0.0) r.force = force;
  return r;
}

const LinerCellState& AbradableLiner::state(int cell) const {
  if (cell < 0 || cell >= n_cells())
    refuse("cell " + std::to_string(cell) + " must be in [0, " + std::to_string(n_cells()) + ")");
  return m_states[static_cast<std::size_t>(cell)];
}

void AbradableLiner::commit(int cell, const LinerBarResponse& response) {
  const LinerCellState& now = state(cell);
  const LinerCellState& next = response.state;
  if (!(next.wear >= now.wear && next.hardening >= now.hardening && std::isfinite(next.wear) &&
        std::isfinite(next.hardening) && std::isfinite(response.plastic_work) &&
        response.plastic_work >= 0.0))
    refuse("cell " + std::to_string(cell) + ": the wear (" + number(now.wear) + " -> " +
           number(next.wear) + ") and hardening (" + number(now.hardening) + " -> " +
           number(next.hardening) + ") must not decrease, the plastic work (" +
           number(response.plastic_work) +
           ") must be finite and >= 0: a response computed from another state");
  m_states[static_cast<std::size_t>(cell)] = next;
  m_plastic_work += response.plastic_work;
}

} // namespace rsi

#include "abradable_cells.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "message_number.hpp"

namespace rsi {

namespace {

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument("AbradableCells: " + what);
}

void positive(double x, const char* name) {
  if (!(std::isfinite(x) && x > 0.0)) refuse(std::string(name) + " = " + message_number(x) + ", allowed finite and > 0");
}

} // namespace

AbradableCells::AbradableCells(const AbradableCellsGeometry& geometry,
                               const AbradableCellsMaterial& material)
    : m_geometry(geometry) {
  positive(geometry.radius, "radius");
  positive(geometry.thickness, "thickness");
  if (!(geometry.thickness < geometry.radius))
    refuse("thickness = " + message_number(geometry.thickness) + ", allowed < radius " +
           message_number(geometry.radius));
  if (geometry.n_theta < 1 || geometry.n_axial < 1 ||
      static_cast<double>(geometry.n_theta) * geometry.n_axial > 2147483647.0)
    refuse("cells " + std::to_string(geometry.n_theta) + " x " + std::to_string(geometry.n_axial) +
           ", allowed >= 1 each and an int product");
  if (!(std::isfinite(geometry.z_min) && std::isfinite(geometry.z_max) &&
        geometry.z_min < geometry.z_max))
    refuse("axial extent [" + message_number(geometry.z_min) + ", " +
           message_number(geometry.z_max) + "], allowed finite with z_min < z_max");
  positive(material.young, "Young's modulus");
  positive(material.yield, "yield stress");
  if (!(std::isfinite(material.hardening) && material.hardening >= 0.0))
    refuse("hardening modulus = " + message_number(material.hardening) +
           ", allowed finite and >= 0");
  m_pitch = 2.0 * M_PI / geometry.n_theta;
  m_row = (geometry.z_max - geometry.z_min) / geometry.n_axial;
  m_area = geometry.radius * m_pitch * m_row;
  m_k = material.young * m_area / geometry.thickness;
  m_kh = material.hardening * m_area / geometry.thickness;
  if (!(std::isfinite(m_k) && m_k > 0.0 && std::isfinite(m_kh)))
    refuse("bar stiffness E A / h = " + message_number(m_k) + ", allowed finite and > 0");
  m_state.assign(static_cast<size_t>(n_cells()), BarState{0.0, material.yield * m_area});
}

int AbradableCells::sector(double theta) const {
  if (!std::isfinite(theta)) refuse("angle " + message_number(theta) + ", allowed finite");
  const double turn = 2.0 * M_PI;
  const double a = theta - turn * std::floor(theta / turn);
  const int i = static_cast<int>(a / m_pitch);
  return i < 0 ? 0 : (i >= m_geometry.n_theta ? m_geometry.n_theta - 1 : i);
}

int AbradableCells::row(double z) const {
  if (!(z >= m_geometry.z_min && z <= m_geometry.z_max))
    refuse("axial coordinate " + message_number(z) + " outside the liner's [" +
           message_number(m_geometry.z_min) + ", " + message_number(m_geometry.z_max) + "]");
  const int j = static_cast<int>((z - m_geometry.z_min) / m_row);
  return j >= m_geometry.n_axial ? m_geometry.n_axial - 1 : j;
}

BarResponse AbradableCells::compliant(const BarState& state, double delta_pred,
                                      double compliance) const {
  BarResponse r;
  r.state = state;
  if (!(delta_pred > 0.0)) return r;
  const double elastic = m_k * delta_pred / (1.0 + compliance * m_k);
  if (elastic <= state.yield_force) {
    r.force = elastic;
    return r;
  }
  // The plastic root and its flow, from delta~ directly (header): forming
  // delta = delta~ - c F first would cancel (c F -> delta~ as c k grows) and
  // leave F with a relative error of eps c k.
  const double d = m_k + m_kh + compliance * m_k * m_kh;
  r.force = m_k * (m_kh * delta_pred + state.yield_force) / d;
  const double dp =
      std::max(0.0, (m_k * delta_pred - state.yield_force * (1.0 + compliance * m_k)) / d);
  r.state.wear = state.wear + dp;
  r.state.yield_force = state.yield_force + m_kh * dp;
  r.plastic_work = dp * (state.yield_force + 0.5 * m_kh * dp);
  return r;
}

void AbradableCells::commit(int cell, const BarResponse& r) {
  BarState& s = m_state.at(static_cast<size_t>(cell));
  if (r.state.wear < s.wear)
    throw std::logic_error("AbradableCells: cell " + std::to_string(cell) +
                           ": a response would lower the wear from " + message_number(s.wear) +
                           " to " + message_number(r.state.wear));
  s = r.state;
  m_plastic_work += r.plastic_work;
}

std::vector<double> AbradableCells::wear() const {
  std::vector<double> p(m_state.size());
  for (size_t i = 0; i < p.size(); ++i) p[i] = m_state[i].wear;
  return p;
}

} // namespace rsi

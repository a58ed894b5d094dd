#include "frame_element.hpp"

#include <cmath>

namespace rsi {

Matrix6d frame_stiffness_local(const BeamProperties& p, double length) {
  const double L = length;
  const double a = p.EA / L;
  const double b = p.EI / (L * L * L);
  Matrix6d k;
  // clang-format off
  k <<  a,  0,          0,         -a,  0,          0,
        0,  12*b,       6*L*b,      0, -12*b,       6*L*b,
        0,  6*L*b,      4*L*L*b,    0, -6*L*b,      2*L*L*b,
       -a,  0,          0,          a,  0,          0,
        0, -12*b,      -6*L*b,      0,  12*b,      -6*L*b,
        0,  6*L*b,      2*L*L*b,    0, -6*L*b,      4*L*L*b;
  // clang-format on
  return k;
}

Matrix6d frame_mass_local(const BeamProperties& p, double length) {
  const double L = length;
  const double a = p.rhoA * L / 6.0;
  const double b = p.rhoA * L / 420.0;
  Matrix6d m;
  // clang-format off
  m << 2*a,  0,         0,          a,    0,          0,
       0,    156*b,     22*L*b,     0,    54*b,      -13*L*b,
       0,    22*L*b,    4*L*L*b,    0,    13*L*b,    -3*L*L*b,
       a,    0,         0,          2*a,  0,          0,
       0,    54*b,      13*L*b,     0,    156*b,     -22*L*b,
       0,   -13*L*b,   -3*L*L*b,    0,   -22*L*b,     4*L*L*b;
  // clang-format on
  return m;
}

Matrix6d frame_rotation(double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  Matrix6d r = Matrix6d::Zero();
  for (int node = 0; node < 2; ++node) {
    const int o = 3 * node;
    r(o, o) = c;
    r(o, o + 1) = s;
    r(o + 1, o) = -s;
    r(o + 1, o + 1) = c;
    r(o + 2, o + 2) = 1.0;
  }
  return r;
}

Matrix6d frame_stiffness(const BeamProperties& p, double length, double angle) {
  const Matrix6d r = frame_rotation(angle);
  return r.transpose() * frame_stiffness_local(p, length) * r;
}

Matrix6d frame_mass(const BeamProperties& p, double length, double angle) {
  const Matrix6d r = frame_rotation(angle);
  return r.transpose() * frame_mass_local(p, length) * r;
}

} // namespace rsi

#pragma once
// The small liner the reduced liner's unit tests share: r 250, h 2, 8
// sectors x 4 rows over z in [0, 8] (cell area 392.7 mm2); E 1000,
// sigma_y 10 MPa, H given (k = 1.96e5 N/mm, the fresh yield depth 0.02 mm).

#include "abradable_cells.hpp"

namespace rsi {

inline AbradableCellsGeometry abradable_test_geometry() {
  AbradableCellsGeometry g;
  g.radius = 250.0;
  g.thickness = 2.0;
  g.n_theta = 8;
  g.n_axial = 4;
  g.z_min = 0.0;
  g.z_max = 8.0;
  return g;
}

inline AbradableCellsMaterial abradable_test_material(double hardening = 300.0) {
  AbradableCellsMaterial m;
  m.young = 1000.0;
  m.yield = 10.0;
  m.hardening = hardening;
  return m;
}

} // namespace rsi

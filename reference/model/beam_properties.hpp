#pragma once
// Stiffness and inertia per unit length of a rectangular beam section.

#include "case_file.hpp"

namespace rsi {

/// EA [N], EI [N m^2] (bending in the plane of the model), rho A [kg/m].
struct BeamProperties {
  double EA = 0.0;
  double EI = 0.0;
  double rhoA = 0.0;
};

/// A = width * thickness, I = width * thickness^3 / 12.
inline BeamProperties beam_properties(const Material& material, const Section& section) {
  const double area = section.width * section.thickness;
  const double inertia =
      section.width * section.thickness * section.thickness * section.thickness / 12.0;
  return {material.young_modulus * area, material.young_modulus * inertia, material.density * area};
}

} // namespace rsi
